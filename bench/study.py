#!/usr/bin/python3
"""Speed against accuracy (issue 7): a grid of seflex runs, each timed (CPU time: summary.json
cpu_time_s, the process's CPU time from building the scene to the last output, i.e. without the
program's start-up (~0.15 s of library loading); a seflex without it: getrusage of the whole
process; the wall time of the same span, run_time_s, is kept as wall_s) and
compared with a converged reference, written to a CSV and charted (log-log error against CPU time,
one curve per formulation, Pareto front).

  /usr/bin/python3 bench/study.py [--quick] [--bin build/apps/seflex] [--out study-output] [--no-solar]

Cases and formulations:
  spin-up beam (bench/study/spinup.yaml, Simo and Vu-Quoc): AIC full inertia (local error 1e-4..1e-6),
    AIC simplified mass, rigid (0 dofs: the prescribed motion), RK4 (explicit, constant steps); error:
    max |lag - lag_ref| of the beam's floating frame behind the hub [deg] (the deflection; rigid and
    rigid-LM: the whole lag).
  solar array, sync and unsync (examples/solar_array, superelements reduced as scripts/demo.sh does):
    AIC full inertia and simplified mass on the 3D and beam-like reductions (local error 1e-4, 1e-5),
    rigid (beam-like; 3D with each line's second hinge a follower, docs/scenes.md); errors: max
    hinge-line angle difference up to the reference's last lock [deg], largest
    lock-time difference [s], largest relative peak lock-torque difference.
  FFRF-LM (seflex run --formulation ffrf-lm; spin-up: local error 1e-4..1e-7; arrays: 3D 1e-4..1e-6 and
    beam-like 1e-4) and rigid-LM (spin-up 1e-6; arrays: beam-like 1e-4 and 1e-5, 3D 1e-5 with its redundant
    equations removed, docs/ffrf.md) are included when the binary offers them
    (otherwise skipped, and said so). A run longer than --timeout (300 s) is stopped: status timeout.
Reference: the finest AIC full-inertia run (3D, local error 1e-6); cross-checked against the finest
FFRF-LM run when there is one (printed as a note: its errors, and FFRF-LM's next run against it). --quick: the spin-up beam only, 3 s, four runs (a CTest).
Geometric stiffening (bench/stiffening_study.py, not with --quick or --no-stiffening-study): the spin-up beam as 1..10
superelements with and without stiffening against the independent corotational reference, at 6 and 12 rad/s.
"""
import argparse, csv, json, os, re, resource, shutil, subprocess, sys, time
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib.runs import edit_scene, save_figure, sh  # noqa: E402
from lib.measures import errors_solar, errors_spinup, spinup_lag  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Study:
    def __init__(self, args):
        self.bin, self.out, self.rows, self.timeout = args.bin, args.out, [], args.timeout
        code, text = sh([self.bin, "run", "--help"])
        self.formulations = re.findall(r"--formulation ([a-z0-9|-]+)", text)
        self.has_ffrf = bool(self.formulations) and "ffrf-lm" in self.formulations[0]
        self.notes = []

    def run(self, case, formulation, variant, scene_text, scene_dir, extra=()):
        name = re.sub(r"[^a-z0-9]+", "-", f"{case} {formulation} {variant}".lower()).strip("-")
        scene = os.path.join(scene_dir, name + ".yaml")
        with open(scene, "w") as f:
            f.write(scene_text)
        folder = os.path.join(self.out, "runs", name)
        if os.path.exists(os.path.join(folder, "summary.json")):
            os.remove(os.path.join(folder, "summary.json"))
        ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        code, text = sh([self.bin, "run", scene, "-o", folder, "--force", "--no-animation", *extra], self.timeout)
        ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)  # CPU time of the seflex process (a killed one is not counted)
        cpu = (ru1.ru_utime + ru1.ru_stime) - (ru0.ru_utime + ru0.ru_stime)
        s = json.load(open(os.path.join(folder, "summary.json"))) if code is not None and os.path.exists(os.path.join(folder, "summary.json")) else {}
        if code is None:
            s = dict(status="timeout", message=text, run_time_s=self.timeout)
        r = dict(case=case, formulation=formulation, variant=variant, folder=folder, status=s.get("status", "failed"),
                 cpu_s=s.get("cpu_time_s", cpu) if code is not None else self.timeout, wall_s=s.get("run_time_s", float("nan")), steps=s.get("steps", 0), dofs=s.get("dofs", 0),
                 locks=s.get("locks", {}), message=(s.get("message") or ("" if code == 0 else text.strip()[-300:])))
        self.rows.append(r)
        print(f"  {case:8s} {formulation:16s} {variant:22s} {r['status']:6s} {r['cpu_s']:8.3f} s  {r['steps']:6d} steps", flush=True)
        return r


