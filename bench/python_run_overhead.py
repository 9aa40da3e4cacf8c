#!/usr/bin/env python3
"""CPU of the sync-3d deployment run from Python (seflex.run in this process) against `seflex run` (a
child process), side by side, alternating, medians of N runs each (issue 42: at most 5 % more).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_run_overhead.py build/apps/seflex [--repeat 7] [--scene SCENE.yaml]

Without --scene it makes the demo's sync-3d in a temporary folder: the 3D superelements with 10
modes (`seflex reduce`, as scripts/demo.sh) and examples/solar_array/sync-3d.yaml. Every run writes
the same files (history, events, poses, summary; no animation: the command's --no-animation).
Columns:
  command        user+sys CPU of the whole `seflex run` process (start-up, reading the superelements,
                 building the scene, integrating, writing), getrusage(RUSAGE_CHILDREN)
  python         user+sys CPU of seflex.run(path) in this process (resource.getrusage(RUSAGE_SELF)
                 around the call: reading, building, integrating, writing, and the result's arrays)
  python Scene   the same with a Scene loaded and edited in Python (one spring preload + 1 %), run from
                 its YAML text
  python process a whole `python3 -c "import seflex; seflex.run(...)"` process (interpreter start-up
                 and the import of numpy and seflex included), getrusage(RUSAGE_CHILDREN)
"""
import argparse
import os
import pathlib
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def self_cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def run_child(cmd):
    c0 = child_cpu()
    subprocess.run(cmd, check=True, capture_output=True)
    return child_cpu() - c0


def make_sync_3d(exe, tmp):
    (tmp / "superelements").mkdir()
    for body, interface in (("yoke", "1,3,4"), ("panel", "1,2,3,4")):
        subprocess.run([exe, "reduce", ROOT / "meshes" / f"{body}.bdf", "--interface", interface, "--modes", "10",
                        "--name", f"{body}-3d", "-o", tmp / "superelements" / f"{body}-3d.se"], check=True, capture_output=True)
    shutil.copy(ROOT / "examples" / "solar_array" / "sync-3d.yaml", tmp / "sync-3d.yaml")
    return tmp / "sync-3d.yaml"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("seflex", help="the seflex command (build/apps/seflex)")
    ap.add_argument("--scene", help="a scene file (default: the demo's sync-3d, made in a temporary folder)")
    ap.add_argument("--repeat", type=int, default=7)
    a = ap.parse_args()
    import seflex  # not at the top: bench/lib/check_imports.py loads every script without the module's path

    exe = os.path.abspath(a.seflex)
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="seflex-bench-"))
    scene_path = pathlib.Path(a.scene) if a.scene else make_sync_3d(exe, tmp)
    edited = seflex.Scene.load(scene_path)
    edited.springs[0].preload *= 1.01
    child = [sys.executable, "-c", f"import seflex; seflex.run({str(scene_path)!r}, output={str(tmp / 'pp')!r}, overwrite=True)"]
    times = {"command": [], "python": [], "python Scene": [], "python process": []}
    for _ in range(a.repeat):
        times["command"].append(run_child([exe, "run", scene_path, "-o", tmp / "cmd", "--force", "--no-animation"]))
        c0 = self_cpu()
        r = seflex.run(scene_path, output=tmp / "py", overwrite=True)
        times["python"].append(self_cpu() - c0)
        c0 = self_cpu()
        seflex.run(edited, output=tmp / "pys", overwrite=True)
        times["python Scene"].append(self_cpu() - c0)
        times["python process"].append(run_child(child))
    shutil.rmtree(tmp)
    print(f"$ {' '.join(sys.argv)}")
    print(f"scene {scene_path.name}: {r.summary['dofs']} dofs, {r.summary['steps']} steps, {r.summary['final_t']:.3f} s simulated; "
          f"{a.repeat} runs each, alternating; user+sys CPU [s]")
    print(f"  {'':15s} {'median':>8s} {'min':>8s} {'max':>8s} {'/ command':>10s} {'paired':>8s}")
    base = statistics.median(times["command"])
    for k, v in times.items():
        m = statistics.median(v)
        paired = statistics.median(x / c for x, c in zip(v, times["command"]))
        print(f"  {k:15s} {m:8.3f} {min(v):8.3f} {max(v):8.3f} {m / base:10.3f} {paired:8.3f}")
    print("  (/ command: ratio of the medians; paired: median of the ratios of the runs made one after the other)")


if __name__ == "__main__":
    main()
