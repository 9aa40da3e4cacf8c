#!/usr/bin/python3
"""Synchronisation error of the solar array against the cable loops' stiffness and preload.

    /usr/bin/python3 scripts/solar_array_cable_sweep.py DEMO_OUT [--img docs/img] [--seflex build/apps/seflex]

DEMO_OUT is the output folder of scripts/demo.sh (it holds superelements/, sync-beam.yaml and the
unsync-beam run). The synchronised beam-like scene is rerun with both loops' stiffness scaled by
1, 2, 3, 4, 6, 10 and 100 (seed Table 4: 2.05e5 N/m) and, at the seed's stiffness, with preloads
of 350, 700 and 1400 N; everything else as in the demo. For each run: max|phi2 - 2 phi1| and
max|phi3 - phi2| before the first lock (as scripts/plot_solar_array.py computes them), the ratio
to the unsynchronised run, the lock times and the peak cable tension of loop 1. Prints a Markdown
table (docs/solar-array-results.md, "Synchronisation error of loop 1") and, with --img, writes
solar-array-cable-sweep.png there. Runs go to DEMO_OUT/cable-sweep/ (two at a time; --reuse keeps finished ones).
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_solar_array as psa  # noqa: E402

K_SEED = 2.05e5  # [N/m], seed Table 4
SCALES = [1, 2, 3, 4, 6, 10, 100]
PRELOADS = [350.0, 700.0, 1400.0]  # [N], at the seed's stiffness


def scene_text(base, k, preload):
    """The sync-beam scene with both loops' stiffness set to k and the given preload."""
    n = len(re.findall(r"stiffness: 2\.05e5\n", base))
    if n != 2:
        raise SystemExit("cable sweep: expected the two cable loops with 'stiffness: 2.05e5' in sync-beam.yaml, found %d" % n)
    repl = "stiffness: %.6g\n" % k + ("    preload: %.6g\n" % preload if preload > 0 else "")
    return base.replace("stiffness: 2.05e5\n", repl)


def run(seflex, folder, name, text):
    path = os.path.join(folder, name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(folder, name)
    p = subprocess.run([seflex, "run", path, "-o", out, "--force", "--no-animation"], capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("cable sweep: %s failed (exit %d):\n%s" % (name, p.returncode, p.stderr))
    return name


def loop1_peak_tension(case):
    h = case.h
    cols = [c for c in ("cable.loop1.tension1", "cable.loop1.tension2") if c in h]
    pre = case.before_first_lock()
    return float(max(np.max(np.abs(h[c][pre])) for c in cols)) if cols else float("nan")


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("demo_out")
    ap.add_argument("--img", help="folder for solar-array-cable-sweep.png")
    ap.add_argument("--seflex", default=os.path.join(root, "build", "apps", "seflex"))
    ap.add_argument("--reuse", action="store_true", help="keep runs already in DEMO_OUT/cable-sweep/ (replot only)")
    a = ap.parse_args()
    demo = os.path.abspath(a.demo_out)
    with open(os.path.join(demo, "sync-beam.yaml")) as f:
        base = f.read()
    folder = os.path.join(demo, "cable-sweep")
    os.makedirs(folder, exist_ok=True)
    if not os.path.exists(os.path.join(folder, "superelements")):
        os.symlink(os.path.join(demo, "superelements"), os.path.join(folder, "superelements"))
    runs = [("k%g" % s, K_SEED * s, 0.0) for s in SCALES] + [("p%g" % p, K_SEED, p) for p in PRELOADS]
    todo = [r for r in runs if not (a.reuse and os.path.exists(os.path.join(folder, r[0], "summary.json")))]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(lambda r: run(a.seflex, folder, r[0], scene_text(base, r[1], r[2])), todo))

    u = psa.Case(demo, "unsync-beam").metrics()
    rows = []
    for name, k, preload in runs:
        c = psa.Case(folder, name)
        m = c.metrics()
        rows.append((k, preload, m, loop1_peak_tension(c)))
    print("Command: /usr/bin/python3 scripts/solar_array_cable_sweep.py %s" % a.demo_out)
    print("Unsynchronised (beam-like): max|phi2 - 2 phi1| %.2f deg, max|phi3 - phi2| %.2f deg\n" % (
        u["max_sync_error_21_deg"], u["max_sync_error_32_deg"]))
    print("| cable stiffness [N/m] | preload [N] | max\\|phi2 - 2 phi1\\| [deg] | unsync / sync | max\\|phi3 - phi2\\| [deg] | unsync / sync "
          "| loop 1 peak tension [N] | lock times HL1 / HL2 / HL3 [s] |")
    print("|---:|---:|---:|---:|---:|---:|---:|---|")
    for k, preload, m, tmax in rows:
        lt = m["lock_time_s"]
        print("| %.3g | %g | %.2f | %.1f | %.2f | %.0f | %.0f | %s |" % (
            k, preload, m["max_sync_error_21_deg"], u["max_sync_error_21_deg"] / m["max_sync_error_21_deg"],
            m["max_sync_error_32_deg"], u["max_sync_error_32_deg"] / m["max_sync_error_32_deg"], tmax,
            " / ".join(psa.fmt(lt[x], "%.3f") for x in psa.LINES)))

    if a.img:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7.5, 4.8))
        ks = np.array([r[0] for r in rows if r[1] == 0])
        e21 = np.array([r[2]["max_sync_error_21_deg"] for r in rows if r[1] == 0])
        e32 = np.array([r[2]["max_sync_error_32_deg"] for r in rows if r[1] == 0])
        ax.loglog(ks, e21, "o-", label="max|phi2 - 2 phi1| (loop 1)")
        ax.loglog(ks, e32, "s-", label="max|phi3 - phi2| (loop 2)")
        pre = [r for r in rows if r[1] > 0]
        ax.loglog([r[0] for r in pre], [r[2]["max_sync_error_21_deg"] for r in pre], "x", color="C3", ms=9,
                  label="loop 1, preload %s N" % "/".join("%g" % r[1] for r in pre))
        ax.axhline(u["max_sync_error_21_deg"] / 5, color="C0", ls=":", label="5x below unsync, loop 1")
        ax.axhline(u["max_sync_error_32_deg"] / 5, color="C1", ls=":", label="5x below unsync, loop 2")
        ax.axvline(K_SEED, color="gray", ls="--", lw=1)
        ax.text(K_SEED * 1.05, 0.5, "seed Table 4", color="gray", rotation=90, va="center", transform=ax.get_xaxis_transform())
        ax.set_xlabel("cable stiffness per cable [N/m]")
        ax.set_ylabel("max synchronisation error before the first lock [deg]")
        ax.set_title("Synchronised beam-like solar array: error against cable stiffness")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper right", framealpha=0.95)
        fig.tight_layout()
        os.makedirs(a.img, exist_ok=True)
        fig.savefig(os.path.join(a.img, "solar-array-cable-sweep.png"), dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
