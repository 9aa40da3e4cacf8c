#!/usr/bin/env python3
"""Rotating-cantilever reference: bending frequencies of a uniform Euler-Bernoulli beam clamped to a hub of
radius 0 that turns at the constant rate Omega, linearised about the steady spin.

Dimensionless (EI = rho A = L = 1): gamma = Omega sqrt(rho A L^4/(E I)), frequency
lambda = omega sqrt(rho A L^4/(E I)).

  flapwise (out of the plane of rotation):  (EI w'')'' - (N w')'             + rho A w_tt = 0
  chordwise / lead-lag (in the plane):      (EI v'')'' - (N v')' - rho A Omega^2 v + rho A v_tt = 0
  N(x) = rho A Omega^2 (L^2 - x^2)/2 (centrifugal tension, hub radius 0), w = w' = 0 at x = 0,
  w'' = w''' = 0 at x = L.

The beam is inextensible along its axis (no axial / chordwise Coriolis coupling), as in the published tables
(Wright et al. 1982; Hodges and Rutkowski 1981). Because the lag operator is the flap one shifted by
-Omega^2 M, lag_i^2 = flap_i^2 - gamma^2 exactly for every mode; the script computes it from the FE
eigenproblem all the same (K + K_G - gamma^2 M), and checks the identity.

Method (independent of seflex): Hermite-cubic finite elements (w, w' per node), consistent mass, the exact
geometric stiffness of the quadratic N(x) integrated with 4-point Gauss (exact for the degree-6 integrand),
generalised symmetric eigenproblem with scipy.linalg.eigh (solved for 1/lambda, see lowest_eigenvalues);
25, 50, 100 and 200 elements, Richardson
extrapolation of the two finest meshes (the error of Hermite elements on frequency is O(h^4)).

Run (from the repository root):
  /usr/bin/python3 bench/references/rotating_cantilever.py            # prints the tables and the comparison
  /usr/bin/python3 bench/references/rotating_cantilever.py --write    # also writes the csv
Output: tests/data/mbd/rotating_cantilever_frequencies.csv
"""
import os
import sys

import numpy as np
from scipy.linalg import eigh

GAMMAS = list(range(0, 13))
MESHES = [25, 50, 100, 200]
NMODES = 3

# Published flapwise values, dimensionless lambda = omega sqrt(rho A L^4/(EI)), hub radius 0.
# Filled in below from the literature search (see PUBLISHED_SOURCE); None where not found.
PUBLISHED = {}
PUBLISHED_SOURCE = ""


def hermite_matrices(n_el):
    """Global K (EI = 1), M (rho A = 1), K_G for N(x) = (1 - x^2)/2 (i.e. Omega = 1), L = 1, clamped at x=0."""
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
    # Gauss-Legendre 4 points on [0, 1]
    xg, wg = np.polynomial.legendre.leggauss(4)
    xi = 0.5 * (xg + 1.0)
    wi = 0.5 * wg
    # derivatives of the Hermite shape functions wrt x (x = x0 + xi h)
    dN = np.stack([(-6 * xi + 6 * xi ** 2) / h,
                   1 - 4 * xi + 3 * xi ** 2,
                   (6 * xi - 6 * xi ** 2) / h,
                   -2 * xi + 3 * xi ** 2], axis=1)          # (4 gauss, 4 shape)
    for e in range(n_el):
        x = (e + xi) * h
        N = 0.5 * (1.0 - x * x)
        ge = np.einsum('g,ga,gb->ab', wi * N * h, dN, dN)
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += ke
        M[s, s] += me
        G[s, s] += ge
    keep = slice(2, ndof)                                   # clamp w = w' = 0 at the hub
    return K[keep, keep], M[keep, keep], G[keep, keep]


def lowest_eigenvalues(A, M):
    """The NMODES lowest lambda of A x = lambda M x (A, M symmetric positive definite), solved as the largest
    mu = 1/lambda of M x = mu A x: LAPACK's absolute error is eps * |largest eigenvalue|, so the lowest lambda
    of the stiff problem would lose digits (cond ~ n^4) while the largest mu keeps them."""
    n = A.shape[0]
    mu = eigh(M, A, eigvals_only=True, subset_by_index=[n - NMODES, n - 1])
    return np.sort(1.0 / mu)


