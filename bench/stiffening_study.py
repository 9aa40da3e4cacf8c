#!/usr/bin/python3
"""How many superelements a beam needs, with and without geometric stiffening (issue 15; docs/speed-vs-accuracy.md,
"Geometric stiffening: superelements per beam").

The spin-up beam of Simo and Vu-Quoc (L = 10 m, EI = 1.4e4 N m^2, EA = 2.8e7 N, rho A = 1.2 kg/m; hub ramped to
6 rad/s, and 12 rad/s, over 15 s; 20 s) as N = 1, 2, 4, 5, 8, 10 AIC superelements in series, each cut from the same
40-CBAR beam (40/N CBARs per piece, reduced to its two end grids with 6 fixed-interface modes, full inertia),
run with and without geometric stiffening (scene key `geometric_stiffening: on|off`; one check run uses a
superelement reduced with `seflex reduce --no-stiffening` instead and must give the same history). The
error is the largest difference over 0-20 s of the tip's transverse displacement in the hub frame from the
INDEPENDENT corotational reference (bench/references/spinup_beam.py, 80 elements, converged to 0.02 % of the
peak: tests/data/mbd/spinup_beam_reference.csv, spinup_beam_12rads_reference.csv), in % of the reference's
peak |v| (0.574 m at 6 rad/s, 0.972 m at 12 rad/s), as tests/mbd/spinup_stiffening_test.cpp measures it.
CPU time: summary.json cpu_time_s; dofs: summary.json dofs.

  /usr/bin/python3 bench/stiffening_study.py [--bin build/apps/seflex] [--out study-output] [--img docs/img]
      [--pieces 1,2,4,5,8,10] [--rates 6,12] [--elements 40] [--timeout 300]

Writes OUT/stiffening/stiffening-study.csv (every run), OUT/stiffening/stiffening-table.md (the tables of the
doc) and the chart OUT/stiffening-vs-superelements.png (copied to --img). bench/study.py runs it (not with
--quick / --no-stiffening-study).
"""
import argparse, csv, json, os, shutil, sys, time
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib.runs import sh  # noqa: E402  (run a command: exit code and output, None on --timeout)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
L = 10.0
ELEMENTS = 40          # CBARs of the whole beam, split evenly between the superelements
MODES = 6              # fixed-interface modes per superelement
THRESHOLDS = (1.0, 3.0, 10.0)  # tip error [% of the reference's peak] of the summary table
REFERENCES = {6.0: "spinup_beam_reference.csv", 12.0: "spinup_beam_12rads_reference.csv"}


def piece_deck(n_el):
    """One of N equal pieces of the 10 m beam: n_el CBARs along x, grids 1..n_el+1, the section and material of
    bench/study/spinup_beam.bdf; a CONM2 with the piece's torsional inertia rho J L_piece (the bars lump
    translational mass only) at the middle grid."""
    pieces = ELEMENTS // n_el
    lp = L / pieces
    out = [f"$ 1/{pieces} of the spin-up beam (bench/stiffening_study.py): {lp:g} m, {n_el} CBARs, grids 1..{n_el + 1}.",
           "BEGIN BULK"]
    for i in range(n_el + 1):
        out.append(f"GRID,{i + 1},,{lp * i / n_el:.8E},0.0,0.0")
    for i in range(n_el):
        out.append(f"CBAR,{i + 1},10,{i + 1},{i + 2},0.0,0.0,1.0")
    out += ["PBAR,10,1,1.0E-2,5.0E-6,5.0E-6,1.0E-5", "MAT1,1,2.8E9,,0.3,120.0",
            f"CONM2,100,{n_el // 2 + 1},,0.0,0.0,0.0,0.0,,+C1", f"+C1,{120.0 * 1e-5 * lp:.6E},0.0,0.0,0.0,0.0,0.0", "ENDDATA"]
    return "\n".join(out) + "\n"


def scene(pieces, se_file, rate, stiffening):
    lp = L / pieces
    n_el = ELEMENTS // pieces
    key = "on" if stiffening else "off"
    lines = [f"# Spin-up beam as {pieces} superelement(s) in series, {rate:g} rad/s, geometric stiffening {key}"
             " (bench/stiffening_study.py)", f"title: spin-up beam, {pieces} superelements, {rate:g} rad/s, stiffening {key}", "bodies:"]
    for b in range(pieces):
        lines.append(f"  - {{name: b{b}, superelement: {se_file}, inertia: full, geometric_stiffening: {key}, "
                     f"placement: {{position: [{b * lp:.10g}, 0, 0]}}}}")
    if pieces > 1:
        lines.append("connections:")
        for b in range(pieces - 1):
            lines.append(f"  - [b{b}.{n_el + 1}, b{b + 1}.1]")
    lines += ["hinges:", "  - {name: hub, parent: ground, child: b0.1, axis: [0, 0, 1]}", "drives:",
              f"  - {{hinge: hub, kind: spin_up, rate_deg_s: {np.degrees(rate)!r}, ramp_time: 15.0}}",
              "integrator: {rho_inf: 0.9, t_end: 20.0, step: 1.0e-3, max_step: 2.0e-2, tolerance: {position: 1.0e-6, angle: 1.0e-6}}",
              "output: {interval: 0.05}"]
    return "\n".join(lines) + "\n"