def pareto(points):
    """Indices of the points no other point beats in both cost and error."""
    idx = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], np.inf
    for i in idx:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def write_markdown(rows, path):
    """The table of docs/speed-vs-accuracy.md: one line per case, formulation and reduction (3D/beam),
    the variants (tolerances, steps) joined by ' / '."""
    def fmt(x, spec):
        return "" if x is None or (isinstance(x, float) and np.isnan(x)) else ("inf" if x == np.inf else format(x, spec))
    groups = {}
    for r in rows:
        kind = r["variant"].split()[0] if r["variant"].split()[0] in ("3D", "beam") else ""
        groups.setdefault((r["case"], r["formulation"], kind), []).append(r)
    with open(path, "w") as f:
        f.write("| case | formulation | variant | CPU [s] | angle error [deg] | lock-time error [s] | peak-torque error |\n|---|---|---|---|---|---|---|\n")
        for (case, fm, kind), rs in groups.items():
            ok = [r for r in rs if r["status"] == "ok"]
            bad = [r for r in rs if r["status"] != "ok"]
            variant = (kind + " " if kind else "") + " / ".join(r["variant"].replace(kind, "").strip() for r in rs)
            cols = [" / ".join(fmt(r.get(k, np.nan), spec) for r in ok).strip(" /") for k, spec in
                    (("cpu_s", ".3g"), ("angle_err_deg", ".3g"), ("lock_time_err_s", ".2g"), ("lock_torque_rel_err", ".2%"))]
            if bad:
                cols[1] += ("; " if ok else "") + "; ".join(f"{r['variant']}: {r['status']} ({r['message'][:80]})" for r in bad)
            f.write(f"| {case} | {fm} | {variant} | " + " | ".join(cols) + " |\n")
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "apps", "seflex"))
    ap.add_argument("--out", default="study-output")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-solar", action="store_true")
    ap.add_argument("--no-stiffening-study", action="store_true", help="skip bench/stiffening_study.py")
    ap.add_argument("--img", default=None, help="also copy the charts here (e.g. docs/img)")
    ap.add_argument("--timeout", type=float, default=300.0, help="stop a run after this many seconds (status timeout)")
    a = ap.parse_args()
    a.bin = os.path.abspath(a.bin)
    if not os.access(a.bin, os.X_OK):
        sys.exit(f"study: no seflex binary at {a.bin} (build the target seflex or pass --bin)")
    os.makedirs(os.path.join(a.out, "runs"), exist_ok=True)
    st = Study(a)
    cmd = "/usr/bin/python3 bench/study.py " + " ".join(sys.argv[1:])
    print(f"seflex study, {time.strftime('%Y-%m-%d')}: {cmd}")
    if not st.has_ffrf:
        st.notes.append("FFRF-LM: skipped (this seflex has no `run --formulation ffrf-lm`)")
        print("  " + st.notes[-1])

    # Spin-up beam.
    sd = os.path.join(a.out, "spinup")
    os.makedirs(sd, exist_ok=True)
    for f in ("spinup_beam.bdf", "spinup.yaml"):
        shutil.copy(os.path.join(ROOT, "bench", "study", f), sd)
    code, text = sh([a.bin, "reduce", os.path.join(sd, "spinup_beam.bdf"), "--interface", "1,11", "--modes", "6", "-o", os.path.join(sd, "spinup_beam.se"), "--force"])
    if code:
        sys.exit("study: seflex reduce failed:\n" + text)
    base = open(os.path.join(sd, "spinup.yaml")).read()
    if a.quick:
        base = edit_scene(base, t_end=3.0)
    tols = [1e-7, 1e-5] if a.quick else [1e-7, 1e-6, 1e-5, 1e-4]
    runs = []
    for tol in tols:
        runs.append(st.run("spinup", "AIC full", f"tol {tol:g}", edit_scene(base, tol=tol), sd, ["--inertia", "full"]))
    ref = runs[0]
    for tol in ([1e-5] if a.quick else [1e-6, 1e-5, 1e-4]):
        st.run("spinup", "AIC simplified", f"tol {tol:g}", edit_scene(base, tol=tol), sd, ["--inertia", "simplified"])
    if not a.quick:
        for h in (2e-3, 1e-3, 5e-4):
            st.run("spinup", "RK4", f"h {h:g}", edit_scene(base, method="rk4", step=h), sd, ["--inertia", "full"])
        st.run("spinup", "rigid", "tol 1e-6", edit_scene(base, tol=1e-6), sd, ["--fidelity", "rigid"])
        if st.has_ffrf:
            for tol in (1e-7, 1e-6, 1e-5, 1e-4):
                st.run("spinup", "FFRF-LM", f"tol {tol:g}", edit_scene(base, tol=tol), sd, ["--formulation", "ffrf-lm"])
            st.run("spinup", "rigid-LM", "tol 1e-6", edit_scene(base, tol=1e-6), sd, ["--formulation", "rigid-lm"])
    if ref["status"] != "ok":
        sys.exit("study: the spin-up reference run failed: " + ref["message"])
    lag_ref = spinup_lag(ref["folder"])
    for r in st.rows:
        if r["case"] == "spinup":
            r.update(errors_spinup(r, lag_ref))

    # Superelements per beam with and without geometric stiffening (its own CSV, table and chart).
    if a.quick or a.no_stiffening_study:
        st.notes.append("stiffening study: skipped (" + ("--quick" if a.quick else "--no-stiffening-study") + ")")
    else:
        # Its own script, run as a program (the scripts never import each other).
        print("stiffening study (bench/stiffening_study.py):", flush=True)
        extra = ["--img", a.img] if a.img else []
        r = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "stiffening_study.py"), "--bin", a.bin, "--out", a.out,
                            "--timeout", f"{a.timeout:g}", *extra])
        if r.returncode:
            sys.exit(f"study: bench/stiffening_study.py failed ({r.returncode})")

    # Solar array (the demo's scenes and reductions).
    have_solar = os.path.exists(os.path.join(ROOT, "examples", "solar_array", "sync-3d.yaml"))
    if a.quick or a.no_solar or not have_solar:
        st.notes.append("solar array: skipped (" + ("--quick" if a.quick else "--no-solar" if a.no_solar else "examples/solar_array/ not found") + ")")
        print("  " + st.notes[-1])
    else:
        od = os.path.join(a.out, "solar")
        os.makedirs(os.path.join(od, "superelements"), exist_ok=True)
        for body, iface, tag in (("yoke", "1,5", "beam"), ("panel", "5,6", "beam"), ("yoke", "1,3,4", "3d"), ("panel", "1,2,3,4", "3d")):
            se = os.path.join(od, "superelements", f"{body}-{tag}.se")
            if not os.path.exists(se):
                code, text = sh([a.bin, "reduce", os.path.join(ROOT, "meshes", body + ".bdf"), "--interface", iface, "--modes", "10", "--name", f"{body}-{tag}", "-o", se, "--force"])
                if code:
                    sys.exit("study: seflex reduce failed:\n" + text)
        for case in ("unsync", "sync"):
            sc = {k: edit_scene(open(os.path.join(ROOT, "examples", "solar_array", f"{case}-{k}.yaml")).read(), stop=0.3) for k in ("3d", "beam")}
            ref_r = st.run(case, "AIC full", "3D tol 1e-6", edit_scene(sc["3d"], tol=1e-6), od, ["--inertia", "full"])
            st.run(case, "AIC full", "3D tol 1e-4", edit_scene(sc["3d"], tol=1e-4), od, ["--inertia", "full"])
            st.run(case, "AIC full", "beam tol 1e-5", edit_scene(sc["beam"], tol=1e-5), od, ["--inertia", "full"])
            st.run(case, "AIC full", "beam tol 1e-4", edit_scene(sc["beam"], tol=1e-4), od, ["--inertia", "full"])
            st.run(case, "AIC simplified", "3D tol 1e-5", edit_scene(sc["3d"], tol=1e-5), od, ["--inertia", "simplified"])
            st.run(case, "AIC simplified", "beam tol 1e-4", edit_scene(sc["beam"], tol=1e-4), od, ["--inertia", "simplified"])
            st.run(case, "rigid", "tol 1e-5", edit_scene(sc["beam"], tol=1e-5), od, ["--fidelity", "rigid"])
            st.run(case, "rigid", "tol 1e-4", edit_scene(sc["beam"], tol=1e-4), od, ["--fidelity", "rigid"])
            # 3D: each hinge line two coaxial hinges on a rigid panel, the second one a follower (docs/scenes.md)
            st.run(case, "rigid", "3D tol 1e-5", edit_scene(sc["3d"], tol=1e-5), od, ["--fidelity", "rigid"])
            if st.has_ffrf:
                for tol in (1e-6, 1e-5, 1e-4):
                    st.run(case, "FFRF-LM", f"3D tol {tol:g}", edit_scene(sc["3d"], tol=tol), od, ["--formulation", "ffrf-lm"])
                st.run(case, "FFRF-LM", "beam tol 1e-4", edit_scene(sc["beam"], tol=1e-4), od, ["--formulation", "ffrf-lm"])
                for tol in (1e-5, 1e-4):
                    st.run(case, "rigid-LM", f"tol {tol:g}", edit_scene(sc["beam"], tol=tol), od, ["--formulation", "rigid-lm"])
                # 3D: 10 redundant equations removed (docs/ffrf.md, "Redundant constraints")
                st.run(case, "rigid-LM", "3D tol 1e-5", edit_scene(sc["3d"], tol=1e-5), od, ["--formulation", "rigid-lm"])
            if ref_r["status"] != "ok":
                sys.exit(f"study: the {case} reference run failed: " + ref_r["message"])
            for r in st.rows:
                if r["case"] == case:
                    r.update(errors_solar(r, ref_r))

    # Cross-check of each reference against the finest FFRF-LM run that finished (its error row) and
    # the self-convergence of FFRF-LM (finest against the next finest, same error measure).
    for c in ("spinup", "unsync", "sync"):
        ff = [r for r in st.rows if r["case"] == c and r["formulation"] == "FFRF-LM" and r["status"] == "ok" and "beam" not in r["variant"]]
        if len(ff) >= 1:
            note = f"cross-check {c}: AIC reference against the finest FFRF-LM run ({ff[0]['variant']}): angle {ff[0]['angle_err_deg']:.3g} deg"
            if c != "spinup":
                note += f", lock time {ff[0]['lock_time_err_s']:.3g} s, peak torque {ff[0]['lock_torque_rel_err']:.3g}"
            if len(ff) >= 2:
                e = (errors_spinup(ff[1], spinup_lag(ff[0]["folder"])) if c == "spinup" else errors_solar(ff[1], ff[0]))
                note += f"; FFRF-LM {ff[1]['variant']} against its finest run: {e['angle_err_deg']:.3g} deg"
            st.notes.append(note)

    # CSV and charts.
    fields = ["case", "formulation", "variant", "status", "cpu_s", "wall_s", "steps", "dofs", "angle_err_deg", "lock_time_err_s", "lock_torque_rel_err", "message"]
    with open(os.path.join(a.out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for r in st.rows:
            w.writerow(r)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [c for c in ("spinup", "unsync", "sync") if any(r["case"] == c for r in st.rows)]
    titles = {"spinup": "spin-up beam: frame lag error [deg]", "unsync": "unsynchronised array: hinge-angle error [deg]",
              "sync": "synchronised array: hinge-angle error [deg]"}
    colors = {"AIC full": "C0", "AIC simplified": "C1", "rigid": "C2", "FFRF-LM": "C3", "rigid-LM": "C4", "RK4": "C5"}
    ylabels = {"spinup": "max error of the frame lag [deg]", "unsync": "max hinge-angle error [deg]", "sync": "max hinge-angle error [deg]"}
    fig, axes = plt.subplots(1, len(cases), figsize=(5.6 * len(cases), 4.8), squeeze=False)
    for ax, c in zip(axes[0], cases):
        rows = [r for r in st.rows if r["case"] == c and r is not None]
        floor, n_bad = 1e-6, 0
        for fm in dict.fromkeys(r["formulation"] for r in rows):
            pts = sorted((r["cpu_s"], max(r.get("angle_err_deg", np.inf), floor), r["variant"]) for r in rows
                         if r["formulation"] == fm and r["status"] == "ok" and r.get("angle_err_deg", 0) > 0)
            if pts:
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", color=colors.get(fm), label=fm)
                for p in pts:
                    ax.annotate(p[2], (p[0], p[1]), fontsize=6, alpha=0.7)
            bad = [r for r in rows if r["formulation"] == fm and r["status"] != "ok"]
            if bad:  # one line per formulation: which runs failed and when
                ts = [float(m.group(1)) for r in bad for m in [re.search(r"stopped at t = ([0-9.eE+-]+) s", r["message"])] if m]
                when = f" at t = {min(ts):.3g}-{max(ts):.3g} s" if ts else ""
                ax.annotate(f"{fm} ({', '.join(r['variant'] for r in bad)}): {bad[0]['status']}{when}", (0.02, 0.02 + 0.05 * n_bad),
                            xycoords="axes fraction", fontsize=6, color="red")
                n_bad += 1
        ok = [(r["cpu_s"], r["angle_err_deg"]) for r in rows if r["status"] == "ok" and 0 < r.get("angle_err_deg", 0) < np.inf]
        front = pareto(ok)
        if front:
            ax.loglog([ok[i][0] for i in front], [ok[i][1] for i in front], "k--", lw=0.8, label="Pareto front")
        ref_cpu = rows[0]["cpu_s"] if rows and rows[0].get("angle_err_deg") == 0.0 else None
        if ref_cpu:  # the reference itself (error 0 by definition) cannot sit on a log axis: its cost as a line
            ax.axvline(ref_cpu, color="k", ls=":", lw=0.8, label=f"AIC reference ({rows[0]['variant']}), error 0")
        ax.set_xlabel("CPU time of the run [s]")
        ax.set_ylabel(ylabels[c])
        ax.set_title(titles[c], fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    # docs/img/speed-vs-accuracy.png charts all three cases: a run without the arrays does not replace it.
    full = all(c in cases for c in ("spinup", "unsync", "sync"))
    if a.img and not full:
        st.notes.append(f"speed-vs-accuracy.png not copied to {a.img} (the solar cases did not run)")
    png = save_figure(fig, a.out, "speed-vs-accuracy.png", a.img if full else None, cmd)
    print(f"\n{'case':8s} {'formulation':16s} {'variant':22s} {'CPU [s]':>9s} {'angle err':>10s} {'lock t err':>10s} {'torque err':>10s}")
    for r in st.rows:
        print(f"{r['case']:8s} {r['formulation']:16s} {r['variant']:22s} {r['cpu_s']:9.3f} {r.get('angle_err_deg', np.nan):10.3g} "
              f"{r.get('lock_time_err_s', np.nan):10.3g} {r.get('lock_torque_rel_err', np.nan):10.3g}")
    for n in st.notes:
        print("note: " + n)
    md = write_markdown(st.rows, os.path.join(a.out, "study-table.md"))
    print(f"wrote {os.path.join(a.out, 'study.csv')}, {md} and {png}\ncommand: {cmd}")
    # End-to-end check (the CTest runs --quick): every run finished, every error is a finite number,
    # the reference has zero error, and the CSV and the chart exist.
    bad = [r for r in st.rows if r["status"] != "ok" or not np.isfinite(r.get("angle_err_deg", np.nan))]
    if a.quick and (bad or st.rows[0].get("angle_err_deg") != 0.0 or not os.path.getsize(png)):
        sys.exit("study --quick: check failed: " + ", ".join(f"{r['formulation']} {r['variant']}: {r['status']}" for r in bad))


if __name__ == "__main__":
    main()
