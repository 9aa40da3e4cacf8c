#!/usr/bin/python3
"""Check bench/lib/linear_test.py (a CTest, label bench) against closed forms, so that the tables of
docs/stability.md ("Numerical damping", "Other candidates") rest on correct one-step maps:
  - the Runge-Kutta stability functions against their Pade forms (Hairer and Wanner II, IV.3 and
    IV.5): Radau IIA-5 (2,3), Radau IIA-3 (1,2), Gauss-2 (2,2); |R(i y)| = 1 for Gauss;
  - each method's order from R(z) - exp(z) (or the BDF principal root) at two small steps;
  - L-stability (R(-inf) = 0) of Radau IIA and the SDIRK; generalized-alpha's spectral radius at
    infinity equals rho_inf, and it does not damp an undamped mode at rho_inf = 1;
  - the exact damped decay per period exp(-2 pi zeta / sqrt(1 - zeta^2)).

  /usr/bin/python3 bench/lib/check_linear_test.py
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lib.linear_test import BDF, one_step, stability_function  # noqa: E402

failures = []


def check(what, ok, detail=""):
    print(f"{'ok  ' if ok else 'FAIL'} {what} {detail}")
    if not ok:
        failures.append(what)


def main():
    pade = {
        "radau5": lambda z: (1 + 2 * z / 5 + z * z / 20) / (1 - 3 * z / 5 + 3 * z * z / 20 - z ** 3 / 60),
        "radau3": lambda z: (1 + z / 3) / (1 - 2 * z / 3 + z * z / 6),
        "gauss2": lambda z: (1 + z / 2 + z * z / 12) / (1 - z / 2 + z * z / 12),
    }
    zs = [0.3j, -0.7 + 2.0j, -5.0, 4.0j, -0.01 + 20j]
    for m, f in pade.items():
        err = max(abs(stability_function(m, z) - f(z)) for z in zs)
        check(f"{m}: stability function is its Pade form", err < 1e-12, f"(largest difference {err:.1e})")
    err = max(abs(abs(stability_function("gauss2", 1j * y)) - 1) for y in (0.1, 1.0, 10.0, 1e3))
    check("gauss2: |R(iy)| = 1", err < 1e-12, f"({err:.1e})")
    # Order p: R(z) - exp(z) ~ C z^(p+1); halving z divides it by 2^(p+1).
    for m, p in (("radau5", 5), ("radau3", 3), ("gauss2", 4), ("sdirk3", 3)):
        e1, e2 = (abs(stability_function(m, z) - np.exp(z)) for z in (0.08j, 0.04j))
        q = np.log2(e1 / e2) - 1
        check(f"{m}: order {p}", abs(q - p) < 0.15, f"(measured {q:.2f})")
    for k in BDF:
        def principal(z):
            a = np.array(BDF[k], dtype=complex)
            a[0] -= z
            r = np.roots(a)
            return r[np.argmin(abs(r - np.exp(z)))]
        e1, e2 = (abs(principal(z) - np.exp(z)) for z in (0.02j, 0.01j))
        q = np.log2(e1 / e2) - 1
        check(f"bdf{k}: order {k}", abs(q - k) < 0.15, f"(measured {q:.2f})")
    for m in ("radau5", "radau3", "sdirk3"):
        r = abs(stability_function(m, -1e9))
        check(f"{m}: L-stable, R(-inf) = 0", r < 1e-6, f"(|R(-1e9)| = {r:.1e})")
    for rho in (0.8, 0.9, 1.0):
        a, _, _ = one_step(f"ga{rho:g}", 1.0, 0.0, 1e4)  # w h = 2 pi 1e4: the high-frequency limit
        r = a ** (1.0 / 1e-4)  # per step: the amplitude ratio per period is r^(2 pi / (w h)) = r^1e-4
        check(f"generalized-alpha rho_inf {rho:g}: spectral radius at infinity = rho_inf", abs(r - rho) < 1e-3, f"({r:.5f})")
    a, _, ph = one_step("ga1", 7.0, 0.0, 2.5e-3)
    check("generalized-alpha rho_inf 1: no damping of an undamped mode", abs(a - 1) < 1e-12, f"({a - 1:.1e})")
    _, _, ph2 = one_step("ga0.9", 7.0, 0.0, 1.25e-3)
    _, _, ph1 = one_step("ga0.9", 7.0, 0.0, 2.5e-3)
    check("generalized-alpha: phase error per period ~ h^2", abs(ph1 / ph2 - 4) < 0.05, f"(ratio {ph1 / ph2:.3f})")
    zeta = 0.02
    _, exact, _ = one_step("radau5", 33.0, zeta, 1e-3)
    ref = np.exp(-2 * np.pi * zeta / np.sqrt(1 - zeta * zeta))
    check("exact decay per period", abs(exact - ref) < 1e-12, f"({exact:.6f} against {ref:.6f})")
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
