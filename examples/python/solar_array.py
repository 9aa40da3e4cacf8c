#!/usr/bin/env python3
"""The solar-array demonstration from Python: reduce the yoke and the panel to the 3D Craig-Bampton
superelements of scripts/demo.sh (yoke interface grids {1, 3, 4}, panel {1, 2, 3, 4}, 10 fixed-interface
modes each), run the synchronised deployment examples/solar_array/sync-3d.yaml (yoke and two panels
unfolding on spring-driven hinges that latch, two cable loops), and plot the hinge angles and the lock
torques against time (a PNG, matplotlib's Agg backend).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/solar_array.py [OUTDIR] [--modes N] [--t-end T] [--small]

OUTDIR (default solar-array-python/) receives superelements/, sync-3d/ (the files of `seflex run`) and
sync-3d.png. --small: 2 modes per body, the preview settings of docs/solar-array-results.md and 3.2 s of
deployment (a few seconds; the CTest).
"""
import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import seflex  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
BODIES = {"yoke": [1, 3, 4], "panel": [1, 2, 3, 4]}  # the 3D reduction's interface grids


def reduce_superelements(out: pathlib.Path, modes: int) -> None:
    """Write out/superelements/{yoke,panel}-3d.se, as scripts/demo.sh does with `seflex reduce`."""
    (out / "superelements").mkdir(parents=True, exist_ok=True)
    for body, interface in BODIES.items():
        model = seflex.read_model(ROOT / "meshes" / f"{body}.bdf")
        se = seflex.reduce(model, interface=interface, modes=modes, name=f"{body}-3d")
        se.save(out / "superelements" / f"{body}-3d.se", overwrite=True)


def sync_3d(out: pathlib.Path, preview: bool) -> seflex.Scene:
    """sync-3d.yaml with its superelement paths taken from `out` (optionally at the preview settings)."""
    scene = seflex.Scene.load(ROOT / "examples" / "solar_array" / "sync-3d.yaml")
    scene.folder = out  # superelements/yoke-3d.se ... are relative to it
    del scene.output.animation
    if preview:  # docs/solar-array-results.md, "Preview settings"
        scene.integrator.max_step = 5.0e-3
        scene.integrator.tolerance = {"position": 1.0e-4, "angle": 1.0e-4}
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", nargs="?", default="solar-array-python", type=pathlib.Path)
    ap.add_argument("--modes", type=int, default=10, help="fixed-interface modes per superelement (default 10)")
    ap.add_argument("--t-end", type=float, help="end time [s] (default: the scene's, 5 s after the last lock)")
    ap.add_argument("--small", action="store_true", help="2 modes, preview settings, up to 3.2 s")
    a = ap.parse_args()
    if a.small:
        a.modes, a.t_end = 2, a.t_end or 3.2
    reduce_superelements(a.out, a.modes)
    scene = sync_3d(a.out, preview=a.small)

    def progress(t, t_end):
        print(f"\r  t = {t:6.3f} s", end="", file=sys.stderr, flush=True)

    r = seflex.run(scene, output=a.out / "sync-3d", overwrite=True, t_end=a.t_end, progress=progress)
    print(file=sys.stderr)

    t = r.histories["t"]
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    for hinge in ("HL1", "HL2a", "HL3a"):
        ax1.plot(t, r.histories[f"{hinge}.phi_deg"], label=hinge)
        ax2.plot(t, r.histories[f"lock.{hinge}.torque"], label=f"lock.{hinge}")
    ax1.set_ylabel("hinge angle [deg]")
    ax2.set_ylabel("lock torque [N m]")
    ax2.set_xlabel("t [s]")
    for ax in (ax1, ax2):
        ax.grid(True)
        ax.legend()
    ax1.set_title(f"{scene.title} ({a.modes} modes per body)")
    fig.tight_layout()
    fig.savefig(a.out / "sync-3d.png", dpi=100)

    print(f"{r.summary['steps']} steps, {r.summary['cpu_time_s']:.2f} s CPU for {r.summary['final_t']:.3f} s; "
          f"results in {a.out / 'sync-3d'}, plot {a.out / 'sync-3d.png'}")
    for name, lock in r.locks.items():
        print(f"  {name:10s} " + ("never latched" if lock.t_latch is None else
                                  f"latched at {lock.t_latch:.4f} s, peak torque {lock.peak_torque:.1f} N m"))


if __name__ == "__main__":
    main()
