#!/usr/bin/python3
"""The distributed backend (`--backend slepc`, issue 16) side by side with the serial one on the clamped
square CQUAD4 plates of bench/plate_modes_vs_calculix.py (EIGRL ND = 20).

For each size it runs, one after the other:
  serial      seflex modes plate.bdf                               (block Lanczos on CHOLMOD)
  slepc P=1   mpirun -n 1 seflex modes plate.bdf --backend slepc   (Krylov-Schur on MUMPS)
  slepc P=2   mpirun -n 2 seflex modes plate.bdf --backend slepc
every process under /usr/bin/time -v, and prints wall time, peak RSS of each rank, the largest
relative eigenvalue difference to the serial run, the solve phases seflex prints and, for the
distributed runs, how the matrices were assembled (partitioned by METIS: rank 0's share of the
elements and rows; or replicated, and why).

usage: bench/distributed_modes.py [--sizes 40,129,408] [--seflex build/apps/seflex] [--ranks 1,2]
                                  [--keep DIR] [--threads 1]
Sizes are elements per side: 40 -> 10,086 dofs, 129 -> 101,400, 408 -> 1,003,686, 577 -> 2,004,606.
BLAS threads per process: --threads (default 1, so that 2 ranks on 2 cores do not oversubscribe;
the serial run gets the same count).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib.plate import write_nastran  # noqa: E402  (the same plate decks as bench/plate_modes_vs_calculix.py)


def run(cmd, env):
    """Wall seconds, list of peak RSS (MB) of every /usr/bin/time -v block in stderr, stdout."""
    t0 = time.monotonic()
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s\n%s" % (p.returncode, " ".join(cmd), p.stdout[-2000:], p.stderr[-3000:]))
    rss = [int(m) / 1024.0 for m in re.findall(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)]
    return wall, rss, p.stdout


def eigenvalues(csv):
    with open(csv) as f:
        next(f)
        return [float(line.split(",")[1]) for line in f]


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default="40,129,408")
    ap.add_argument("--seflex", default=os.path.join(root, "build", "apps", "seflex"))
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--keep", default=None, help="keep the decks and outputs in this folder")
    a = ap.parse_args()
    env = dict(os.environ)
    for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
        env[k] = str(a.threads)
    if os.geteuid() == 0:  # OpenMPI refuses root unless told (containers, CI)
        env["OMPI_ALLOW_RUN_AS_ROOT"] = env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
    work = a.keep or tempfile.mkdtemp(prefix="seflex-dist-")
    os.makedirs(work, exist_ok=True)
    print("# %s, load average %s, BLAS threads %d" % (time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                                                      " ".join("%.2f" % x for x in os.getloadavg()), a.threads))
    print("| N | dofs | run | wall | peak RSS per rank | sum RSS | max rel. eigenvalue diff to serial | solve line |")
    print("|---|---|---|---|---|---|---|---|")
    for n in [int(s) for s in a.sizes.split(",")]:
        deck = os.path.join(work, "plate%d.bdf" % n)
        write_nastran(deck, n)
        dofs = 6 * (n + 1) ** 2  # before the edge constraints, as the other plate tables count
        runs = [("serial", ["/usr/bin/time", "-v", a.seflex, "modes", deck], "serial")]
        for p in [int(r) for r in a.ranks.split(",")]:
            runs.append(("slepc P=%d" % p, [a.mpirun, "-n", str(p), "/usr/bin/time", "-v", a.seflex, "modes", deck,
                                           "--backend", "slepc"], "p%d" % p))
        ref = None
        for name, cmd, tag in runs:
            csv = os.path.join(work, "plate%d_%s.csv" % (n, tag))
            wall, rss, out = run(cmd + ["--csv", csv, "--force"], env)
            lam = eigenvalues(csv)
            if ref is None:
                ref = lam
            diff = max(abs(x - y) / abs(y) for x, y in zip(lam, ref))
            solve = re.search(r"time: (.*)", out)
            assembly = re.search(r"assembly: (.*)", out)  # distributed runs: partitioned or replicated
            print("| %d | %s | %s | %.2f s | %s | %s MB | %.1e | %s%s |" % (
                n, format(dofs, ","), name, wall, ", ".join("%s MB" % format(round(r), ",") for r in rss),
                format(round(sum(rss)), ","), diff, solve.group(1) if solve else "",
                "; assembly " + assembly.group(1) if assembly else ""), flush=True)
    print("\ncommand: %s" % " ".join(sys.argv))


if __name__ == "__main__":
    main()
