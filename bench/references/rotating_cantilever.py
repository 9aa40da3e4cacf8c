#!/usr/bin/env python3
"""Rotating-cantilever reference: bending frequencies of a uniform Euler-Bernoulli beam clamped to a hub of
radius 0 that turns at the constant rate Omega, linearised about the steady spin. Independent of seflex.

Dimensionless (EI = rho A = L = 1): gamma = Omega sqrt(rho A L^4/(E I)), frequency
lambda = omega sqrt(rho A L^4/(E I)).

  flapwise (out of the plane of rotation):  (EI w'')'' - (N w')'                   + rho A w_tt = 0
  chordwise / lead-lag (in the plane):      (EI v'')'' - (N v')' - rho A Omega^2 v + rho A v_tt = 0
  N(x) = rho A Omega^2 (L^2 - x^2)/2 (centrifugal tension, hub radius 0); w = w' = 0 at x = 0,
  w'' = w''' = 0 at x = L.

Axially inextensible, no chordwise/axial Coriolis coupling (the classic tables' assumptions). Because the lag
operator is the flap one shifted by -Omega^2 rho A, lag_i^2 = flap_i^2 - gamma^2 exactly, mode by mode.

Two independent methods, and their agreement is printed:
  1. Hermite-cubic finite elements (w, w' per node), consistent mass, geometric stiffness of the quadratic N(x)
     integrated exactly (4-point Gauss), scipy.linalg.eigh solved for 1/lambda^2 (see lowest_eigenvalues);
     25, 50, 100, 200 elements, Richardson extrapolation of the last two (error O(h^4)).
  2. Frobenius power series about the root (the method of Wright et al. 1982): two series solutions
     satisfying the clamp, 2x2 frequency determinant at the free end, roots by Brent to 1e-13.
The table written is the Frobenius one.

Published values: Wright, A.D., Smith, C.E., Thresher, R.W., Wang, J.L.C., "Vibration modes of centrifugally
stiffened beams", ASME J. Appl. Mech. 49(1) (1982) 197-202 (authors as cited in the reference list at
https://jrstan.basu.ac.ir/article_2485.html, ref. [3]) tabulate these frequencies; their table itself could
NOT be retrieved with the search tool available (see bench/references/README.md), so no rotating value is
quoted. Only the non-rotating (gamma = 0) values were found: 3.5160, 22.0345, 61.6972 (Thomson, Theory of
Vibration with Applications, App. D.3, clamped-free beam, (beta l)^2 column,
https://digilib.universitaspertamina.ac.id/ebook/Theory%20of%20Vibration%20with%20Applications/files/basic-html/page523.html).

Run (from the repository root):
  /usr/bin/python3 bench/references/rotating_cantilever.py            # prints the tables and the comparison
  /usr/bin/python3 bench/references/rotating_cantilever.py --write    # also writes the csv
Output: tests/data/mbd/rotating_cantilever_frequencies.csv
"""
import os
import sys

import numpy as np
from scipy.linalg import eigh
from scipy.optimize import brentq

GAMMAS = list(range(0, 13))
MESHES = [25, 50, 100, 200]
NMODES = 3

# Published flapwise values (lambda), only what could be found and checked; see the module docstring.
PUBLISHED = {0: (3.5160, 22.0345, 61.6972)}
PUBLISHED_SOURCE = (
    "published: gamma = 0 only, 3.5160 22.0345 61.6972 (Thomson, Theory of Vibration with Applications, App. D.3,\n"
    "clamped-free (beta l)^2). The rotating table of Wright, Smith, Thresher and Wang (1982, J. Appl. Mech. 49:197-202)\n"
    "could not be retrieved here: the pub_ columns are empty for gamma > 0.")


