#!/usr/bin/python3
"""Plots and metrics of the solar-array deployment demo (scripts/demo.sh, docs/solar-array-results.md).

    /usr/bin/python3 scripts/plot_solar_array.py OUTDIR [--no-plots]

Reads OUTDIR/<case>/history.csv (and summary.json) of the four cases {unsync, sync} x {beam, 3d}
written by `seflex run`, and writes
  OUTDIR/plots/<case>.png       hinge angles with the lock instants, lock torques after locking,
                                (sync) cable torques: the content of the seed's figures 8-13
  OUTDIR/plots/beam-vs-3d.png   beam-like against 3D, and their difference up to the first lock
  OUTDIR/metrics.json           lock times, peak lock torques (from the latch to the end, and in the
                                first 0.3 s: the impact), synchronisation errors before the first
                                lock, lock-time spread, beam-vs-3D difference, ratios unsync/sync
  OUTDIR/results.txt            the table printed at the end
Hinge lines: HL1, HL2, HL3. In the 3D cases a line is two hinges (HL2a, HL2b): its angle is their
mean, its lock time the later latch of the two, its lock torque the sum of the two.
Uses Debian's python3 (numpy, matplotlib); no other dependency.
"""
import csv
import json
import math
import os
import re
import sys

import numpy as np

CASES = ["unsync-beam", "unsync-3d", "sync-beam", "sync-3d"]
LINES = ["HL1", "HL2", "HL3"]
LOCK_DEG = {"HL1": 90.0, "HL2": 180.0, "HL3": 180.0}
IMPACT_WINDOW = 0.3  # [s] after latching: the first impact (the peak over the whole run rings on)


def line_of(hinge):
    m = re.match(r"(HL\d+)", hinge)
    return m.group(1) if m else hinge


