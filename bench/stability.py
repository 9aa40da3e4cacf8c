#!/usr/bin/python3
"""Where methods fail (issue 7, docs/stability.md): largest stable constant step of the explicit RK4
foil, of the implicit generalized-alpha (AIC) and of FFRF-LM (seflex run --formulation ffrf-lm), with
and without a lock; FFRF-LM constraint drift (printed by seflex run) at fixed and adaptive steps; Newton failures at a lock with
large steps; the simplified mass and FFRF-LM against the AIC full inertia as the spin rate of the
spin-up beam grows. With --radau, only Radau IIA-5 (integrator.method radau5): its largest steps on the
falling link with and without its stiff lock, its measured order with and without the lock crossing,
and the numerical damping of a mode (the panels' 33 Hz) per period at large steps against
generalized-alpha at rho_inf 0.8 / 0.9 / 1.0.

  /usr/bin/python3 bench/stability.py [--bin build/apps/seflex] [--out stability-output] [--img docs/img] [--radau]

Models: bench/study/link_lock.yaml (flexible link of examples/scenes/link.bdf, 3 modes, falling 1 s;
"without lock": the lock removed) and bench/study/spinup.yaml (10 m spin-up beam, 6 modes).
A run is "stable" when it reaches t_end with status ok (RK4 stops itself on blow-up, exit 4).
"""
import argparse, os, re, shutil, subprocess, sys, time, json
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib.runs import edit_scene, save_figure  # noqa: E402
from lib.measures import spinup_lag  # noqa: E402
from lib.linear_test import amplitude_per_period  # noqa: E402  (the one-step maps of the linear test)


def run(binary, text, folder, extra=()):
    scene = folder + ".yaml"
    open(scene, "w").write(text)
    r = subprocess.run([binary, "run", scene, "-o", folder, "--force", "--no-animation", *extra], capture_output=True, text=True)
    s = json.load(open(os.path.join(folder, "summary.json")))
    # FFRF-LM / rigid-LM: `seflex run` prints the largest constraint drift (mbd::FfrfStats).
    m = re.search(r"largest constraint drift ([0-9.eE+-]+) m, ([0-9.eE+-]+) rad \(([0-9.eE+-]+) m/s\)", r.stdout)
    if m:
        s["drift"] = tuple(float(x) for x in m.groups())
    return s


def sample_every(text, h):
    """The integrator lands on every output sample, so output.interval caps the step: sample at h."""
    return re.sub(r"interval: [0-9.eE+-]+", f"interval: {max(h, 1e-3):g}", text, count=1)


def fixed(text, method, h):
    if method == "rk4":
        return sample_every(edit_scene(text, method="rk4", step=h), h)
    t = re.sub(r", max_step: [0-9.eE+-]+", "", text)
    t = re.sub(r"step: [0-9.eE+-]+", f"step: {h:g}, adaptive: false, min_step: {h:g}", t, count=1)
    return sample_every(t, h)


def capped(text, h):
    """Adaptive generalized-alpha with initial and largest step h (a flow-style integrator map)."""
    t = re.sub(r"max_step: [0-9.eE+-]+, ", "", text)
    return sample_every(re.sub(r"step: [0-9.eE+-]+", f"step: {h:g}, max_step: {h:g}", t, count=1), h)


def solar(text, h, adaptive):
    """examples/solar_array scene (block-style integrator) with a fixed step h or a largest step h."""
    t = re.sub(r"\n  step: [0-9.eE+-]+", f"\n  step: {h:g}", text)
    t = re.sub(r"max_step: [0-9.eE+-]+", f"max_step: {h:g}", t)
    t = re.sub(r"after_all_locked: [0-9.eE+-]+", "after_all_locked: 0.5", t)
    t = re.sub(r"  interval: [0-9.eE+-]+\n  animation: [^\n]+", f"  interval: {max(h, 5e-3):g}", t)
    if not adaptive:
        t = re.sub(r"min_step: [0-9.eE+-]+", f"min_step: {h:g}", t).replace("adaptive: true", "adaptive: false")
    return t


def radau(text):
    """The link scene (flow-style integrator map) with method radau5."""
    return text.replace("integrator: {rho_inf: 0.8, ", "integrator: {method: radau5, ")


def with_tol(text, tol):
    return text.replace("integrator: {", f"integrator: {{tolerance: {{position: {tol:g}, angle: {tol:g}}}, ", 1)


