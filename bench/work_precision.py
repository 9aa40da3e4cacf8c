#!/usr/bin/python3
"""Work-precision diagrams (issue 38): CPU seconds of a whole `seflex run` against its error versus a
converged reference, one line per time integrator, one point per tolerance (per step for the explicit
RK4), on four models:

  sync-3d   examples/solar_array/sync-3d.yaml (yoke + two panels, 10 fixed-interface modes each, full
            inertia, geometric stiffening, 71 dofs, to 5 s after the last lock): lock times [s], peak
            lock torques [relative], hinge-line angles to the last lock and over the whole run [deg];
  spinup    bench/study/spinup.yaml (Simo and Vu-Quoc's 10 m beam, 6 modes, 20 s): the beam's
            deflection, measured as its floating frame's lag behind the hub [deg];
  link      bench/study/link_lock.yaml (the 1 m link, 3 modes, falling 1 s, a stiff lock at -60 deg,
            docs/stability.md): lock time, peak lock torque, hinge angle to the lock and over the run;
  chain20   a chain of 20 flexible links (examples/scenes/link.bdf, 3 modes, full inertia) hanging from
            ground, released horizontally under gravity, 1 s: hinge angles over the run [deg].

Methods: Lie-group generalized-alpha at rho_inf 0.8 / 0.9 / 1.0 (its local-error tolerance, largest
step = the scene's output interval, on which its steps land), Radau IIA-5 (`--method radau5`, its
local-error tolerance; largest step 50 ms: its output comes from the collocation polynomial) and the
explicit RK4 (constant steps from just below its stability limit down). CPU: user + system time of
the whole process (start-up included), the best of --repeat runs taken in turns.
Reference: per model, a tight Radau IIA-5 run and a tight generalized-alpha run (rho_inf 0.9); the
errors are taken against the Radau one and the difference between the two is printed and drawn as a
dashed line: errors below it are not resolved by the reference.
RK4 on sync-3d and on the chain: its stability limit is below 5e-5 s (sync-3d) and 7.5e-5 s (the
chain; one link alone is stable at 3e-4 s), so a whole run costs hundreds of CPU seconds; the script
runs it a short time at a stable step, reports the cost extrapolated to the whole run, and shows that
the larger step blows up.

usage: /usr/bin/python3 bench/work_precision.py [--bin build/apps/seflex] [--out work-precision-output]
           [--img docs/img] [--cases sync-3d,spinup,link,chain20] [--repeat 2] [--replot] [--quick]
  --img    also copy the charts work-precision-CASE.png there
  --replot redraw the charts and the tables from OUT/work-precision.json
  --quick  the link model only, 0.2 s, two points per method, one round (a CTest: checks the script)
"""
import argparse, json, os, re, resource, shutil, subprocess, sys, time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib import measures  # noqa: E402
from lib.runs import edit_scene, save_figure  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RADAU_MAX_STEP = 0.05

HINGE_MEASURES = [("lock_time_err_s", "lock time [s]"), ("lock_torque_rel_err", "peak lock torque [relative]"),
                  ("angle_err_deg", "hinge angle to the last lock [deg]"), ("angle_run_deg", "hinge angle, whole run [deg]")]
CASES = {
    "sync-3d": dict(measures=HINGE_MEASURES, ga_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8], radau_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7],
                    rk4_steps=[], rk4_probe=(2e-5, 5e-5, 0.2), ref_tol=1e-8),
    "spinup": dict(measures=[("angle_err_deg", "deflection (frame lag behind the hub) [deg]")],
                   ga_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9], radau_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8],
                   rk4_steps=[3.2e-3, 1.6e-3, 8e-4, 4e-4, 2e-4], ref_tol=1e-9),
    "link": dict(measures=HINGE_MEASURES, ga_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9], radau_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8],
                 rk4_steps=[3e-4, 1.5e-4, 7.5e-5, 3.75e-5], ref_tol=1e-9),
    "chain20": dict(measures=[("angle_run_deg", "hinge angles, whole run [deg]")], ga_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8],
                    radau_tols=[1e-3, 1e-4, 1e-5, 1e-6, 1e-7], rk4_steps=[], rk4_probe=(3e-5, 7.5e-5, 0.05), ref_tol=1e-8),
}
METHODS = [("generalized-alpha, rho_inf 0.8", "ga", 0.8), ("generalized-alpha, rho_inf 0.9", "ga", 0.9),
           ("generalized-alpha, rho_inf 1.0", "ga", 1.0), ("Radau IIA-5", "radau5", None), ("RK4 (explicit)", "rk4", None),
           ("the demo as published (generalized-alpha, rho_inf 0.9, 1e-5, max_step 2.5 ms)", "published", None)]