def read_history(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        raise SystemExit("plot_solar_array: %s has no samples" % path)
    head = rows[0]
    data = np.array([[float(x) if x not in ("", "nan") else math.nan for x in r] for r in rows[1:] if r], dtype=float)
    return {name: data[:, j] for j, name in enumerate(head)}


class Case:
    """One run: hinge-line angles, lock times and torques, cable torques."""

    def __init__(self, out, name):
        self.name = name
        folder = os.path.join(out, name)
        self.h = read_history(os.path.join(folder, "history.csv"))
        self.summary = {}
        sp = os.path.join(folder, "summary.json")
        if os.path.exists(sp):
            with open(sp) as f:
                self.summary = json.load(f)
        h = self.h
        self.t = h["t"]
        self.hinges = [c[: -len(".phi_deg")] for c in h if c.endswith(".phi_deg")]
        self.members = {ln: [x for x in self.hinges if line_of(x) == ln] for ln in LINES}
        for ln in LINES:
            if not self.members[ln]:
                raise SystemExit("plot_solar_array: %s has no hinge of line %s" % (name, ln))
        self.phi = {ln: np.mean([h[x + ".phi_deg"] for x in self.members[ln]], axis=0) for ln in LINES}
        # Lock latch time of every hinge: the first sample with latched = 1 (the run writes a sample
        # at each located latch instant), or summary.json's value when it has one.
        self.t_latch = {}
        for x in self.hinges:
            col = h.get("lock.%s.latched" % x)
            if col is None:
                continue
            idx = np.nonzero(col > 0.5)[0]
            self.t_latch[x] = float(self.t[idx[0]]) if idx.size else None
        for x, v in summary_lock_times(self.summary).items():
            if x in self.t_latch and v is not None:
                self.t_latch[x] = v
        self.t_lock = {}
        for ln in LINES:
            ts = [self.t_latch.get(x) for x in self.members[ln]]
            self.t_lock[ln] = None if any(v is None for v in ts) else max(ts)
        # Lock torque of a line: sum over its hinges, zero before latching.
        self.lock_torque = {ln: np.sum([h.get("lock.%s.torque" % x, np.zeros_like(self.t)) for x in self.members[ln]], axis=0)
                            for ln in LINES}
        # Cable torques per loop and line.
        self.cables = {}
        for c in h:
            m = re.match(r"cable\.(.+)\.torque\.(.+)$", c)
            if m:
                loop, hinge = m.group(1), m.group(2)
                d = self.cables.setdefault(loop, {})
                ln = line_of(hinge)
                d[ln] = d.get(ln, 0.0) + h[c]
        known = [v for v in self.t_lock.values() if v is not None]
        self.t_first = min(known) if known else float(self.t[-1])
        self.all_locked = len(known) == len(LINES)

    def before_first_lock(self):
        return self.t < self.t_first

    def metrics(self):
        pre = self.before_first_lock()
        e21 = np.abs(self.phi["HL2"] - 2 * self.phi["HL1"])[pre]
        e32 = np.abs(self.phi["HL3"] - self.phi["HL2"])[pre]
        peak, impact = {}, {}
        for ln in LINES:
            first = min([self.t_latch[x] for x in self.members[ln] if self.t_latch.get(x) is not None], default=None)
            after = None if first is None else np.abs(self.lock_torque[ln][self.t >= first])
            peak[ln] = None if first is None else float(np.max(after))
            win = None if first is None else (self.t >= first) & (self.t <= first + IMPACT_WINDOW)
            impact[ln] = None if first is None else float(np.max(np.abs(self.lock_torque[ln][win])))
        known = [v for v in self.t_lock.values() if v is not None]
        res = {
            "lock_time_s": self.t_lock,
            "lock_time_per_hinge_s": self.t_latch,
            "all_locked": self.all_locked,
            "lock_time_spread_s": (max(known) - min(known)) if self.all_locked else None,
            "peak_lock_torque_Nm": peak,
            "impact_lock_torque_Nm": impact,
            "max_sync_error_21_deg": float(e21.max()) if e21.size else 0.0,
            "max_sync_error_32_deg": float(e32.max()) if e32.size else 0.0,
            "sync_error_window_s": [float(self.t[0]), self.t_first],
            "t_end_s": float(self.t[-1]),
        }
        for key in ("run_time_s", "steps", "newton_iterations", "status"):
            if key in self.summary:
                res[key] = self.summary[key]
        return res


def summary_lock_times(summary):
    """{hinge: t_latch} from summary.json, whatever of the expected layouts it has."""
    out = {}
    locks = summary.get("locks")
    if isinstance(locks, dict):
        items = locks.items()
    elif isinstance(locks, list):
        items = [(d.get("name", ""), d) for d in locks if isinstance(d, dict)]
    else:
        items = []
    for name, v in items:
        hinge = v.get("hinge") if isinstance(v, dict) else None
        hinge = hinge or re.sub(r"^lock\.", "", name)
        t = v.get("t_latch", v.get("time", v.get("lock_time"))) if isinstance(v, dict) else v
        if isinstance(t, (int, float)):
            out[hinge] = float(t)
    return out


def beam_vs_3d(beam, d3):
    """Max |phi_beam - phi_3d| over the hinge lines up to the first lock of either run [deg]."""
    t_stop = min(beam.t_first, d3.t_first)
    sel = beam.t <= t_stop
    diff = 0.0
    for ln in LINES:
        other = np.interp(beam.t[sel], d3.t, d3.phi[ln])
        diff = max(diff, float(np.max(np.abs(beam.phi[ln][sel] - other))))
    return diff, t_stop


def ratio(a, b):
    return None if (a is None or b is None or b == 0) else a / b


def fmt(x, f="%.3f"):
    return "-" if x is None else f % x


def plot_case(plt, c, path):
    sync = bool(c.cables)
    n = 3 if sync else 2
    fig, ax = plt.subplots(n, 1, figsize=(7.5, 2.6 * n + 0.6), sharex=True)
    colors = {"HL1": "C0", "HL2": "C1", "HL3": "C2"}
    for ln in LINES:
        ax[0].plot(c.t, c.phi[ln], color=colors[ln], label=ln)
        tl = c.t_lock[ln]
        if tl is not None:
            ax[0].axvline(tl, color=colors[ln], ls=":", lw=1)
            ax[0].plot([tl], [LOCK_DEG[ln]], "o", color=colors[ln], ms=5)
    ax[0].set_ylabel("hinge angle [deg]")
    ax[0].set_title(c.name + ": hinge angles (dots: lock instants)")
    ax[0].legend(loc="lower right", fontsize=8)
    ax[0].grid(alpha=0.3)
    for ln in LINES:
        first = min([c.t_latch[x] for x in c.members[ln] if c.t_latch.get(x) is not None], default=None)
        if first is None:
            continue
        y = np.where(c.t >= first, c.lock_torque[ln], np.nan)
        ax[1].plot(c.t, y, color=colors[ln], label=ln)
    ax[1].set_ylabel("lock torque [N m]")
    ax[1].set_title("lock torques after locking")
    ax[1].legend(loc="upper right", fontsize=8)
    ax[1].grid(alpha=0.3)
    if sync:
        for loop, d in sorted(c.cables.items()):
            for ln, tau in sorted(d.items()):
                ax[2].plot(c.t, tau, label="%s on %s" % (loop, ln))
        ax[2].set_ylabel("cable torque [N m]")
        ax[2].set_title("synchronisation cable torques")
        ax[2].legend(loc="upper right", fontsize=8)
        ax[2].grid(alpha=0.3)
    ax[-1].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(path, dpi=72)
    plt.close(fig)


def plot_overlay(plt, cases, path):
    fig, ax = plt.subplots(2, 2, figsize=(11, 6.4))
    for j, kind in enumerate(["unsync", "sync"]):
        b, d = cases[kind + "-beam"], cases[kind + "-3d"]
        for ln, col in zip(LINES, ["C0", "C1", "C2"]):
            ax[0, j].plot(b.t, b.phi[ln], color=col, label=ln + " beam-like")
            ax[0, j].plot(d.t, d.phi[ln], color=col, ls="--", label=ln + " 3D")
        ax[0, j].set_title("%s: beam-like (solid) and 3D (dashed)" % kind)
        ax[0, j].set_ylabel("hinge angle [deg]")
        ax[0, j].grid(alpha=0.3)
        ax[0, j].legend(fontsize=7, ncol=2, loc="lower right")
        t_stop = min(b.t_first, d.t_first)
        sel = b.t <= t_stop
        for ln, col in zip(LINES, ["C0", "C1", "C2"]):
            ax[1, j].plot(b.t[sel], np.interp(b.t[sel], d.t, d.phi[ln]) - b.phi[ln][sel], color=col, label=ln)
        ax[1, j].set_title("3D - beam-like up to the first lock (t = %.3f s)" % t_stop)
        ax[1, j].set_ylabel("angle difference [deg]")
        ax[1, j].set_xlabel("time [s]")
        ax[1, j].grid(alpha=0.3)
        ax[1, j].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=66)
    plt.close(fig)


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 2
    out = argv[1]
    do_plots = "--no-plots" not in argv
    cases = {name: Case(out, name) for name in CASES}
    metrics = {"cases": {name: c.metrics() for name, c in cases.items()}, "comparisons": {}}
    cmp_ = metrics["comparisons"]
    for model in ("beam", "3d"):
        u, s = metrics["cases"]["unsync-" + model], metrics["cases"]["sync-" + model]
        cmp_["unsync_over_sync_" + model] = {
            "sync_error_21": ratio(u["max_sync_error_21_deg"], s["max_sync_error_21_deg"]),
            "sync_error_32": ratio(u["max_sync_error_32_deg"], s["max_sync_error_32_deg"]),
            "lock_time_spread": ratio(u["lock_time_spread_s"], s["lock_time_spread_s"]),
        }
    for kind in ("unsync", "sync"):
        diff, t_stop = beam_vs_3d(cases[kind + "-beam"], cases[kind + "-3d"])
        cmp_["beam_vs_3d_" + kind] = {"max_angle_difference_deg": diff, "up_to_s": t_stop}
    with open(os.path.join(out, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=2)
        f.write("\n")

    lines = []
    w = lines.append
    w("%-12s %8s %8s %8s %8s | %9s %9s %9s | %9s %9s | %7s" % ("case", "t HL1", "t HL2", "t HL3", "spread", "Tlk HL1", "Tlk HL2",
                                                             "Tlk HL3", "|p2-2p1|", "|p3-p2|", "run"))
    w("%-12s %8s %8s %8s %8s | %9s %9s %9s | %9s %9s | %7s" % ("", "[s]", "[s]", "[s]", "[s]", "[N m]", "[N m]", "[N m]", "[deg]",
                                                             "[deg]", "[s]"))
    for name in CASES:
        m = metrics["cases"][name]
        w("%-12s %8s %8s %8s %8s | %9s %9s %9s | %9s %9s | %7s" % (
            name, fmt(m["lock_time_s"]["HL1"]), fmt(m["lock_time_s"]["HL2"]), fmt(m["lock_time_s"]["HL3"]),
            fmt(m["lock_time_spread_s"]), fmt(m["peak_lock_torque_Nm"]["HL1"], "%.1f"), fmt(m["peak_lock_torque_Nm"]["HL2"], "%.1f"),
            fmt(m["peak_lock_torque_Nm"]["HL3"], "%.1f"), fmt(m["max_sync_error_21_deg"], "%.3f"),
            fmt(m["max_sync_error_32_deg"], "%.3f"), fmt(m.get("run_time_s"), "%.2f")))
    for model in ("beam", "3d"):
        r = cmp_["unsync_over_sync_" + model]
        w("unsync/sync (%s): |phi2-2phi1| x%s, |phi3-phi2| x%s, lock-time spread x%s" % (
            model, fmt(r["sync_error_21"], "%.1f"), fmt(r["sync_error_32"], "%.1f"), fmt(r["lock_time_spread"], "%.1f")))
    for kind in ("unsync", "sync"):
        r = cmp_["beam_vs_3d_" + kind]
        w("beam-like vs 3D (%s): max angle difference %.3f deg up to t = %.3f s" % (kind, r["max_angle_difference_deg"], r["up_to_s"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "results.txt"), "w") as f:
        f.write(text)
    print(text, end="")

    if do_plots:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        os.makedirs(os.path.join(out, "plots"), exist_ok=True)
        global _PLOTS
        _PLOTS = [(plot_case, (plt, c, os.path.join(out, "plots", name + ".png"))) for name, c in cases.items()]
        _PLOTS.append((plot_overlay, (plt, cases, os.path.join(out, "plots", "beam-vs-3d.png"))))
        # The five figures in $SEFLEX_JOBS processes (forked after matplotlib is imported: no re-import).
        try:
            jobs = int(os.environ.get("SEFLEX_JOBS", os.cpu_count() or 1))
        except ValueError:
            jobs = 1
        jobs = max(1, min(len(_PLOTS), jobs))
        if jobs > 1:
            import multiprocessing
            with multiprocessing.get_context("fork").Pool(jobs) as pool:
                pool.map(_draw, range(len(_PLOTS)))
        else:
            for k in range(len(_PLOTS)):
                _draw(k)
    return 0


_PLOTS = []


def _draw(k):
    f, args = _PLOTS[k]
    f(*args)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
