"""Time integrators on the linear test oscillator x'' + 2 zeta w x' + w^2 x = 0 at a constant step h:
the amplitude ratio and the phase error per period of each method's one-step map (issue 38: which
integrator could pay on the demo, before building it).

Methods:
  radau5   Radau IIA, 3 stages, order 5, L-stable (what `--method radau5` integrates with)
  radau3   Radau IIA, 2 stages, order 3, L-stable
  gauss2   Gauss-Legendre, 2 stages, order 4, A-stable, no damping (R(inf) = 1)
  sdirk3   Alexander's 3-stage SDIRK, order 3, L-stable (the stages solved one after the other)
  bdf1..5  backward differentiation at a constant step (SUNDIALS IDA's orders), principal root for
           the phase, the largest root for the amplitude
  ga<rho>  Lie-group generalized-alpha in Arnold and Bruls' form, as mbd/src/solvers/integrator.cpp
           (coefficients of step_control.hpp), spectral radius of its map on (x, v, xddot, a)
A Runge-Kutta method's one-step map is its stability function R(z) = 1 + z b^T (I - z A)^-1 1 at
z = h lambda, lambda = w (-zeta +- i sqrt(1 - zeta^2)) (Hairer and Wanner II, IV.3).
"""
import numpy as np

_S6 = np.sqrt(6.0)
_S3 = np.sqrt(3.0)
_G = 0.435866521508459  # Alexander's SDIRK3: the root of x^3 - 3x^2 + 3x/2 - 1/6 in (1/6, 1/2)
_T2 = (1 + _G) / 2
_B1, _B2 = -(6 * _G * _G - 16 * _G + 1) / 4, (6 * _G * _G - 20 * _G + 5) / 4
TABLEAUX = {  # (A, b)
    "radau5": ([[(88 - 7 * _S6) / 360, (296 - 169 * _S6) / 1800, (-2 + 3 * _S6) / 225],
                [(296 + 169 * _S6) / 1800, (88 + 7 * _S6) / 360, (-2 - 3 * _S6) / 225],
                [(16 - _S6) / 36, (16 + _S6) / 36, 1.0 / 9]], [(16 - _S6) / 36, (16 + _S6) / 36, 1.0 / 9]),
    "radau3": ([[5 / 12, -1 / 12], [3 / 4, 1 / 4]], [3 / 4, 1 / 4]),
    "gauss2": ([[1 / 4, 1 / 4 - _S3 / 6], [1 / 4 + _S3 / 6, 1 / 4]], [1 / 2, 1 / 2]),
    "sdirk3": ([[_G, 0, 0], [_T2 - _G, _G, 0], [_B1, _B2, _G]], [_B1, _B2, _G]),
}
# BDF-k: sum_j a_j x_{n+1-j} = h f(x_{n+1}), a_0 first.
BDF = {1: [1, -1], 2: [3 / 2, -2, 1 / 2], 3: [11 / 6, -3, 3 / 2, -1 / 3], 4: [25 / 12, -4, 3, -4 / 3, 1 / 4],
       5: [137 / 60, -5, 5, -10 / 3, 5 / 4, -1 / 5]}
STAGES = {"radau5": 3, "radau3": 2, "gauss2": 2, "sdirk3": 3}  # stage residuals per Newton iteration


def stability_function(method, z):
    A, b = TABLEAUX[method]
    n = len(b)
    return 1 + z * np.asarray(b) @ np.linalg.solve(np.eye(n) - z * np.asarray(A), np.ones(n))


def _ga_map(rho, w, zeta, h):
    am, af = (2 * rho - 1) / (rho + 1), rho / (rho + 1)
    g = 0.5 + af - am
    b = 0.25 * (g + 0.5) ** 2
    # Unknowns of a step (x1, v1, xdd1, a1) from (x0, v0, xdd0, a0):
    #   x1 - b h^2 a1 = x0 + h v0 + (0.5 - b) h^2 a0;  v1 - g h a1 = v0 + (1 - g) h a0;
    #   xdd1 + 2 zeta w v1 + w^2 x1 = 0;  (1 - am) a1 - (1 - af) xdd1 = af xdd0 - am a0.
    L = np.array([[1, 0, 0, -b * h * h], [0, 1, 0, -g * h], [w * w, 2 * zeta * w, 1, 0], [0, 0, -(1 - af), 1 - am]], dtype=float)
    R = np.array([[1, h, 0, (0.5 - b) * h * h], [0, 1, 0, (1 - g) * h], [0, 0, 0, 0], [0, 0, af, -am]], dtype=float)
    return np.linalg.eigvals(np.linalg.solve(L, R))


def one_step(method, f_hz, zeta, h):
    """(amplitude ratio per period, exact ratio, phase error per period [deg]) of `method` on the
    oscillator of frequency f_hz and damping ratio zeta at the step h [s]. The amplitude ratio is that
    of the largest root of the map (what grows or decays); the phase error is the principal root's
    (the one nearest exp(h lambda)) against the exact damped frequency."""
    w = 2 * np.pi * f_hz
    wd = w * np.sqrt(1 - zeta * zeta)
    z = h * complex(-zeta * w, wd)
    if method in TABLEAUX:
        r = stability_function(method, z)
        roots = np.array([r])
    elif method.startswith("bdf"):
        a = np.array(BDF[int(method[3:])], dtype=complex)
        a[0] -= z
        roots = np.roots(a)
    elif method.startswith("ga"):
        roots = _ga_map(float(method[2:]), w, zeta, h)
    else:
        raise ValueError(f"unknown method {method}")
    principal = roots[np.argmin(abs(roots - np.exp(z)))]
    steps = 2 * np.pi / (wd * h)
    return (max(abs(roots)) ** steps, np.exp(-zeta * w * h) ** steps,
            (np.angle(principal) / (wd * h) - 1) * 360.0)


def amplitude_per_period(method, w_h, rho=None):
    """Amplitude ratio over one period of the undamped oscillator at w h = w_h (radau5, or
    generalized-alpha with rho)."""
    name = "radau5" if method == "radau5" else f"ga{rho:g}"
    return one_step(name, 1.0, 0.0, w_h / (2 * np.pi))[0]
