#!/usr/bin/env python3
"""A parameter study from Python: the synchronised 3D solar-array deployment (sync-3d) with the
preload of every hinge spring scaled from 70 % to 130 % of the seed's (the spring stiffness kept),
plotting each lock's latch time and peak torque after latching against the HL1 spring's preload. The
sweep is the eleven lines between the markers; superelements as in solar_array.py, at the preview settings.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/preload_sweep.py [OUTDIR] [--values N] [--t-end T] [--small]

OUTDIR (default preload-sweep/) receives superelements/ and preload_sweep.png. --small: 3 values,
2 modes per body, up to 3.8 s (a few seconds; the CTest).
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import seflex  # noqa: E402
from solar_array import reduce_superelements, sync_3d  # noqa: E402

LOCKS = ("lock.HL1", "lock.HL2a", "lock.HL3a")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", nargs="?", default="preload-sweep", type=pathlib.Path)
    ap.add_argument("--values", type=int, default=10)
    ap.add_argument("--modes", type=int, default=10, help="fixed-interface modes per superelement (default 10)")
    ap.add_argument("--t-end", type=float, help="end time [s] (default: the scene's, 5 s after the last lock)")
    ap.add_argument("--small", action="store_true", help="3 values, 2 modes, up to 3.8 s")
    a = ap.parse_args()
    if a.small:
        a.values, a.modes, a.t_end = 3, 2, a.t_end or 3.8
    reduce_superelements(a.out, a.modes)
    scene = sync_3d(a.out, preview=True)

    # --- the sweep ---
    factors = np.linspace(0.7, 1.3, a.values)
    nominal = {s.hinge: s.preload for s in scene.springs}
    t_latch, peak = np.full((a.values, len(LOCKS)), np.nan), np.full((a.values, len(LOCKS)), np.nan)
    for i, f in enumerate(factors):
        s = scene.copy()
        for spring in s.springs:
            spring.preload = f * nominal[spring.hinge]
        r = seflex.run(s, t_end=a.t_end)
        for j, name in enumerate(LOCKS):
            if r.locks[name].t_latch is not None:
                t_latch[i, j], peak[i, j] = r.locks[name]
    # --- end of the sweep ---

    preload = factors * nominal["HL1"]
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for j, name in enumerate(LOCKS):
        ax1.plot(preload, t_latch[:, j], "o-", label=name)
        ax2.plot(preload, peak[:, j], "o-", label=name)
    ax1.set_ylabel("latch time [s]")
    ax2.set_ylabel("peak torque after latching [N m]")
    ax2.set_xlabel("HL1 spring preload (torque at 0 deg) [N m]; the other springs scaled alike")
    for ax in (ax1, ax2):
        ax.grid(True)
        ax.legend()
    fig.tight_layout()
    fig.savefig(a.out / "preload_sweep.png", dpi=100)
    print("preload HL1 [N m] | " + " | ".join(f"{n} t_latch [s], peak [N m]" for n in LOCKS))
    for i, p in enumerate(preload):
        print(f"{p:8.3f} | " + " | ".join(f"{t_latch[i, j]:.4f} {peak[i, j]:7.1f}" for j in range(len(LOCKS))))
    print(f"plot: {a.out / 'preload_sweep.png'}")


if __name__ == "__main__":
    main()