def final_angle(folder, hinge="H1"):
    """The hinge's angle at the run's end [deg] (last row of history.csv)."""
    with open(os.path.join(folder, "history.csv")) as f:
        head = f.readline().strip().split(",")
        last = None
        for line in f:
            last = line
    return float(last.strip().split(",")[head.index(f"{hinge}.phi_deg")])


def radau_study(b, a, link, nolock, cmd):
    """Radau IIA-5 where it fails: largest steps, order through the lock, numerical damping."""
    d = lambda n: os.path.join(a.out, n)
    rows = []
    for h in (1e-3, 5e-3, 1e-2, 2e-2, 5e-2, 1e-1):
        for name, text in (("link, no lock", nolock), ("link, lock", link)):
            sf = run(b, fixed(radau(text), "radau5", h), d("radau-fixed"))
            tf, why = failure(d("radau-fixed"))
            sa = run(b, capped(radau(text), h), d("radau-adaptive"))
            lk = sa["locks"].get("lock.H1", {})
            rows.append(dict(model=name, h=h, fixed=sf["status"], fixed_t=tf, fixed_why=why, adaptive=sa["status"], steps=sa["steps"],
                             rejected_error=sa.get("rejected_error"), rejected_newton=sa.get("rejected_newton"),
                             t_latch=lk.get("t_latch"), peak=lk.get("peak_abs_torque_after_latch")))
            print(f"  radau5 {name:14s} h {h:g}: fixed {sf['status']}" + (f" (t = {tf:.4g} s: {why})" if tf is not None else "") +
                  f"; adaptive, largest step h: {sa['status']}, {sa['steps']} steps, {sa.get('rejected_error')} + {sa.get('rejected_newton')} rejected"
                  + (f", t_latch {lk.get('t_latch')}, peak lock torque {lk.get('peak_abs_torque_after_latch', 0):.4g} N m" if lk else ""), flush=True)
    # Order at constant steps (Newton to round-off: 30 iterations, tolerance 1e-12): error of the final
    # angle (t = 1 s) against h = 0.125 ms; with the lock the step that crosses it is cut to the crossing.
    fixed_order = []
    for name, text in (("link, no lock", nolock), ("link, lock", link)):
        tight = lambda h: fixed(with_tol(radau(text), 1e-12).replace("integrator: {", "integrator: {radau: {max_iterations: 30}, ", 1), "radau5", h)
        ref = run(b, tight(1.25e-4), d("radau-fixed-ref"))
        a_ref = final_angle(d("radau-fixed-ref"))
        pts = []
        for h in (2e-3, 1e-3, 5e-4):
            s = run(b, tight(h), d("radau-fixed-h"))
            pts.append((h, s["status"], abs(final_angle(d("radau-fixed-h")) - a_ref) if s["status"] == "ok" else float("nan")))
        ok = [p for p in pts if p[1] == "ok"]
        slope = np.polyfit(np.log([p[0] for p in ok]), np.log([max(p[2], 1e-14) for p in ok]), 1)[0] if len(ok) > 1 else float("nan")
        fixed_order.append(dict(model=name, reference_status=ref["status"], points=pts, order=slope))
        print(f"  radau5 {name}, constant steps: final angle error against h = 0.125 ms ({ref['status']}): " +
              ", ".join(f"h {h:g}: {st}, {err:.2e} deg" for h, st, err in pts) + f"; order {slope:.2f}", flush=True)
    # Order: error of the final angle (t = 1 s) against local error 1e-10 over the steps taken.
    order = []
    for name, text in (("link, no lock", nolock), ("link, lock", link)):
        ref = run(b, with_tol(radau(text), 1e-10), d("radau-ref"))
        a_ref = final_angle(d("radau-ref"))
        pts = []
        for tol in (1e-4, 1e-5, 1e-6, 1e-7, 1e-8):
            s = run(b, with_tol(radau(text), tol), d("radau-tol"))
            pts.append((tol, s["steps"], abs(final_angle(d("radau-tol")) - a_ref)))
        n, e = np.log([p[1] for p in pts[-3:]]), np.log([max(p[2], 1e-14) for p in pts[-3:]])
        slope = -np.polyfit(n, e, 1)[0]  # the three tightest: the loosest are not asymptotic
        order.append(dict(model=name, reference_steps=ref["steps"], points=pts, order=slope))
        print(f"  radau5 {name}: final angle error against local error 1e-10 ({ref['steps']} steps): " +
              ", ".join(f"tol {t:g}: {st} steps, {err:.2e} deg" for t, st, err in pts) + f"; order (error ~ steps^-p) p = {slope:.2f}", flush=True)
    # Numerical damping of a 33 Hz mode (the panels' first) per period at the demo's steps and above.
    f_mode = 33.0
    damping = []
    for h in (2.5e-3, 5e-3, 1e-2, 2e-2):
        wh = 2 * np.pi * f_mode * h
        r = dict(h=h, radau5=amplitude_per_period("radau5", wh), **{f"ga{rho:g}": amplitude_per_period("ga", wh, rho) for rho in (0.8, 0.9, 1.0)})
        damping.append(r)
        print(f"  33 Hz mode, h {h:g} s (w h = {wh:.3f}): amplitude per period radau5 {r['radau5']:.4f}, generalized-alpha rho_inf 0.8 "
              f"{r['ga0.8']:.4f}, 0.9 {r['ga0.9']:.4f}, 1.0 {r['ga1']:.4f}", flush=True)
    with open(os.path.join(a.out, "stability-radau.json"), "w") as f:
        json.dump(dict(command=cmd, rows=rows, fixed_order=fixed_order, order=order, damping=damping), f, indent=1)
    print(f"wrote {os.path.join(a.out, 'stability-radau.json')}")