def tip_in_hub_frame(folder, pieces, n_el):
    """t, v: the tip's transverse displacement in the frame turning with the hub. The tip is the second
    interface of the last body: p = p_WB + R_WB (p_BoT_B + u_T), u_T = q[6:9] (formulation.md 1.2), p_BoT_B from
    the undeformed pose at t = 0 (tip at (L, 0, 0))."""
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.reader(f))
    k = rows[0].index("hub.phi_deg")
    t_h = np.array([float(r[0]) for r in rows[1:]])
    hub = np.radians([float(r[k]) for r in rows[1:]])
    last = f"b{pieces - 1}"
    t, v = [], []
    p_BoT_B = None
    with open(os.path.join(folder, "poses.csv")) as f:
        r = csv.reader(f)
        head = next(r)
        iq = head.index("q6")
        for row in r:
            if row[1] != last:
                continue
            R = np.array([float(x) for x in row[2:11]]).reshape(3, 3)
            p = np.array([float(x) for x in row[11:14]])
            if p_BoT_B is None:
                p_BoT_B = R.T @ (np.array([L, 0.0, 0.0]) - p)
            u = np.array([float(x) for x in row[iq:iq + 3]])
            tip = p + R @ (p_BoT_B + u)
            ti = float(row[0])
            th = np.interp(ti, t_h, hub)
            t.append(ti)
            v.append(-np.sin(th) * tip[0] + np.cos(th) * tip[1])
    return np.array(t), np.array(v)


def reference(rate):
    d = np.loadtxt(os.path.join(ROOT, "tests", "data", "mbd", REFERENCES[rate]), delimiter=",", comments="#")
    keep = d[:, 0] <= 20.0 + 1e-9
    return d[keep, 0], d[keep, 1]


def needed(rows, rate, stiff, thr):
    """Fewest superelements whose run finished with a tip error <= thr % (None: none of those tried)."""
    ok = [r["pieces"] for r in rows if r["rate"] == rate and r["stiffening"] == stiff and r["status"] == "ok" and r["err_pct"] <= thr]
    return min(ok) if ok else None


