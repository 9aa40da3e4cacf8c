#!/usr/bin/python3
"""How many fixed-interface modes the solar-array demo needs (docs/solar-array-results.md, "Number of
fixed-interface modes"): reruns the demo's scenes with other mode counts per superelement.

    /usr/bin/python3 scripts/solar_array_modes_study.py [--seflex build/apps/seflex] [--out DIR]
                                                        [--jobs 2] [--configs ...]

Each configuration is "CASE REDUCTION YOKE_MODES PANEL_MODES" (e.g. "unsync beam 10 22"); the default
set is the one the document reports: unsynchronised and synchronised beam-like runs with 0, 5, 10
and 20 modes on both bodies, and the lock torques of the unsynchronised 3D model with 10 and 20 and
of the beam-like model with 10/10, 14/10, 10/15, 10/22 and 14/22. Superelements are reduced as
scripts/demo.sh does (same interface sets), scenes are the demo's (examples/solar_array) with the
superelement paths changed; runs go to the end (5 s after the last lock). Prints a table (lock times,
impact and peak lock torques as scripts/plot_solar_array.py defines them, steps, CPU time) and the
command that made it.
"""
import argparse
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import plot_solar_array as psa  # noqa: E402

SETS = {("yoke", "beam"): "1,5", ("panel", "beam"): "5,6", ("yoke", "3d"): "1,3,4", ("panel", "3d"): "1,2,3,4"}
DEFAULT = ["unsync beam %d %d" % (m, m) for m in (0, 5, 10, 20)] + ["sync beam %d %d" % (m, m) for m in (0, 5, 10, 20)] + [
    "unsync 3d 10 10", "unsync 3d 20 20", "unsync beam 14 10", "unsync beam 10 15", "unsync beam 10 22", "unsync beam 14 22"]


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed: %s\n%s%s" % (" ".join(cmd), p.stdout[-2000:], p.stderr[-2000:]))


def superelement(seflex, out, body, red, modes):
    path = os.path.join(out, "superelements", "%s-%s-%d.se" % (body, red, modes))
    if not os.path.exists(path):
        run([seflex, "reduce", os.path.join(ROOT, "meshes", body + ".bdf"), "--interface", SETS[(body, red)],
             "--modes", str(modes), "--name", "%s-%s" % (body, red), "-o", path, "--force"])
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seflex", default=os.path.join(ROOT, "build", "apps", "seflex"))
    ap.add_argument("--out", default="modes-study")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--configs", nargs="*", default=DEFAULT)
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(os.path.join(out, "superelements"), exist_ok=True)
    print("command: %s" % " ".join([os.path.relpath(os.path.abspath(sys.argv[0]), ROOT)] + sys.argv[1:]))
    configs = [c.split() for c in a.configs]
    for case, red, ym, pm in configs:  # reductions first (shared between runs)
        superelement(a.seflex, out, "yoke", red, int(ym))
        superelement(a.seflex, out, "panel", red, int(pm))

    def one(cfg):
        case, red, ym, pm = cfg
        name = "%s-%s-y%s-p%s" % (case, red, ym, pm)
        scene = open(os.path.join(ROOT, "examples", "solar_array", "%s-%s.yaml" % (case, red))).read()
        scene = scene.replace("superelements/yoke-%s.se" % red, superelement(a.seflex, out, "yoke", red, int(ym)))
        scene = scene.replace("superelements/panel-%s.se" % red, superelement(a.seflex, out, "panel", red, int(pm)))
        yml = os.path.join(out, name + ".yaml")
        with open(yml, "w") as f:
            f.write(scene)
        run([a.seflex, "run", yml, "-o", os.path.join(out, name), "--force", "--no-animation"])
        return name, psa.Case(out, name).metrics()

    with ThreadPoolExecutor(max_workers=a.jobs) as ex:
        results = list(ex.map(one, configs))
    print("\n| case | reduction | yoke / panel modes | lock times HL1 / HL2 / HL3 [s] | impact torque HL1 / HL2 / HL3 [N m] "
          "| peak torque [N m] | steps | CPU [s] |")
    print("|---|---|---|---|---|---|---:|---:|")
    for (case, red, ym, pm), (name, m) in zip(configs, results):
        lt = " / ".join("%.4f" % m["lock_time_s"][ln] if m["lock_time_s"][ln] is not None else "-" for ln in psa.LINES)
        it = " / ".join("%.0f" % m["impact_lock_torque_Nm"][ln] if m["impact_lock_torque_Nm"][ln] is not None else "-" for ln in psa.LINES)
        pt = " / ".join("%.0f" % m["peak_lock_torque_Nm"][ln] if m["peak_lock_torque_Nm"][ln] is not None else "-" for ln in psa.LINES)
        s = psa.Case(out, name).summary
        print("| %s | %s | %s / %s | %s | %s | %s | %s | %.1f |" % (case, red, ym, pm, lt, it, pt, m.get("steps", "-"),
                                                                   s.get("cpu_time_s", float("nan"))))


if __name__ == "__main__":
    main()
