#!/usr/bin/python3
"""CPU time (user + system) of starting the seflex command, for one or more builds side by side.

Each build runs `seflex version` and `seflex info meshes/panel.bdf` R times, the builds taking turns
in every round (a busy spell of the shared machine hits all of them); the mean CPU time per run and
the number of shared libraries loaded (ldd) are printed. The start-up is paid by every command,
every run of a scene and every CLI test.

usage: bench/startup_speed.py [--repeat R] SEFLEX [SEFLEX ...]
"""
import argparse
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def cpu_of(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=20)
    ap.add_argument("seflex", nargs="+")
    a = ap.parse_args()
    panel = os.path.join(ROOT, "meshes", "panel.bdf")
    cases = [("version", ["version"]), ("info panel.bdf", ["info", panel])]
    print("# bench/startup_speed.py --repeat %d %s   (%s, %d cores, load %s)" %
          (a.repeat, " ".join(a.seflex), time.strftime("%Y-%m-%dT%H:%MZ", time.gmtime()), os.cpu_count(),
           open("/proc/loadavg").read().split()[0]))
    totals = {(b, c): 0.0 for b in a.seflex for c, _ in cases}
    for _ in range(a.repeat):
        for b in a.seflex:
            for c, args in cases:
                totals[(b, c)] += cpu_of([b] + args)
    print("| build | shared libraries | %s |" % " | ".join("CPU of `%s` [ms]" % c for c, _ in cases))
    print("|---|---:|%s" % ("---:|" * len(cases)))
    for b in a.seflex:
        libs = subprocess.run(["ldd", b], capture_output=True, text=True).stdout.count("=>")
        print("| %s | %d | %s |" % (b, libs, " | ".join("%.1f" % (1e3 * totals[(b, c)] / a.repeat) for c, _ in cases)))


if __name__ == "__main__":
    sys.exit(main())
