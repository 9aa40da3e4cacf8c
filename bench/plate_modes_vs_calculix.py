#!/usr/bin/python3
"""Speed of `seflex modes` against CalculiX on clamped square CQUAD4 / S4 plates (issue 3).

For each size it writes the same plate twice - a Nastran deck for seflex (CQUAD4, PSHELL, EIGRL
ND = 20) and a CalculiX input (S4 shells, *FREQUENCY 20) - with the same grids, elements,
material and clamped edges, runs both under /usr/bin/time -v, and prints wall time, peak memory
(maximum resident set size), their ratios and the first frequencies of both (the elements differ:
MITC4 + lumped mass in seflex, S4 expanded to C3D8I with consistent mass in CalculiX, so the
frequencies agree to a few per cent, not exactly).

usage: bench/plate_modes_vs_calculix.py [--sizes 40,129,408] [--seflex build/apps/seflex]
                                       [--ccx ccx] [--keep DIR] [--threads 2] [--only seflex|ccx]
                                       [--decks-only]
Sizes are elements per side: 40 -> 10,086 dofs, 129 -> 101,400 dofs, 408 -> 1,003,686 dofs
(6 dofs per grid before the edge constraints). CalculiX is found as --ccx, else $CCX, else `ccx`
on PATH (Debian package calculix-ccx; a benchmark-only dependency).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/: the shared helpers in bench/lib/
from lib.plate import MODES, SIDE, THICKNESS, ccx_frequencies, seflex_frequencies, write_calculix, write_nastran  # noqa: E402


def timed(cmd, cwd, env):
    """Run cmd under /usr/bin/time -v; returns (wall seconds, peak RSS in MB, stdout)."""
    t0 = time.monotonic()
    p = subprocess.run(["/usr/bin/time", "-v"] + cmd, cwd=cwd, env=env, capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s\n%s" % (p.returncode, " ".join(cmd), p.stdout[-2000:], p.stderr[-2000:]))
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)
    return wall, int(m.group(1)) / 1024.0, p.stdout


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default="40,129,408")
    ap.add_argument("--seflex", default=os.path.join(root, "build", "apps", "seflex"))
    ap.add_argument("--ccx", default=os.environ.get("CCX", "ccx"))
    ap.add_argument("--keep", help="write the decks and results here instead of a temporary folder")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", choices=["seflex", "ccx"])
    ap.add_argument("--decks-only", action="store_true",
                    help="write DIR/nN/plate.bdf and plate.inp (with --keep DIR) and stop; e.g. for bench/factorization_backends")
    args = ap.parse_args()
    ccx = shutil.which(args.ccx)
    if args.only != "seflex" and ccx is None:
        sys.exit("CalculiX not found (--ccx, $CCX or `ccx` on PATH; Debian package calculix-ccx)")
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads), OPENBLAS_NUM_THREADS=str(args.threads),
               CCX_NPROC_EQUATION_SOLVER=str(args.threads))
    work = args.keep or tempfile.mkdtemp(prefix="seflex-bench-")
    os.makedirs(work, exist_ok=True)
    print("command: %s" % " ".join([os.path.relpath(sys.argv[0], root) if sys.argv[0].startswith(root) else sys.argv[0]] + sys.argv[1:]))
    print("threads %d, %d lowest modes, clamped steel plate %g m x %g m x %g m\n" % (args.threads, MODES, SIDE, SIDE, THICKNESS))
    print("%6s %10s | %10s %10s | %10s %10s | %7s %7s | %9s %9s" % (
        "n", "dofs", "seflex s", "seflex MB", "ccx s", "ccx MB", "t ratio", "m ratio", "f1 seflex", "f1 ccx"))
    for n in [int(s) for s in args.sizes.split(",")]:
        dofs = 6 * (n + 1) ** 2
        d = os.path.join(work, "n%d" % n)
        os.makedirs(d, exist_ok=True)
        write_nastran(os.path.join(d, "plate.bdf"), n)
        write_calculix(os.path.join(d, "plate.inp"), n)
        if args.decks_only:
            print("%6d %10d   %s" % (n, dofs, os.path.join(d, "plate.bdf")))
            continue
        ts = ms = tc = mc = float("nan")
        fs, fc = [float("nan")], [float("nan")]
        if args.only != "ccx":
            csv = os.path.join(d, "seflex.csv")
            if os.path.exists(csv):
                os.remove(csv)
            ts, ms, out = timed([args.seflex, "modes", "plate.bdf", "--csv", "seflex.csv"], d, env)
            with open(os.path.join(d, "seflex.out"), "w") as f:
                f.write(out)
            fs = seflex_frequencies(csv)
        if args.only != "seflex":
            tc, mc, _ = timed([ccx, "-i", "plate"], d, env)
            fc = ccx_frequencies(os.path.join(d, "plate.dat"))
        print("%6d %10d | %10.2f %10.0f | %10.2f %10.0f | %7.2f %7.2f | %9.3f %9.3f" % (
            n, dofs, ts, ms, tc, mc, tc / ts, mc / ms, fs[0], fc[0]), flush=True)
        if len(fs) == len(fc) == MODES:
            dev = max(abs(a / b - 1) for a, b in zip(fs, fc))
            print("%6s %10s   modes 1-%d: largest seflex/ccx frequency difference %.2f %%" % ("", "", MODES, 100 * dev))
    if not args.decks_only:
        print("\n(t ratio, m ratio: CalculiX time and peak memory over seflex's; files in %s)" % work)


if __name__ == "__main__":
    main()
