#!/usr/bin/env python3
"""CPU of a scene run from Python (seflex.run in this process) against `seflex run` (a child process),
side by side, alternating, medians of N runs each; optionally a second command (e.g. a build of main)
as a third column. Both write the same files (history, events, poses, summary; no animation).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_run_overhead.py build/apps/seflex SCENE.yaml \
        [--repeat 5] [--other /path/to/another/seflex]

The command's CPU is its whole process (start-up, reading the superelements, building the scene,
integrating, writing), from getrusage(RUSAGE_CHILDREN); Python's is time.process_time() around
seflex.run (the same work without the process start-up; the import is done before).
"""
import argparse
import resource
import shutil
import statistics
import subprocess
import tempfile
import time

import seflex


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_command(exe, scene, out):
    c0 = child_cpu()
    subprocess.run([exe, "run", scene, "-o", out, "--force", "--no-animation"], check=True, capture_output=True)
    return child_cpu() - c0


def run_python(scene, out):
    c0 = time.process_time()
    seflex.run(scene, output=out, overwrite=True)
    return time.process_time() - c0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("seflex")
    ap.add_argument("scene")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--other", help="another seflex executable, measured the same way")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp()
    times = {"command": [], "python": []}
    if a.other:
        times["other"] = []
    for _ in range(a.repeat):
        times["command"].append(run_command(a.seflex, a.scene, f"{tmp}/cmd"))
        times["python"].append(run_python(a.scene, f"{tmp}/py"))
        if a.other:
            times["other"].append(run_command(a.other, a.scene, f"{tmp}/other"))
    shutil.rmtree(tmp)
    print(f"scene {a.scene}, {a.repeat} runs each, CPU seconds (median, min, max)")
    for k, v in times.items():
        print(f"  {k:8s} {statistics.median(v):8.3f} {min(v):8.3f} {max(v):8.3f}")
    m = statistics.median(times["python"]) / statistics.median(times["command"])
    print(f"python / command = {m:.3f}")
    if a.other:
        print(f"command / other = {statistics.median(times['command']) / statistics.median(times['other']):.3f}")


if __name__ == "__main__":
    main()