def chain_scene(n):
    """n links of examples/scenes/link.bdf (1 m, hinged at grids 1 and 5) in a row along x, released."""
    lines = [f"# {n} flexible links hanging from ground, released horizontally (bench/work_precision.py)",
             f"title: chain of {n} flexible links", "bodies:"]
    lines += [f"  - {{name: L{k}, superelement: link.se, inertia: full, placement: {{position: [{k - 1}, 0, 0]}}}}" for k in range(1, n + 1)]
    lines += ["hinges:", "  - {name: H1, parent: ground, child: L1.1, axis: [0, 0, 1]}"]
    lines += [f"  - {{name: H{k}, parent: L{k - 1}.5, child: L{k}.1, axis: [0, 0, 1]}}" for k in range(2, n + 1)]
    lines += ["loads:", "  gravity: [0, -9.81, 0]",
              "integrator: {rho_inf: 0.9, t_end: 1.0, step: 1.0e-4, max_step: 1.0e-2, tolerance: {position: 1.0e-5, angle: 1.0e-5}}",
              "output: {interval: 0.01}"]
    return "\n".join(lines) + "\n"


def prepare(case, b, work, quick):
    """Scene text and the folder its superelements are in."""
    d = os.path.join(work, case)
    os.makedirs(d, exist_ok=True)

    def reduce(deck, iface, modes, se, extra=()):
        subprocess.run([b, "reduce", deck, "--interface", iface, "--modes", str(modes), "-o", os.path.join(d, se), "--force", *extra],
                       check=True, capture_output=True)
    if case == "sync-3d":
        os.makedirs(os.path.join(d, "superelements"), exist_ok=True)
        for mesh, iface, name in (("yoke", "1,3,4", "yoke-3d"), ("panel", "1,2,3,4", "panel-3d")):
            reduce(os.path.join(ROOT, "meshes", mesh + ".bdf"), iface, 10, os.path.join("superelements", name + ".se"))
        text = open(os.path.join(ROOT, "examples", "solar_array", "sync-3d.yaml")).read()
    elif case == "spinup":
        reduce(os.path.join(ROOT, "bench", "study", "spinup_beam.bdf"), "1,11", 6, "spinup_beam.se")
        text = open(os.path.join(ROOT, "bench", "study", "spinup.yaml")).read()
    elif case == "link":
        reduce(os.path.join(ROOT, "examples", "scenes", "link.bdf"), "1,5", 3, "link.se")
        text = open(os.path.join(ROOT, "bench", "study", "link_lock.yaml")).read()
        text = text.replace("integrator: {rho_inf: 0.8,", "integrator: {rho_inf: 0.8, max_step: 1.0e-2, tolerance: {position: 1.0e-5, angle: 1.0e-5},")
    else:
        reduce(os.path.join(ROOT, "examples", "scenes", "link.bdf"), "1,5", 3, "link.se")
        text = chain_scene(20)
    if quick:
        text = edit_scene(text, t_end=0.2)
    return text, d


def scene_for(text, rho=None, max_step=None):
    if rho is not None:
        text, k = re.subn(r"rho_inf: [0-9.eE+-]+", f"rho_inf: {rho:g}", text, count=1)
        if not k:
            raise SystemExit("work_precision: the scene has no rho_inf to change")
    if max_step is not None:
        text = edit_scene(text, max_step=max_step)
    return text


def run(b, text, d, name, extra, timeout):
    scene = os.path.join(d, name + ".yaml")
    with open(scene, "w") as f:
        f.write(text)
    folder = os.path.join(d, "runs", name)
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        r = subprocess.run([b, "run", scene, "-o", folder, "--force", "--no-animation", *extra], capture_output=True, text=True, timeout=timeout)
        code, out = r.returncode, r.stdout + r.stderr
    except subprocess.TimeoutExpired:
        code, out = None, f"stopped after {timeout:g} s"
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (ru1.ru_utime + ru1.ru_stime) - (ru0.ru_utime + ru0.ru_stime)
    path = os.path.join(folder, "summary.json")
    s = json.load(open(path)) if code is not None and os.path.exists(path) else dict(status="timeout", locks={})
    if code not in (0, None) and s.get("status") == "ok":
        s["status"] = f"exit {code}"
    s["output_tail"] = out[-300:]
    return folder, s, cpu


