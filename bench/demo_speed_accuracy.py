#!/usr/bin/python3
"""Speed against accuracy of the demo's 3D synchronised deployment (issue 12's 20x-real-time target).

examples/solar_array/sync-3d.yaml (yoke + two panels, 10 fixed-interface modes each, full inertia,
geometric stiffening, 71 dofs, run to 5 s after the last lock) at a grid of local-error tolerances,
largest steps and (optionally) fixed-interface modes kept per body (the scene's `internal_modes`, same
superelement files), for one or more seflex builds side by side: the builds and grid points take turns
in every round (a busy spell of the shared machine hits all of them), best and median CPU time of
the whole process (user + system, start-up included, as the issue counts it) over the rounds.
Errors against a tight reference run of the last build (all modes, local error 1e-7, the first grid
point's step limit):
  - lock time: largest |t_latch - t_latch_ref| over the hinge lines [s];
  - peak torque: largest relative difference of a hinge line's peak lock torque;
  - angle to last lock: largest hinge-line angle difference up to the reference's last lock [deg];
  - angle, whole run: the same over the whole run, 5 s of undamped lock ringing included [deg].
The superelements are reduced once, by the last build, as scripts/demo.sh reduces them.

usage: /usr/bin/python3 bench/demo_speed_accuracy.py [--repeat R] [--grid [METHOD@]TOL:MAXSTEP[:MODES],...] [--png FILE]
                                                     [--reference [METHOD@]TOL] [--quick] SEFLEX [SEFLEX ...]
  --grid   default 1e-5:2.5e-3,1e-4:2.5e-3,1e-5:5e-3,1e-4:5e-3,1e-3:5e-3 (the scene's own point first);
           METHOD: the integrator (`seflex run --method`: generalized-alpha, the scene's, or radau5);
           MODES: keep the first MODES fixed-interface modes of every body (default: all 10)
  --reference  the reference run (default generalized-alpha@1e-7; its largest step that of the first grid
           point); a second one, e.g. radau5@1e-8, is compared with it and the difference printed, so
           that the reference is shown converged by two methods agreeing
  --quick  a 0.5 s run, two grid points, one round, the reference at 1e-6: checks the script (a CTest)
"""
import argparse, json, os, re, resource, shutil, subprocess, sys, tempfile, time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib import measures, runs  # noqa: E402  (scene editing and the studies' error measures)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REAL_TIME_FACTOR = 20.0  # issue 12: at least 20x faster than real time in CPU time