def hermite_matrices(n_el):
    """K (EI = 1), M (rho A = 1), K_G for N(x) = (1 - x^2)/2 (gamma = 1), L = 1, clamp at x = 0 removed."""
    h = 1.0 / n_el
    ndof = 2 * (n_el + 1)
    K = np.zeros((ndof, ndof))
    M = np.zeros((ndof, ndof))
    G = np.zeros((ndof, ndof))
    ke = np.array([[12, 6 * h, -12, 6 * h],
                   [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                   [-12, -6 * h, 12, -6 * h],
                   [6 * h, 2 * h * h, -6 * h, 4 * h * h]]) / h ** 3
    me = h / 420.0 * np.array([[156, 22 * h, 54, -13 * h],
                               [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                               [54, 13 * h, 156, -22 * h],
                               [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    xg, wg = np.polynomial.legendre.leggauss(4)
    xi = 0.5 * (xg + 1.0)
    wi = 0.5 * wg
    dN = np.stack([(-6 * xi + 6 * xi ** 2) / h,
                   1 - 4 * xi + 3 * xi ** 2,
                   (6 * xi - 6 * xi ** 2) / h,
                   -2 * xi + 3 * xi ** 2], axis=1)          # d(shape)/dx at the Gauss points (4 x 4)
    for e in range(n_el):
        x = (e + xi) * h
        N = 0.5 * (1.0 - x * x)
        ge = np.einsum('g,ga,gb->ab', wi * N * h, dN, dN)
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += ke
        M[s, s] += me
        G[s, s] += ge
    keep = slice(2, ndof)
    return K[keep, keep], M[keep, keep], G[keep, keep]


def lowest_eigenvalues(A, M):
    """The NMODES lowest lambda of A x = lambda M x (A, M SPD), solved as the largest mu = 1/lambda of
    M x = mu A x: LAPACK's absolute error is eps * |largest eigenvalue|, so the lowest lambda of the stiff
    problem would lose digits (cond ~ n^4, 2e-4 relative at 400 elements) while the largest mu keeps them."""
    n = A.shape[0]
    mu = eigh(M, A, eigvals_only=True, subset_by_index=[n - NMODES, n - 1])
    return np.sort(1.0 / mu)


def fe_frequencies(n_el):
    K, M, G = hermite_matrices(n_el)
    flap = np.zeros((len(GAMMAS), NMODES))
    lag = np.zeros((len(GAMMAS), NMODES))
    for i, g in enumerate(GAMMAS):
        flap[i] = np.sqrt(lowest_eigenvalues(K + g * g * G, M))
        lag[i] = np.sqrt(lowest_eigenvalues(K + g * g * G - g * g * M, M))
    return flap, lag


def frobenius_det(mu, g, nterms=300):
    """Frequency determinant of the power-series solution of w'''' - (N w')' = mu w, N = g^2 (1 - x^2)/2,
    mu = lambda^2 (flap) or lambda^2 + g^2 (lag). w = sum a_k x^k with a_0 = a_1 = 0 (clamp) and
      (k+4)(k+3)(k+2)(k+1) a_{k+4} = g^2/2 (k+2)(k+1) a_{k+2} + (mu - g^2 (k(k-1)/2 + k)) a_k.
    Free end: w''(1) = 0, w'''(1) - N(1) w'(1) = w'''(1) = 0; determinant of that 2x2 system in (a_2, a_3)."""
    k = np.arange(nterms + 4)
    ends = []
    for a2, a3 in ((1.0, 0.0), (0.0, 1.0)):
        a = np.zeros(nterms + 4)
        a[2], a[3] = a2, a3
        for j in range(nterms):
            a[j + 4] = (0.5 * g * g * (j + 2) * (j + 1) * a[j + 2] + (mu - g * g * (j * (j - 1) / 2 + j)) * a[j]) \
                / ((j + 4) * (j + 3) * (j + 2) * (j + 1))
        ends.append((np.sum(k * (k - 1) * a), np.sum(k * (k - 1) * (k - 2) * a)))
    return ends[0][0] * ends[1][1] - ends[0][1] * ends[1][0]


def frobenius_frequencies(g, guesses, lag=False):
    """Roots of frobenius_det bracketed within +-3 % of the FE guesses, to 1e-13."""
    shift = g * g if lag else 0.0
    out = []
    for lam in guesses:
        def f(x):
            return frobenius_det(x * x + shift, g)
        lo, hi = 0.97 * lam, 1.03 * lam
        if not np.sign(f(lo)) != np.sign(f(hi)):
            raise RuntimeError(f"Frobenius root not bracketed near {lam} (gamma {g})")
        out.append(brentq(f, lo, hi, xtol=1e-13, rtol=1e-14))
    return np.array(out)


def main():
    write = "--write" in sys.argv
    runs = {n: fe_frequencies(n) for n in MESHES}
    nf, nc = MESHES[-1], MESHES[-2]
    flap_fe = (16 * runs[nf][0] - runs[nc][0]) / 15     # Richardson, O(h^4)
    lag_fe = (16 * runs[nf][1] - runs[nc][1]) / 15
    flap = np.array([frobenius_frequencies(g, flap_fe[i]) for i, g in enumerate(GAMMAS)])
    lag = np.array([frobenius_frequencies(g, lag_fe[i], lag=True) for i, g in enumerate(GAMMAS)])
    d_flap = np.max(np.abs(flap_fe / flap - 1))
    d_lag = np.max(np.abs(lag_fe / lag - 1))
    ident = np.max(np.abs(lag ** 2 - (flap ** 2 - np.array(GAMMAS)[:, None] ** 2)) / flap ** 2)

    print("FE convergence: max over gamma 0..12 and modes 1..3 of |FE / Frobenius - 1|")
    for n in MESHES:
        print(f"  {n:4d} elements: flap {np.max(np.abs(runs[n][0] / flap - 1)):.2e}   "
              f"lag {np.max(np.abs(runs[n][1] / lag - 1)):.2e}")
    print(f"  Richardson {nc}/{nf}: flap {d_flap:.1e}, lag {d_lag:.1e}")
    print(f"  check lag^2 = flap^2 - gamma^2 (Frobenius): max rel. deviation {ident:.1e}")
    print()
    print("gamma |  flap1      flap2      flap3    |  lag1       lag2       lag3     | published flap (rel. diff)")
    for i, g in enumerate(GAMMAS):
        line = (f"{g:5d} | {flap[i, 0]:9.4f}  {flap[i, 1]:9.4f}  {flap[i, 2]:9.4f} | "
                f"{lag[i, 0]:9.4f}  {lag[i, 1]:9.4f}  {lag[i, 2]:9.4f} |")
        pub = PUBLISHED.get(g)
        if pub:
            line += "".join(f" {p:.4f} ({p / flap[i, k] - 1:+.1e})" for k, p in enumerate(pub))
        else:
            line += " (not found)"
        print(line)

    if write:
        here = os.path.dirname(os.path.abspath(__file__))
        out = os.path.normpath(os.path.join(here, "..", "..", "tests", "data", "mbd",
                                            "rotating_cantilever_frequencies.csv"))
        with open(out, "w") as f:
            f.write("# Rotating uniform Euler-Bernoulli cantilever, hub radius 0, linearised about the steady spin.\n")
            f.write("# Dimensionless: gamma = Omega sqrt(rho A L^4/(EI)); frequencies omega sqrt(rho A L^4/(EI)).\n")
            f.write("# flap = out of the plane of rotation (K + K_G); lag = chordwise, in the plane (K + K_G - Omega^2 M);\n")
            f.write("# axially inextensible, no Coriolis coupling; lag^2 = flap^2 - gamma^2.\n")
            f.write("# Computed by bench/references/rotating_cantilever.py (independent of seflex): Frobenius power series\n")
            f.write(f"# (roots to 1e-13); Hermite FE {nc}/{nf} elements + Richardson agrees to {max(d_flap, d_lag):.1e} relative.\n")
            for line in PUBLISHED_SOURCE.splitlines():
                f.write("# " + line + "\n")
            f.write("# source: computed (this script); pub_flap1..3: published value where found, else empty\n")
            f.write("gamma,flap1,flap2,flap3,lag1,lag2,lag3,pub_flap1,pub_flap2,pub_flap3,source\n")
            for i, g in enumerate(GAMMAS):
                pub = PUBLISHED.get(g, (None, None, None))
                ps = ",".join("" if p is None else f"{p:.4f}" for p in pub)
                f.write(f"{g}," + ",".join(f"{v:.6f}" for v in flap[i]) + "," +
                        ",".join(f"{v:.6f}" for v in lag[i]) + f",{ps},computed\n")
        print(f"\nwrote {out}")


if __name__ == "__main__":
    main()