def run_study(bin_path, out, img=None, pieces_list=(1, 2, 4, 5, 8, 10), rates=(6.0, 12.0), timeout=300.0, cmd=None):
    cmd = cmd or "/usr/bin/python3 bench/stiffening_study.py"
    wd = os.path.join(out, "stiffening")
    os.makedirs(wd, exist_ok=True)
    rows = []
    for pieces in pieces_list:
        if ELEMENTS % pieces:
            sys.exit(f"stiffening study: {ELEMENTS} CBARs do not split into {pieces} equal pieces")
        n_el = ELEMENTS // pieces
        deck = os.path.join(wd, f"piece{pieces}.bdf")
        with open(deck, "w") as f:
            f.write(piece_deck(n_el))
        se = os.path.join(wd, f"piece{pieces}.se")
        code, text = sh([bin_path, "reduce", deck, "--interface", f"1,{n_el + 1}", "--modes", str(MODES), "-o", se, "--force"])
        if code:
            sys.exit("stiffening study: seflex reduce failed:\n" + text)
        for rate in rates:
            t0, v0 = reference(rate)
            peak = float(np.max(np.abs(v0)))
            for stiff in (True, False):
                name = f"n{pieces}-w{rate:g}-{'on' if stiff else 'off'}"
                sc = os.path.join(wd, name + ".yaml")
                with open(sc, "w") as f:
                    f.write(scene(pieces, os.path.basename(se), rate, stiff))
                folder = os.path.join(wd, "runs", name)
                code, text = sh([bin_path, "run", sc, "-o", folder, "--force", "--no-animation"], timeout)
                js = os.path.join(folder, "summary.json")
                s = json.load(open(js)) if code is not None and os.path.exists(js) else {}
                r = dict(pieces=pieces, rate=rate, stiffening=stiff, status=s.get("status", "timeout" if code is None else "failed"),
                         cpu_s=s.get("cpu_time_s", timeout if code is None else float("nan")), steps=s.get("steps", 0),
                         dofs=s.get("dofs", 0), peak_m=peak, folder=folder,
                         message=(s.get("message") or ("" if code == 0 else text.strip()[-200:])).replace("\n", " "))
                err, t_worst, t_last = np.inf, float("nan"), float("nan")
                if os.path.exists(os.path.join(folder, "poses.csv")):
                    t, v = tip_in_hub_frame(folder, pieces, n_el)
                    t_last = float(t[-1]) if len(t) else 0.0
                    if r["status"] == "ok":
                        g = t0 <= t[-1] + 1e-9
                        d = np.abs(np.interp(t0[g], t, v) - v0[g])
                        err, t_worst = float(np.max(d)), float(t0[g][np.argmax(d)])
                r.update(err_m=err, err_pct=100.0 * err / peak, t_worst=t_worst, t_last=t_last)
                rows.append(r)
                print(f"  {pieces} SE  {rate:4g} rad/s  stiffening {'on ' if stiff else 'off'}  {r['status']:7s} {r['cpu_s']:8.3f} s CPU "
                      f"{r['dofs']:4d} dofs {r['steps']:6d} steps  tip error {err:.4g} m = {r['err_pct']:.3g} % of {peak:.4g} m"
                      + (f"  ({r['message'][:100]})" if r["status"] != "ok" else ""), flush=True)

    # Check: the scene key `off` and a superelement reduced with --no-stiffening are the same model.
    check = None
    if 1 in pieces_list and 6.0 in rates:
        n_el = ELEMENTS
        se = os.path.join(wd, "piece1-nostiff.se")
        code, text = sh([bin_path, "reduce", os.path.join(wd, "piece1.bdf"), "--interface", f"1,{n_el + 1}", "--modes", str(MODES), "-o", se,
                         "--force", "--no-stiffening"])
        sc = os.path.join(wd, "n1-w6-nostiff-file.yaml")
        with open(sc, "w") as f:
            f.write(scene(1, os.path.basename(se), 6.0, True).replace("geometric_stiffening: on, ", ""))
        folder = os.path.join(wd, "runs", "n1-w6-nostiff-file")
        code, text = sh([bin_path, "run", sc, "-o", folder, "--force", "--no-animation"], timeout)
        off = [r for r in rows if r["pieces"] == 1 and r["rate"] == 6.0 and not r["stiffening"]][0]
        if code == 0 and off["status"] == "ok":
            t, v = tip_in_hub_frame(folder, 1, n_el)
            ta, va = tip_in_hub_frame(off["folder"], 1, n_el)
            check = float(np.max(np.abs(np.interp(ta, t, v) - va)))
            print(f"  check: 1 SE, reduced with --no-stiffening (no key) against the scene key off: largest tip difference {check:.3g} m")
        else:
            print(f"  check: the --no-stiffening run failed: {text.strip()[-200:]}")

    fields = ["pieces", "rate", "stiffening", "status", "cpu_s", "steps", "dofs", "err_m", "err_pct", "peak_m", "t_worst", "t_last", "message"]
    with open(os.path.join(wd, "stiffening-study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)

    # Tables: every run, and the superelements needed per threshold.
    def fmt_err(r):
        if r["status"] != "ok":
            return f"{r['status']} at t = {r['t_last']:.3g} s"
        return f"{r['err_pct']:.3g} % ({r['err_m']:.3g} m)"
    md = [f"Command: `{cmd}` ({time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}).", "",
          "| hub rate | superelements | dofs | with stiffening: tip error | CPU [s] | without: tip error | CPU [s] |", "|---|---|---|---|---|---|---|"]
    for rate in rates:
        for pieces in pieces_list:
            on = [r for r in rows if r["rate"] == rate and r["pieces"] == pieces and r["stiffening"]][0]
            off = [r for r in rows if r["rate"] == rate and r["pieces"] == pieces and not r["stiffening"]][0]
            md.append(f"| {rate:g} rad/s | {pieces} | {on['dofs']} | {fmt_err(on)} | {on['cpu_s']:.3g} | {fmt_err(off)} | {off['cpu_s']:.3g} |")
    md += ["", "| hub rate | tip error <= | superelements with stiffening | without |", "|---|---|---|---|"]
    for rate in rates:
        for thr in THRESHOLDS:
            a, b = needed(rows, rate, True, thr), needed(rows, rate, False, thr)
            md.append(f"| {rate:g} rad/s | {thr:g} % | {a if a else f'more than {max(pieces_list)}'} | {b if b else f'more than {max(pieces_list)}'} |")
    if check is not None:
        md += ["", f"Check: one superelement reduced with `--no-stiffening` (no scene key) against the scene key `off`: largest tip "
               f"difference {check:.3g} m."]
    table = os.path.join(wd, "stiffening-table.md")
    with open(table, "w") as f:
        f.write("\n".join(md) + "\n")

    # Chart: tip error against CPU time (points labelled by N) and against N, with / without, per rate.
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11.5, 5.2))
    styles = {(True, 6.0): ("C0", "o-"), (False, 6.0): ("C3", "o--"), (True, 12.0): ("C0", "s-"), (False, 12.0): ("C3", "s--")}
    fail_y = {6.0: 500.0, 12.0: 150.0}  # failed runs (runaway) are marked with an x at these heights, with the time of failure
    for rate in rates:
        for stiff in (True, False):
            rs = sorted((r for r in rows if r["rate"] == rate and r["stiffening"] == stiff), key=lambda r: r["pieces"])
            color, style = styles.get((stiff, rate), ("k", "o-"))
            label = f"{rate:g} rad/s, {'with' if stiff else 'without'} stiffening"
            # a failed run breaks the line (NaN) instead of being bridged
            err = [max(r["err_pct"], 1e-3) if r["status"] == "ok" else np.nan for r in rs]
            axes[0].loglog([r["cpu_s"] for r in rs], err, style, color=color, label=label)
            for r, e in zip(rs, err):
                if np.isfinite(e):
                    axes[0].annotate(f"{r['pieces']}", (r["cpu_s"], e), fontsize=7, xytext=(3, 3), textcoords="offset points")
            axes[1].semilogy([r["pieces"] for r in rs], err, style, color=color, label=label)
            for r in rs:
                if r["status"] != "ok":
                    y = fail_y.get(rate, 300.0)
                    axes[1].plot([r["pieces"]], [y], "x", color=color, ms=9, mew=2)
                    axes[1].annotate(f"{r['t_last']:.2g} s", (r["pieces"], y), fontsize=6, color=color, xytext=(-8, -11), textcoords="offset points")
    for ax in axes:
        for thr in THRESHOLDS:
            ax.axhline(thr, color="k", lw=0.6, ls=":")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylabel("max tip error in the hub frame [% of the reference's peak]")
    axes[0].set_xlabel("CPU time of the run [s] (labels: superelements)")
    axes[0].set_title("spin-up beam: error against cost", fontsize=9)
    axes[1].set_xlabel("superelements in series (6 modes each)")
    axes[1].set_xscale("log", base=2)
    axes[1].set_xticks(list(pieces_list), [str(p) for p in pieces_list])
    axes[1].set_ylim(top=1500.0)
    failed = sorted({r["rate"] for r in rows if r["status"] != "ok"})
    note = ("\n(x: the run failed at the time given" + ("; upper row 6 rad/s, lower 12 rad/s)" if len(failed) > 1 else f", {failed[0]:g} rad/s)")
            if failed else "")
    axes[1].set_title("spin-up beam: error against superelements" + note, fontsize=9)
    h, lab = axes[0].get_legend_handles_labels()
    fig.legend(h, lab, loc="upper center", ncol=4, fontsize=8)
    fig.text(0.01, 0.01, cmd, fontsize=6)
    fig.tight_layout(rect=(0, 0.03, 1, 0.94))
    png = os.path.join(out, "stiffening-vs-superelements.png")
    fig.savefig(png, dpi=110)
    if img:
        shutil.copy(png, img)
    print("\n" + "\n".join(md))
    print(f"wrote {os.path.join(wd, 'stiffening-study.csv')}, {table} and {png}\ncommand: {cmd}")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "apps", "seflex"))
    ap.add_argument("--out", default="study-output")
    ap.add_argument("--img", default=None, help="also copy the chart here (e.g. docs/img)")
    ap.add_argument("--pieces", default="1,2,4,5,8,10", help="superelement counts (divisors of --elements)")
    ap.add_argument("--rates", default="6,12", help="hub rates [rad/s]: 6 and/or 12 (the references)")
    ap.add_argument("--elements", type=int, default=ELEMENTS, help="CBARs of the whole beam (40)")
    ap.add_argument("--timeout", type=float, default=300.0)
    a = ap.parse_args()
    globals()["ELEMENTS"] = a.elements
    a.bin = os.path.abspath(a.bin)
    if not os.access(a.bin, os.X_OK):
        sys.exit(f"stiffening study: no seflex binary at {a.bin} (build the target seflex or pass --bin)")
    try:
        pieces = [int(x) for x in a.pieces.split(",")]
        rates = [float(x) for x in a.rates.split(",")]
    except ValueError:
        sys.exit(f"stiffening study: --pieces expects integers and --rates numbers separated by commas, got '{a.pieces}', '{a.rates}'")
    bad = [r for r in rates if r not in REFERENCES]
    if bad:
        sys.exit(f"stiffening study: no corotational reference for {bad} rad/s (have 6 and 12)")
    cmd = "/usr/bin/python3 bench/stiffening_study.py " + " ".join(sys.argv[1:])
    print(f"seflex stiffening study, {time.strftime('%Y-%m-%d')}: {cmd}")
    run_study(a.bin, a.out, a.img, pieces, rates, a.timeout, cmd)


if __name__ == "__main__":
    main()