def run(binary, scene, folder, method=None):
    """One `seflex run`; returns (summary, CPU seconds of the whole process)."""
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    extra = ["--method", method] if method else []
    r = subprocess.run([binary, "run", scene, "-o", folder, "--force", "--no-animation"] + extra, capture_output=True, text=True)
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        sys.exit(f"demo_speed_accuracy: {binary} run {scene} failed ({r.returncode}):\n{(r.stdout + r.stderr)[-800:]}")
    with open(os.path.join(folder, "summary.json")) as f:
        s = json.load(f)
    return s, (ru1.ru_utime + ru1.ru_stime) - (ru0.ru_utime + ru0.ru_stime)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binaries", nargs="+")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--grid", default="1e-5:2.5e-3,1e-4:2.5e-3,1e-5:5e-3,1e-4:5e-3,1e-3:5e-3")
    ap.add_argument("--png", help="also chart CPU time against the errors")
    ap.add_argument("--reference", action="append", help="[METHOD@]TOL of the reference run (default generalized-alpha@1e-7); "
                    "repeat for a second reference checked against the first")
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    grid = []
    for p in a.grid.split(","):
        method, _, p = p.rpartition("@")
        f = p.split(":")
        if len(f) not in (2, 3):
            sys.exit(f"demo_speed_accuracy: --grid point '{p}': expected [METHOD@]TOL:MAXSTEP or [METHOD@]TOL:MAXSTEP:MODES")
        grid.append((float(f[0]), float(f[1]), int(f[2]) if len(f) == 3 else None, method or None))
    refs = []
    for p in a.reference or []:
        method, _, tol = p.rpartition("@")
        refs.append((method or None, float(tol)))
    if a.quick:
        grid, a.repeat = grid[:1] + grid[3:4], 1
    bins = [os.path.abspath(b) if os.path.exists(b) else b for b in a.binaries]
    cmd = "bench/demo_speed_accuracy.py " + " ".join(sys.argv[1:])
    print(f"# {cmd}   ({time.strftime('%Y-%m-%dT%H:%MZ', time.gmtime())}, {os.cpu_count()} cores, "
          f"load {os.getloadavg()[0]:.1f})", flush=True)

    work = tempfile.mkdtemp(prefix="seflex-speed-accuracy-")
    try:
        sed = os.path.join(work, "superelements")
        os.makedirs(sed)
        for mesh, iface, name in (("yoke", "1,3,4", "yoke-3d"), ("panel", "1,2,3,4", "panel-3d")):
            subprocess.run([bins[-1], "reduce", os.path.join(ROOT, "meshes", mesh + ".bdf"), "--interface", iface,
                            "--modes", "10", "-o", os.path.join(sed, name + ".se")], check=True, capture_output=True)
        with open(os.path.join(ROOT, "examples", "solar_array", "sync-3d.yaml")) as f:
            base = f.read()
        if a.quick:
            base = runs.edit_scene(base, t_end=0.5)

        def scene(tol, max_step, name, modes=None):
            text = runs.edit_scene(base, tol=tol, max_step=max_step)
            if modes is not None:
                text, k = re.subn(r"(\n    inertia: full\n)", rf"\1    internal_modes: {modes}\n", text)
                if k != 3:
                    sys.exit("demo_speed_accuracy: could not give the scene's three bodies internal_modes")
            path = os.path.join(work, name + ".yaml")
            with open(path, "w") as f:
                f.write(text)
            return path

        if not refs:
            refs = [(None, 1e-6 if a.quick else 1e-7)]
        ref_method, ref_tol = refs[0]
        ref_folder = os.path.join(work, "reference")
        ref_summary, _ = run(bins[-1], scene(ref_tol, grid[0][1], "reference"), ref_folder, ref_method)
        print(f"reference: {bins[-1]}, {ref_method or 'the scene method'}, local error {ref_tol:g}, max_step {grid[0][1]:g}: "
              f"{ref_summary['steps']} steps", flush=True)
        for k, (m2, t2) in enumerate(refs[1:]):
            f2 = os.path.join(work, f"reference-{k + 2}")
            s2, _ = run(bins[-1], scene(t2, grid[0][1], f"reference-{k + 2}"), f2, m2)
            e2 = measures.errors_hinges(f2, s2, ref_folder, ref_summary)
            print(f"second reference: {m2 or 'the scene method'}, local error {t2:g}: {s2['steps']} steps; against the reference: "
                  f"lock time {e2.get('lock_time_err_s', float('nan')):.2g} s, peak torque {e2.get('lock_torque_rel_err', float('nan')):.2%}, "
                  f"angle to last lock {e2.get('angle_err_deg', float('nan')):.3g} deg, whole run {e2['angle_run_deg']:.3g} deg", flush=True)

        configs = [(b, *p) for b in bins for p in grid]
        cpu = {c: [] for c in configs}
        last = {}
        for _ in range(a.repeat):
            for k, c in enumerate(configs):
                folder = os.path.join(work, f"run-{k}")
                s, t = run(c[0], scene(c[1], c[2], f"scene-{k}", c[3]), folder, c[4])
                cpu[c].append(t)
                last[c] = (folder, s)

        rows = []
        for c in configs:
            b, tol, ms, modes, method = c
            folder, s = last[c]
            e = measures.errors_hinges(folder, s, ref_folder, ref_summary)
            t = sorted(cpu[c])
            rows.append(dict(bin=b, method=s.get("method", method or "?"), tol=tol, max_step=ms, modes=modes, dofs=s["dofs"], steps=s["steps"], rejected=s["rejected_steps"],
                             newton=s["newton_iterations"], simulated=s["final_t"], best=t[0], median=t[len(t) // 2], **e))
        def g(x, spec):
            return "-" if x is None or (isinstance(x, float) and not np.isfinite(x)) else format(x, spec)
        print("\n| build | method | tolerance | max_step [ms] | modes (dofs) | steps (rejected) | Newton its | simulated [s] | best CPU [s] | median [s] "
              "| x real time | lock time [s] | peak torque | angle to last lock [deg] | angle, whole run [deg] |")
        print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in rows:
            x = r["simulated"] / r["best"]
            print(f"| {r['bin']} | {r['method']} | {r['tol']:g} | {1e3 * r['max_step']:g} | {'all' if r['modes'] is None else r['modes']} ({r['dofs']}) | {r['steps']} ({r['rejected']}) | {r['newton']} | "
                  f"{r['simulated']:.2f} | {r['best']:.3f} | {r['median']:.3f} | {x:.1f}{' (>= 20x)' if x >= REAL_TIME_FACTOR else ''} | "
                  f"{g(r.get('lock_time_err_s'), '.2g')} | {g(r.get('lock_torque_rel_err'), '.2%')} | "
                  f"{g(r.get('angle_err_deg'), '.3g')} | {g(r['angle_run_deg'], '.3g')} |")
        if a.quick:
            bad = [r for r in rows if not (np.isfinite(r["angle_run_deg"]) and r["best"] > 0 and r["steps"] > 0)]
            if bad:
                sys.exit("demo_speed_accuracy --quick: a run gave no finite error or no steps")
        if a.png:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
            fig, ax = plt.subplots(1, 2, figsize=(10, 4.2))
            for key, axis, title in (("angle_err_deg", ax[0], "hinge-line angle to the last lock"),
                                     ("angle_run_deg", ax[1], "hinge-line angle, whole run (5 s of lock ringing)")):
                lines = sorted({(r["bin"], r["method"]) for r in rows})
                for b, m in lines:
                    rs = [r for r in rows if r["bin"] == b and r["method"] == m and np.isfinite(r.get(key, np.nan))]
                    axis.loglog([r["best"] for r in rs], [r[key] for r in rs], "o-" if len(lines) > 1 else "o",
                                label=f"{os.path.basename(b) if len(bins) > 1 else ''} {m}".strip() if len(lines) > 1 else None)
                    for r in rs:
                        axis.annotate(f"{r['tol']:g}, {1e3 * r['max_step']:g} ms" + ("" if r["modes"] is None else f", {r['modes']} modes"),
                                      (r["best"], r[key]), fontsize=7)
                limit = rows[0]["simulated"] / REAL_TIME_FACTOR
                axis.axvline(limit, color="gray", ls="--")
                axis.text(limit, axis.get_ylim()[1], " 20x real time", va="top", fontsize=7, color="gray")
                axis.set_xlabel("CPU time of the whole run [s]")
                axis.set_ylabel("error against local error 1e-7 [deg]")
                axis.set_title(title, fontsize=9)
                if len(lines) > 1:
                    axis.legend(fontsize=7)
            fig.text(0.01, 0.01, cmd, fontsize=6)
            fig.tight_layout(rect=(0, 0.03, 1, 1))
            fig.savefig(a.png, dpi=110)
            print(f"\nchart: {a.png}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