def failure(folder):
    ev = open(os.path.join(folder, "events.csv")).read()
    m = re.search(r"stopped at t = ([0-9.eE+-]+) s.*?\): ([^;]+)", ev)
    return (float(m.group(1)), m.group(2)) if m else (None, "")


def largest_stable(binary, text, method, folder, lo, hi, n=7):
    """Bisection in log h between a stable lo and an unstable hi (checked first). method "ffrf-lm":
    generalized-alpha on the floating frame with Lagrange multipliers (seflex run --formulation ffrf-lm)."""
    extra = ["--formulation", "ffrf-lm"] if method == "ffrf-lm" else []
    ok = lambda h: run(binary, fixed(text, "generalized-alpha" if method == "ffrf-lm" else method, h), folder, extra)["status"] == "ok"
    if not ok(lo):
        return None, lo
    if ok(hi):
        return hi, None
    for _ in range(n):
        mid = np.sqrt(lo * hi)
        lo, hi = (mid, hi) if ok(mid) else (lo, mid)
    return lo, hi


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "apps", "seflex"))
    ap.add_argument("--out", default="stability-output")
    ap.add_argument("--img", default=None)
    ap.add_argument("--replot", action="store_true", help="only redraw the chart from OUT/stability.json")
    ap.add_argument("--radau", action="store_true", help="only the Radau IIA-5 study (OUT/stability-radau.json)")
    a = ap.parse_args()
    if a.replot:
        with open(os.path.join(a.out, "stability.json")) as f:
            plot(json.load(f), a, "/usr/bin/python3 bench/stability.py " + " ".join(x for x in sys.argv[1:] if x != "--replot"))
        return
    b = os.path.abspath(a.bin)
    os.makedirs(a.out, exist_ok=True)
    cmd = "/usr/bin/python3 bench/stability.py " + " ".join(sys.argv[1:])
    print(f"seflex stability, {time.strftime('%Y-%m-%d')}: {cmd}")
    for f in ("spinup_beam.bdf", "spinup.yaml", "link_lock.yaml"):
        shutil.copy(os.path.join(ROOT, "bench", "study", f), a.out)
    shutil.copy(os.path.join(ROOT, "examples", "scenes", "link.bdf"), a.out)
    for deck, iface, modes, se in (("spinup_beam.bdf", "1,11", "6", "spinup_beam.se"), ("link.bdf", "1,5", "3", "link.se")):
        subprocess.run([b, "reduce", os.path.join(a.out, deck), "--interface", iface, "--modes", modes, "-o", os.path.join(a.out, se), "--force"],
                       check=True, capture_output=True)
    link = open(os.path.join(a.out, "link_lock.yaml")).read()
    nolock = re.sub(r"locks:\n  - [^\n]+\n", "", link)
    if a.radau:
        radau_study(b, a, link, nolock, cmd)
        return
    spin = edit_scene(open(os.path.join(a.out, "spinup.yaml")).read(), t_end=4.0)
    d = lambda n: os.path.join(a.out, n)
    # 1. Largest stable constant step.
    table = []
    for name, text in (("link, no lock", nolock), ("link, lock", link), ("spin-up beam 0-4 s", spin)):
        for method, lo, hi in (("rk4", 1e-5, 1e-2), ("generalized-alpha", 1e-4, 5e-2), ("ffrf-lm", 1e-3 if name.startswith("spin") else 1e-4, 2e-1)):
            s, u = largest_stable(b, text, method, d("bisect"), lo, hi)
            table.append((name, method, s, u))
            print(f"  {name:20s} {method:18s} largest stable step {s if s else float('nan'):.3g} s (unstable at {u if u else float('nan'):.3g} s)", flush=True)
    # 1b. FFRF-LM constraint drift on the link (index 3: positions to the Newton tolerance, velocities not).
    drift_rows = []
    for name, text in (("link, no lock", nolock), ("link, lock", link)):
        for h in (1e-3, 1e-2):
            for mode, t in (("fixed", fixed(text, "generalized-alpha", h)), ("adaptive", capped(text, h))):
                s = run(b, t, d("ffrfdrift"), ["--formulation", "ffrf-lm"])
                dr = s.get("drift", (np.nan,) * 3)
                lk = s["locks"].get("lock.H1", {})
                drift_rows.append((name, h, mode, s["status"], s["steps"]) + dr)
                print(f"  FFRF-LM {name:14s} {mode:8s} h {h:g}: {s['status']}, {s['steps']} steps; drift {dr[0]:.2e} m, {dr[1]:.2e} rad, "
                      f"{dr[2]:.2e} m/s" + (f"; t_latch {lk.get('t_latch')}, peak lock torque {lk.get('peak_abs_torque_after_latch', 0):.4g} N m" if lk else ""),
                      flush=True)
    # 2. Implicit at large steps through the locks: fixed step (Newton must converge on the latching
    #    step) and adaptive with that step as the largest (rejected steps, Newton retries).
    lock_rows = []
    for h in (1e-3, 2e-3, 4e-3, 5e-3, 1e-2, 2e-2, 5e-2):
        sf = run(b, fixed(link, "generalized-alpha", h), d("lockfixed"))
        tf, why = failure(d("lockfixed"))
        sa = run(b, capped(link, h), d("lockstep"))
        lk = sa["locks"]["lock.H1"]
        lock_rows.append((h, sf["status"], tf, sa["status"], sa["steps"], sa["rejected_steps"], lk["t_latch"], lk["peak_abs_torque_after_latch"]))
        print(f"  link with lock, h = {h:g}: fixed step {sf['status']}" + (f" (t = {tf:.4g} s: {why})" if tf is not None else "") +
              f"; adaptive, max step h: {sa['status']}, {sa['steps']} steps, {sa['rejected_steps']} rejected, t_latch {lk['t_latch']}, "
              f"peak lock torque {lk['peak_abs_torque_after_latch']:.4g} N m", flush=True)
    # Solar array (beam-like, synchronised; superelements as scripts/demo.sh makes them).
    os.makedirs(d("superelements"), exist_ok=True)
    for body, iface in (("yoke", "1,5"), ("panel", "5,6")):
        subprocess.run([b, "reduce", os.path.join(ROOT, "meshes", body + ".bdf"), "--interface", iface, "--modes", "10", "--name", body + "-beam",
                        "-o", d(f"superelements/{body}-beam.se"), "--force"], check=True, capture_output=True)
    sa_text = open(os.path.join(ROOT, "examples", "solar_array", "sync-beam.yaml")).read()
    solar_rows = []
    for h in (2e-3, 5e-3, 6e-3, 1e-2, 2e-2):
        for adaptive in (False, True):
            s = run(b, solar(sa_text, h, adaptive), d("solar"))
            tf, why = failure(d("solar"))
            latches = {k: v["t_latch"] for k, v in s["locks"].items()}
            solar_rows.append((h, adaptive, s["status"], tf, s["steps"], s["rejected_steps"], latches))
            print(f"  sync-beam solar array, {'adaptive, max' if adaptive else 'fixed'} step {h:g}: {s['status']}" +
                  (f" at t = {tf:.4g} s ({why})" if tf is not None else "") + f", {s['steps']} steps, {s['rejected_steps']} rejected, latches {latches}", flush=True)
    # 3. Simplified mass against full inertia as the spin rate grows (lag of the beam behind the hub).
    spin_rows, ffrf_rows = [], []
    for rate in (1.5, 3.0, 6.0, 6.5, 6.8, 9.0):
        text = re.sub(r"rate_deg_s: [0-9.eE+-]+", f"rate_deg_s: {np.degrees(rate):.10g}", open(os.path.join(a.out, "spinup.yaml")).read())
        lags, fails = {}, {}
        for key, extra in (("full", ["--inertia", "full"]), ("simplified", ["--inertia", "simplified"]), ("ffrf-lm", ["--formulation", "ffrf-lm"])):
            s = run(b, text, d(f"spin-{key}"), extra)
            lags[key] = spinup_lag(d(f"spin-{key}")) if s["status"] == "ok" else None
            fails[key] = None if s["status"] == "ok" else failure(d(f"spin-{key}"))[0]
        # FFRF-LM (no geometric stiffening in its frame-clamped modes): its lag and its difference to AIC full.
        if lags["ffrf-lm"] is None:
            ff_lag, ff_diff = np.inf, np.inf
            print(f"  spin-up to {rate:g} rad/s: FFRF-LM failed at t = {fails['ffrf-lm']} s", flush=True)
        else:
            ff_lag = float(np.max(np.abs(lags["ffrf-lm"][1])))
            ff_diff = np.inf if lags["full"] is None else float(np.max(np.abs(np.interp(lags["full"][0], *lags["ffrf-lm"]) - lags["full"][1])))
            print(f"  spin-up to {rate:g} rad/s: FFRF-LM max lag {ff_lag:.3g} deg, max difference to AIC full {ff_diff:.3g} deg", flush=True)
        ffrf_rows.append((rate, ff_lag, ff_diff, fails["ffrf-lm"]))
        if lags["full"] is None:  # the reference itself failed (reported, the sweep goes on)
            spin_rows.append((rate, np.nan, np.nan, np.nan, fails["full"]))
            print(f"  spin-up to {rate:g} rad/s: the full-inertia run failed (see {d('spin-full')}/summary.txt)", flush=True)
            continue
        t, lf = lags["full"]
        if lags["simplified"] is None:
            spin_rows.append((rate, float(np.max(np.abs(lf))), np.inf, np.inf, None))
        else:
            ts, ls = lags["simplified"]
            spin_rows.append((rate, float(np.max(np.abs(lf))), float(np.max(np.abs(ls))), float(np.max(np.abs(np.interp(t, ts, ls) - lf))), None))
        print(f"  spin-up to {rate:g} rad/s: max lag full {spin_rows[-1][1]:.3g} deg, simplified {spin_rows[-1][2]:.3g} deg, "
              f"max difference {spin_rows[-1][3]:.3g} deg", flush=True)
    data = dict(table=table, lock_rows=lock_rows, solar_rows=solar_rows, spin_rows=spin_rows, ffrf_rows=ffrf_rows)
    with open(os.path.join(a.out, "stability.json"), "w") as f:
        json.dump(data, f)
    plot(data, a, cmd)