def frequencies(n_el, gammas=GAMMAS):
    K, M, G = hermite_matrices(n_el)
    flap = np.zeros((len(gammas), NMODES))
    lag = np.zeros((len(gammas), NMODES))
    for i, g in enumerate(gammas):
        flap[i] = np.sqrt(lowest_eigenvalues(K + g * g * G, M))
        lag[i] = np.sqrt(lowest_eigenvalues(K + g * g * G - g * g * M, M))
    return flap, lag


def main():
    write = "--write" in sys.argv
    runs = {n: frequencies(n) for n in MESHES}
    nf, nc = MESHES[-1], MESHES[-2]
    # Richardson on omega with O(h^4)
    flap = (16 * runs[nf][0] - runs[nc][0]) / 15
    lag = (16 * runs[nf][1] - runs[nc][1]) / 15

    print("Convergence (flap, max over gamma 0..12 and modes 1..3 of |rel. diff| to the extrapolated value):")
    for n in MESHES:
        print(f"  {n:4d} elements: flap {np.max(np.abs(runs[n][0] / flap - 1)):.2e}   "
              f"lag {np.max(np.abs(runs[n][1] / lag - 1)):.2e}")
    print(f"  Richardson correction ({nc}/{nf}) at most {np.max(np.abs(flap / runs[nf][0] - 1)):.1e} (relative)")
    ident = np.max(np.abs(lag ** 2 - (flap ** 2 - np.array(GAMMAS)[:, None] ** 2)) / flap ** 2)
    print(f"  check lag^2 = flap^2 - gamma^2: max rel. deviation {ident:.1e}")
    print()
    print("gamma |  flap1      flap2      flap3    |  lag1       lag2       lag3     | published flap1..3 (rel. diff)")
    for i, g in enumerate(GAMMAS):
        line = (f"{g:5d} | {flap[i, 0]:9.4f}  {flap[i, 1]:9.4f}  {flap[i, 2]:9.4f} | "
                f"{lag[i, 0]:9.4f}  {lag[i, 1]:9.4f}  {lag[i, 2]:9.4f} |")
        pub = PUBLISHED.get(g)
        if pub:
            for k in range(3):
                if pub[k] is None:
                    line += "      -        "
                else:
                    line += f" {pub[k]:.4f} ({pub[k] / flap[i, k] - 1:+.1e})"
        print(line)

    if write:
        here = os.path.dirname(os.path.abspath(__file__))
        out = os.path.join(here, "..", "..", "tests", "data", "mbd", "rotating_cantilever_frequencies.csv")
        with open(out, "w") as f:
            f.write("# Rotating uniform Euler-Bernoulli cantilever, hub radius 0, linearised about steady spin.\n")
            f.write("# Dimensionless: gamma = Omega sqrt(rho A L^4/(EI)); frequencies omega sqrt(rho A L^4/(EI)).\n")
            f.write("# flap = out of the plane of rotation (K + K_G); lag = chordwise, in the plane (K + K_G - Omega^2 M);\n")
            f.write("# axially inextensible, no Coriolis coupling. lag^2 = flap^2 - gamma^2.\n")
            f.write(f"# Computed by bench/references/rotating_cantilever.py: Hermite-cubic FE, {nc} and {nf} elements,\n")
            f.write(f"# Richardson-extrapolated (O(h^4)); largest correction {np.max(np.abs(flap / runs[nf][0] - 1)):.1e} relative.\n")
            for line in PUBLISHED_SOURCE.strip().splitlines():
                f.write("# " + line + "\n")
            f.write("# source column: 'computed' (this script); pub_flap1..3: published values where found, else empty\n")
            f.write("gamma,flap1,flap2,flap3,lag1,lag2,lag3,pub_flap1,pub_flap2,pub_flap3,source\n")
            for i, g in enumerate(GAMMAS):
                pub = PUBLISHED.get(g, (None, None, None))
                ps = ",".join("" if p is None else f"{p:.4f}" for p in pub)
                f.write(f"{g}," + ",".join(f"{v:.6f}" for v in flap[i]) + "," +
                        ",".join(f"{v:.6f}" for v in lag[i]) + f",{ps},computed\n")
        print(f"\nwrote {os.path.normpath(out)}")


if __name__ == "__main__":
    main()
