"""Error measures of the speed-against-accuracy studies (bench/study.py, bench/demo_speed_accuracy.py,
bench/stability.py): the spin-up beam's frame lag, the solar array's hinge-line angles, lock times and
peak lock torques, each against a reference run."""
import csv
import os
import re

import numpy as np

from lib.runs import read_history


def lines_of(hist):
    """Hinge-line angles [deg]: 3D hinge pairs HLna/HLnb averaged into HLn."""
    out = {}
    for k, v in hist.items():
        m = re.match(r"(.+?)([ab]?)\.phi_deg$", k)
        if m and k.endswith(".phi_deg"):
            out.setdefault(m.group(1), []).append(v)
    return {k: np.mean(v, axis=0) for k, v in out.items()}


def lock_lines(locks):
    """Per hinge line: first latch time, sum of the peak torques (3D: two locks share a line)."""
    out = {}
    for name, l in locks.items():
        line = re.sub(r"^lock\.", "", name)
        line = re.sub(r"(HL\d)[ab]$", r"\1", line)
        t, p = out.get(line, (None, 0.0))
        if l["t_latch"] is not None:
            t = l["t_latch"] if t is None else min(t, l["t_latch"])
            p += l["peak_abs_torque_after_latch"]
        out[line] = (t, p)
    return out


def spinup_lag(folder):
    h = read_history(os.path.join(folder, "history.csv"))
    t_h, hub = h["t"], np.radians(h["hub.phi_deg"])
    with open(os.path.join(folder, "poses.csv")) as f:
        rows = list(csv.reader(f))[1:]
    t = np.array([float(r[0]) for r in rows])
    ang = np.unwrap(np.array([np.arctan2(float(r[5]), float(r[2])) for r in rows]))  # R10, R00
    return t, np.degrees(ang - np.interp(t, t_h, hub))


def errors_spinup(r, ref):
    if r["status"] != "ok":
        return dict(angle_err_deg=np.inf)
    t0, l0 = ref
    t, l = spinup_lag(r["folder"])
    T = min(t[-1], t0[-1])
    g = t0[t0 <= T]
    return dict(angle_err_deg=float(np.max(np.abs(np.interp(g, t, l) - np.interp(g, t0, l0)))), ref_scale_deg=float(np.max(np.abs(l0))))


def errors_solar(r, ref_r):
    if r["status"] != "ok":
        return dict(angle_err_deg=np.inf, lock_time_err_s=np.inf, lock_torque_rel_err=np.inf)
    h0, h = read_history(os.path.join(ref_r["folder"], "history.csv")), read_history(os.path.join(r["folder"], "history.csv"))
    L0, L = lines_of(h0), lines_of(h)
    k0, k = lock_lines(ref_r["locks"]), lock_lines(r["locks"])
    T = max(t for t, _ in k0.values() if t is not None)  # up to the reference's last lock
    g = h0["t"][h0["t"] <= T]
    ang = max(float(np.max(np.abs(np.interp(g, h["t"], L[n]) - np.interp(g, h0["t"], L0[n])))) for n in L0 if n in L)
    lt = max(abs((k[n][0] if k.get(n, (None,))[0] is not None else np.inf) - k0[n][0]) for n in k0)
    lq = max(abs(k[n][1] - k0[n][1]) / k0[n][1] if n in k else np.inf for n in k0)
    return dict(angle_err_deg=ang, lock_time_err_s=lt, lock_torque_rel_err=lq)


def errors_hinges(folder, summary, ref_folder, ref_summary):
    """Every hinge measure of a run against a reference run: errors_solar's lock times, peak lock torques
    and hinge-line angles to the reference's last lock (when the reference locks at all), and the
    largest hinge-line angle difference over the whole run, angle_run_deg [deg]."""
    r = dict(folder=folder, status=summary["status"], locks=summary["locks"])
    ref = dict(folder=ref_folder, status=ref_summary["status"], locks=ref_summary["locks"])
    e = errors_solar(r, ref) if any(l["t_latch"] is not None for l in ref_summary["locks"].values()) else {}
    if summary["status"] != "ok":
        e["angle_run_deg"] = np.inf
        return e
    h0 = read_history(os.path.join(ref_folder, "history.csv"))
    h = read_history(os.path.join(folder, "history.csv"))
    L0, L = lines_of(h0), lines_of(h)
    # Up to the earlier of the two runs' last samples but one: the last is the run's end state, off
    # the output grid (the step that passes the stop time), and a reference time between a run's last
    # two samples would compare the reference with a straight line through the ringing (sync-3d,
    # Radau at 1e-6: 0.0093 deg there against 0.00027 deg before it).
    g = h0["t"][h0["t"] <= min(h["t"][-2], h0["t"][-2])] if min(len(h["t"]), len(h0["t"])) > 1 else h0["t"][:1]
    e["angle_run_deg"] = max(float(np.max(np.abs(np.interp(g, h["t"], L[n]) - np.interp(g, h0["t"], L0[n])))) for n in L0)
    return e