def measure_scales(case, ref_folder, ref_s):
    """The size of each measure in the reference run, for "1 % of its measure": the last lock's time, 1 for
    relative torques, the largest hinge-line angle (the frame lag for the spin-up beam)."""
    if case == "spinup":
        return dict(angle_err_deg=float(np.max(np.abs(measures.spinup_lag(ref_folder)[1]))))
    L = measures.lines_of(measures.read_history(os.path.join(ref_folder, "history.csv")))
    angle = max(float(np.max(np.abs(v))) for v in L.values())
    latched = [l["t_latch"] for l in ref_s["locks"].values() if l["t_latch"] is not None]
    return dict(lock_time_err_s=max(latched) if latched else None, lock_torque_rel_err=1.0, angle_err_deg=angle, angle_run_deg=angle)


def cheapest(rows, key, level):
    """The cheapest run of rows whose error is at most level: (CPU, row) or (None, None)."""
    ok = [r for r in rows if r["status"] == "ok" and np.isfinite(r.get(key, np.nan)) and r[key] <= level]
    r = min(ok, key=lambda r: r["cpu"], default=None)
    return (r["cpu"], r) if r else (None, None)


def case_errors(case, folder, s, ref_folder, ref_s):
    if case == "spinup":
        r = dict(folder=folder, status=s["status"])
        return measures.errors_spinup(r, measures.spinup_lag(ref_folder))
    return measures.errors_hinges(folder, s, ref_folder, ref_s)


def study(case, a, work):
    c = CASES[case]
    text, d = prepare(case, a.bin, work, a.quick)
    ga_cap = 5e-3 if case == "sync-3d" else None  # the output interval (5 ms; the others' scenes have it already)
    ref_tol = 1e-7 if a.quick else c["ref_tol"]
    # References: Radau IIA-5 tight (the errors' reference) and generalized-alpha tight (the check).
    ref_folder, ref_s, ref_cpu = run(a.bin, scene_for(text, max_step=RADAU_MAX_STEP), d, "reference-radau5",
                                     ["--method", "radau5", "--tolerance", f"{ref_tol:g}"], a.timeout * 4)
    if ref_s["status"] != "ok":
        sys.exit(f"work_precision: the {case} reference run failed: {ref_s.get('message', '')}\n{ref_s['output_tail']}")
    chk_folder, chk_s, chk_cpu = run(a.bin, scene_for(text, rho=0.9), d, "reference-ga",
                                     ["--method", "generalized-alpha", "--tolerance", f"{ref_tol:g}"],
                                     a.timeout * 4)
    agree = case_errors(case, chk_folder, chk_s, ref_folder, ref_s) if chk_s["status"] == "ok" else {}
    ref = dict(scales=measure_scales(case, ref_folder, ref_s), radau_tol=ref_tol, radau_steps=ref_s["steps"], radau_cpu=ref_cpu,
               ga_tol=ref_tol, ga_status=chk_s["status"], ga_steps=chk_s.get("steps"),
               ga_cpu=chk_cpu, agreement=agree)

    points = []
    for label, kind, rho in METHODS:
        if kind == "ga":
            for tol in (c["ga_tols"][1:3] if a.quick else c["ga_tols"]):
                points.append((label, kind, tol, scene_for(text, rho=rho, max_step=ga_cap), ["--method", "generalized-alpha", "--tolerance", f"{tol:g}"]))
        elif kind == "radau5":
            for tol in (c["radau_tols"][1:3] if a.quick else c["radau_tols"]):
                points.append((label, kind, tol, scene_for(text, max_step=RADAU_MAX_STEP), ["--method", "radau5", "--tolerance", f"{tol:g}"]))
        elif kind == "published":
            if case == "sync-3d" and not a.quick:
                points.append((label, kind, 1e-5, text, []))
        else:
            for h in (c["rk4_steps"][:2] if a.quick else c["rk4_steps"]):
                points.append((label, kind, h, text, ["--method", "rk4", "--step", f"{h:g}"]))
    cpu = {k: [] for k in range(len(points))}
    last = {}
    for _ in range(a.repeat):
        for k, (label, kind, x, t, extra) in enumerate(points):
            if k in last and last[k][1]["status"] != "ok":
                continue  # a failed point is not repeated
            folder, s, t_cpu = run(a.bin, t, d, f"p{k}", extra, a.timeout)
            cpu[k].append(t_cpu)
            last[k] = (folder, s)
    rows = []
    for k, (label, kind, x, t, extra) in enumerate(points):
        folder, s = last[k]
        row = dict(case=case, method=label, kind=kind, knob=x, status=s["status"], message=s.get("message", ""),
                   steps=s.get("steps"), rejected=s.get("rejected_steps"), cpu=min(cpu[k]))
        if s["status"] == "ok":
            row.update(case_errors(case, folder, s, ref_folder, ref_s))
        rows.append(row)
    extra = {}
    if "rk4_probe" in c and not a.quick:
        stable, unstable, probe = c["rk4_probe"]
        folder, s, t_cpu = run(a.bin, edit_scene(text, t_end=probe), d, "rk4-probe", ["--method", "rk4", "--step", f"{stable:g}"], a.timeout)
        extra = dict(rk4_probe=dict(step=stable, t_end=probe, status=s["status"], cpu=t_cpu, whole_run_s=ref_s["final_t"],
                                    whole_run_cpu_estimate=t_cpu / probe * ref_s["final_t"], unstable_step=unstable))
        folder, s, _ = run(a.bin, edit_scene(text, t_end=probe), d, "rk4-probe-unstable", ["--method", "rk4", "--step", f"{unstable:g}"], a.timeout)
        extra["rk4_probe"]["status_at_unstable_step"] = s["status"] + ": " + s.get("message", "")[:90]
    return dict(case=case, reference=ref, rows=rows, **extra)