def plot(data, a, cmd):
    """The chart of the measured rows (also from OUT/stability.json with --replot)."""
    table, lock_rows, solar_rows, spin_rows, ffrf_rows = (data[k] for k in ("table", "lock_rows", "solar_rows", "spin_rows", "ffrf_rows"))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(16, 4.8))
    models = list(dict.fromkeys(n for n, _, _, _ in table))
    methods = [("rk4", "RK4 (explicit)", "C0"), ("generalized-alpha", "AIC, generalized-alpha", "C1"), ("ffrf-lm", "FFRF-LM, generalized-alpha", "C2")]
    for j, (m, label, color) in enumerate(methods):
        rows = [next((r for r in table if r[0] == n and r[1] == m), None) for n in models]
        x = [i + (j - 1) * 0.27 for i in range(len(models))]
        hs = [r[2] if r and r[2] else 0 for r in rows]
        bars = ax[0].bar(x, hs, width=0.27, color=color, label=label)
        for bar, r in zip(bars, rows):
            if r and r[3] is None:  # stable at the largest step tried: a lower bound
                bar.set_hatch("//")
                ax[0].annotate(">=", (bar.get_x() + bar.get_width() / 2, bar.get_height()), ha="center", va="bottom", fontsize=7)
    ax[0].set_xticks(range(len(models)), models, fontsize=8)
    ax[0].set_yscale("log")
    ax[0].set_ylabel("largest stable constant step [s]")
    ax[0].set_ylim(top=3.0)  # room for the legend above the bars
    ax[0].legend(fontsize=7, loc="upper left", ncol=2)
    ax[0].set_title("largest stable constant step (hatched, >=: stable at the largest step tried)", fontsize=8)
    hs = [r[0] for r in lock_rows]
    ax[1].semilogx(hs, [r[5] for r in lock_rows], "o-", label="link, adaptive: rejected steps")
    fail = [r for r in lock_rows if r[1] != "ok"]
    t_latch = next((r[6] for r in lock_rows if r[3] == "ok" and r[6] is not None), None)
    after = [r[0] for r in fail if t_latch is None or r[2] is None or r[2] >= t_latch]
    before = [r[0] for r in fail if not (t_latch is None or r[2] is None or r[2] >= t_latch)]
    ax[1].semilogx(after, [0.5] * len(after), "rx", ms=9, label="link, fixed step: Newton fails after the latch")
    if before:
        ax[1].semilogx(before, [0.5] * len(before), "kx", ms=9, label="link, fixed step: Newton fails before the latch (free fall)")
    sr = [r for r in solar_rows if r[1]]
    ax[1].semilogx([r[0] for r in sr], [r[5] for r in sr], "s-", label="solar array, adaptive: rejected steps")
    sf = [r[0] for r in solar_rows if not r[1] and r[2] != "ok"]
    ax[1].semilogx(sf, [1.0] * len(sf), "m+", ms=11, label="solar array, fixed step: fails in the first steps")
    ax[1].set_xlabel("fixed step, or largest step of the adaptive run [s]")
    ax[1].set_ylabel("rejected steps (Newton or error test)")
    ax[1].legend(fontsize=6)
    ax[1].set_title("implicit generalized-alpha through the locks, large steps", fontsize=8)
    r = np.array([x[0] for x in spin_rows], dtype=float)
    ax[2].plot(r, [x[1] for x in spin_rows], "o-", color="C1", label="lag, AIC full inertia")
    ax[2].plot(r, [x[2] for x in spin_rows], "s-", color="C4", label="lag, AIC simplified mass")
    ax[2].plot(r, [x[3] for x in spin_rows], "^--", color="C4", label="|simplified - full|")
    rf = [x for x in ffrf_rows if np.isfinite(x[1])]
    ax[2].plot([x[0] for x in rf], [x[1] for x in rf], "D-", color="C2", mfc="none", label="lag, FFRF-LM")
    ax[2].plot([x[0] for x in rf], [x[2] for x in rf], "v:", color="C2", label="|FFRF-LM - AIC full|")
    for x in ffrf_rows:
        if not np.isfinite(x[1]):
            ax[2].annotate(f"FFRF-LM fails at t = {x[3]:.3g} s" if x[3] is not None else "FFRF-LM fails", (x[0], 0.5), fontsize=6, color="C2", rotation=90)
    for x in rf:
        if x[1] > 90.0:  # more than a quarter turn behind the hub: a diverged run that still ended "ok"
            ax[2].annotate("FFRF-LM ends 'ok',\ndiverged", (x[0], x[1]), fontsize=7, color="C2", ha="right", va="top")
    for x in spin_rows:
        if not np.isfinite(x[1]):
            ax[2].annotate(f"AIC full inertia fails at t = {x[4]:.3g} s" if x[4] is not None else "AIC full inertia fails", (x[0], 1e-3),
                           fontsize=7, color="C1", rotation=90, ha="right")
    ax[2].set_yscale("log")
    ax[2].set_xlabel("final spin rate [rad/s] (ramp 15 s)")
    ax[2].set_ylabel("max lag of the beam behind the hub [deg]")
    ax[2].legend(fontsize=7)
    ax[2].set_title("spin-up beam: simplified mass and FFRF-LM vs AIC full inertia", fontsize=8)
    png = save_figure(fig, a.out, "stability.png", a.img, cmd)
    print(f"wrote {png}\ncommand: {cmd}")


if __name__ == "__main__":
    main()
