#!/usr/bin/python3
"""Which time integrators could pay on the demo (issue 38: "other candidates welcome, e.g. a 2-stage
Gauss or an ESDIRK, with the reason each wins or loses"; "BDF of order 3-5 amplifies the panels'
lightly damped 33 Hz mode"): the linear test oscillator at constant steps, no seflex run.

sync-3d's accuracy is set by the motions after the locks latch: the 7 Hz lock ringing (undamped, 5 s,
35 periods, which all three accuracy measures follow) and the bodies' modes a latch excites, damped
as the scene damps them (stiffness-proportional, beta = 2e-4 s: zeta = beta pi f, 2 % at the panels'
first mode, 33 Hz, critical above 1.6 kHz). For each method (bench/lib/linear_test.py) it prints
  1. amplitude ratio and phase error per period of the 7 Hz ringing and of the 33 Hz mode at the
     demo's steps and above;
  2. its high-frequency limit |R(inf)| (what it leaves of the stiff interface modes a latch excites);
  3. the largest constant step at which 35 periods of the ringing keep their amplitude within 1 %
     and their phase within the published generalized-alpha run's (rho_inf 0.9 at 2.5 ms), while no
     mode of 5 Hz - 1.6 kHz with the scene's damping grows (the band of modes that grows at the
     published step is printed); and the stage residuals per Newton iteration, so that
     steps x residuals is the work of the ringing relative to the published run.
This is the linear estimate only: on sync-3d the implicit Runge-Kutta steps are also limited by
simplified Newton's contraction (docs/benchmarks.md).

usage: /usr/bin/python3 bench/integrator_candidates.py
"""
import os, sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib.linear_test import STAGES, one_step, stability_function  # noqa: E402

RING_HZ, RING_PERIODS = 7.0, 35  # the lock ringing after the last latch: 5 s
PANEL_HZ, PANEL_ZETA = 33.0, 0.02
BETA = 2.0e-4  # the scene's stiffness-proportional damping [s]: zeta = BETA pi f
MODES_HZ = np.geomspace(5.0, 1.6e3, 400)
PUBLISHED = ("ga0.9", 2.5e-3)
METHODS = ["ga0.9", "radau5", "radau3", "gauss2", "sdirk3", "bdf2", "bdf3", "bdf4", "bdf5"]
NAMES = {"ga0.9": "generalized-alpha rho_inf 0.9", "radau5": "Radau IIA-5 (3 stages)", "radau3": "Radau IIA-3 (2 stages)",
         "gauss2": "Gauss-Legendre, 2 stages (order 4)", "sdirk3": "SDIRK, 3 stages (order 3, L-stable)",
         "bdf2": "BDF2", "bdf3": "BDF3", "bdf4": "BDF4", "bdf5": "BDF5"}


def residuals_per_iteration(m):
    return STAGES.get(m, 1)


def high_frequency_limit(m):
    z = -1e9
    if m in STAGES:
        return abs(stability_function(m, z))
    if m.startswith("ga"):
        return float(m[2:])
    return 0.0  # BDF: every root of a_0 x^k = z x^k ... tends to 0 as z -> -inf


def growing_modes(m, h):
    """The frequencies of MODES_HZ, damped as the scene damps them, that grow at the step h."""
    return [f for f in MODES_HZ if one_step(m, f, min(BETA * np.pi * f, 0.99), h)[0] > 1.0 + 1e-9]


def acceptable(m, h, phase_limit):
    amp, _, ph = one_step(m, RING_HZ, 0.0, h)
    return abs(amp ** RING_PERIODS - 1) <= 0.01 and abs(ph) * RING_PERIODS <= phase_limit and not growing_modes(m, h)


def largest_step(m, phase_limit):
    """The largest step below which every step passes (from 0.2 ms)."""
    hs = np.geomspace(2e-4, 5e-2, 200)
    best = None
    for h in hs:
        if not acceptable(m, h, phase_limit):
            break
        best = h
    return best


def main():
    print("/usr/bin/python3 bench/integrator_candidates.py")
    hs = (2.5e-3, 5e-3, 1e-2, 1.5e-2, 2e-2)
    for f, zeta, what in ((RING_HZ, 0.0, "7 Hz lock ringing, undamped"), (PANEL_HZ, PANEL_ZETA, "33 Hz panel mode, 2 % damping")):
        ex = one_step("radau5", f, zeta, 1e-3)[1]
        print(f"\n{what}: amplitude ratio per period (exact {ex:.4f}) / phase error per period [deg]\n")
        print("| method | " + " | ".join(f"h = {h * 1e3:g} ms" for h in hs) + " |")
        print("|---|" + "---:|" * len(hs))
        for m in METHODS:
            cells = []
            for h in hs:
                a, _, p = one_step(m, f, zeta, h)
                cells.append(f"{a:.4f} / {p:+.3f}")
            print(f"| {NAMES[m]} | " + " | ".join(cells) + " |")
    a0, _, p0 = one_step(PUBLISHED[0], RING_HZ, 0.0, PUBLISHED[1])
    limit = abs(p0) * RING_PERIODS
    print(f"\nThe published run's method and step ({NAMES[PUBLISHED[0]]}, {PUBLISHED[1] * 1e3:g} ms): {RING_PERIODS} periods of the "
          f"ringing drift {limit:.1f} deg in phase.\nLargest constant step with 35 periods of the ringing within 1 % in amplitude "
          f"and {limit:.1f} deg in phase, no mode of 5 Hz - 1.6 kHz growing with the scene's damping:\n")
    print("| method | largest step [ms] | steps relative to the published run | stage residuals per Newton iteration | |R(inf)| | modes that grow at 2.5 ms |")
    print("|---|---:|---:|---:|---:|---|")
    for m in METHODS:
        h = largest_step(m, limit)
        hf = high_frequency_limit(m)
        g = growing_modes(m, PUBLISHED[1])
        band = f"{min(g):.0f}-{max(g):.0f} Hz" if g else "none"
        if h is None:
            print(f"| {NAMES[m]} | none from 0.2 ms | - | {residuals_per_iteration(m)} | {hf:.3g} | {band} |")
        else:
            print(f"| {NAMES[m]} | {h * 1e3:.2f} | {PUBLISHED[1] / h:.3f} | {residuals_per_iteration(m)} | {hf:.3g} | {band} |")


if __name__ == "__main__":
    main()