def fmt(x, spec):
    return "-" if x is None or (isinstance(x, float) and not np.isfinite(x)) else format(x, spec)


def report(results, out, img, cmd):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for res in results:
        case, ref, rows = res["case"], res["reference"], res["rows"]
        ms = CASES[case]["measures"]
        ag = ref["agreement"]
        print(f"\n## {case}\nreference: Radau IIA-5 at local error {ref['radau_tol']:g} ({ref['radau_steps']} steps, {ref['radau_cpu']:.2f} s CPU); "
              f"check: generalized-alpha rho_inf 0.9 at {ref['ga_tol']:g} ({ref['ga_status']}, {ref['ga_steps']} steps, {ref['ga_cpu']:.2f} s); "
              "the two differ by " + ", ".join(f"{n} {fmt(ag.get(k), '.2g')}" for k, n in ms))
        if "rk4_probe" in res:
            p = res["rk4_probe"]
            print(f"RK4: at a {p['unstable_step']:g} s step, {p['status_at_unstable_step']}; at {p['step']:g} s ({p['status']}), "
                  f"{p['cpu']:.1f} s CPU for {p['t_end']:g} s: a whole run of {p['whole_run_s']:.1f} s would cost about "
                  f"{p['whole_run_cpu_estimate']:.0f} s CPU (not run)")
        print("\n| method | tolerance / step | steps (rejected) | CPU [s] | " + " | ".join(n for _, n in ms) + " |")
        print("|---|---:|---:|---:|" + "---:|" * len(ms))
        for r in rows:
            knob = f"h = {r['knob']:g} s" if r["kind"] == "rk4" else f"{r['knob']:g}"
            if r["status"] != "ok":
                print(f"| {r['method']} | {knob} | - | {r['cpu']:.3f} | {r['status']}: {r['message'][:80]} |" + " |" * (len(ms) - 1))
                continue
            print(f"| {r['method']} | {knob} | {r['steps']} ({r['rejected']}) | {r['cpu']:.3f} | "
                  + " | ".join(fmt(r.get(k), ".2%" if "rel" in k else ".2g") for k, _ in ms) + " |")
        # The issue's comparison: at each error level below 1 % of the measure, the cheapest run of any
        # method against the cheapest generalized-alpha run reaching it (no interpolation between runs).
        print("\n| measure | error level | cheapest generalized-alpha [s] | cheapest of all [s] (method, tolerance / step) | ratio |")
        print("|---|---:|---:|---:|---:|")
        for key, name in ms:
            scale = ref["scales"].get(key)
            if not scale:
                continue
            for k in range(2, 9):
                level = scale * 10.0 ** -k
                ga, _ = cheapest([r for r in rows if r["kind"] in ("ga", "published")], key, level)
                best, rb = cheapest(rows, key, level)
                if best is None:
                    break
                print(f"| {name} | {level:.2g} ({10.0 ** -k:.0e} of {scale:.3g}) | {fmt(ga, '.3f')} | {best:.3f} ({rb['method']}, {rb['knob']:g}) | "
                      f"{fmt(best / ga if ga else None, '.2f')}{'' if ga else ' (generalized-alpha does not reach it)'} |")
        n = len(ms)
        cols = min(n, 2)
        fig, axes = plt.subplots((n + cols - 1) // cols, cols, figsize=(5.2 * cols, 4.0 * ((n + cols - 1) // cols) + 0.6), squeeze=False)
        for (key, name), ax in zip(ms, axes.flat):
            for label, kind, rho in METHODS:
                rs = [r for r in rows if r["method"] == label and r["status"] == "ok" and np.isfinite(r.get(key, np.nan)) and r[key] > 0]
                if not rs:
                    continue
                line, = ax.loglog([r["cpu"] for r in rs], [r[key] for r in rs], {"rk4": "s--", "published": "k*"}.get(kind, "o-"), label=label, ms=4)
                for r in rs:
                    ax.annotate(f"{r['knob']:g}", (r["cpu"], r[key]), fontsize=6, color=line.get_color())
            if ag.get(key):
                ax.axhline(ag[key], color="gray", ls=":", lw=1)
                ax.text(ax.get_xlim()[0], ag[key], " references agree to here", fontsize=6, color="gray", va="bottom")
            ax.set_xlabel("CPU time of the whole run [s]")
            ax.set_ylabel("error " + name)
            ax.set_title(f"{case}: {name}", fontsize=9)
            ax.grid(True, which="both", lw=0.3)
        seen = {}
        for ax in axes.flat:
            for h, l in zip(*ax.get_legend_handles_labels()):
                seen.setdefault(l, h)
        rows_of_legend = (len(seen) + 2) // 3
        bottom = (0.1 + 0.16 * rows_of_legend) / fig.get_size_inches()[1]
        fig.legend(list(seen.values()), list(seen.keys()), loc="lower center", ncol=3, fontsize=7, bbox_to_anchor=(0.5, 0.1 / fig.get_size_inches()[1]))
        png = save_figure(fig, out, f"work-precision-{case}.png", img, cmd, bottom=bottom)
        plt.close(fig)
        print(f"\nchart: {png}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "apps", "seflex"))
    ap.add_argument("--out", default="work-precision-output")
    ap.add_argument("--img")
    ap.add_argument("--cases", default="sync-3d,spinup,link,chain20")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--replot", action="store_true")
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    a.bin = os.path.abspath(a.bin)
    cmd = "bench/work_precision.py " + " ".join(sys.argv[1:])
    os.makedirs(a.out, exist_ok=True)
    data = os.path.join(a.out, "work-precision.json")
    if a.replot:
        report(json.load(open(data))["results"], a.out, a.img, cmd)
        return
    if a.quick:
        a.cases, a.repeat = "link", 1
    cases = a.cases.split(",")
    for c in cases:
        if c not in CASES:
            sys.exit(f"work_precision: unknown case '{c}' (expected one of {', '.join(CASES)})")
    print(f"# {cmd}   ({time.strftime('%Y-%m-%dT%H:%MZ', time.gmtime())}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f})", flush=True)
    work = os.path.join(a.out, "work")
    results = []
    for c in cases:
        results.append(study(c, a, work))
        json.dump(dict(command=cmd, results=results), open(data, "w"), indent=1)
    report(results, a.out, a.img, cmd)
    if a.quick:
        bad = [r for r in results[0]["rows"] if r["kind"] != "rk4" and not (r["status"] == "ok" and np.isfinite(r.get("angle_run_deg", np.nan)))]
        if bad:
            sys.exit(f"work_precision --quick: {len(bad)} implicit runs gave no finite error: {bad[0]}")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
