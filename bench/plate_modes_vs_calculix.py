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

SIDE = 1.0        # m
THICKNESS = 0.01  # m
E, NU, RHO = 2.1e11, 0.3, 7850.0
MODES = 20


def real(x):
    """A Nastran real: always with a decimal point or exponent."""
    t = "%.9g" % x
    if "." in t:
        return t
    return t.replace("e", ".e") if "e" in t else t + "."  # 7e-08 -> 7.e-08: Nastran reals carry a point


def grid_id(i, j, n):
    return 1 + i + (n + 1) * j


def boundary(n):
    return [grid_id(i, j, n) for j in range(n + 1) for i in range(n + 1) if i in (0, n) or j in (0, n)]


def write_nastran(path, n):
    h = SIDE / n
    with open(path, "w") as f:
        f.write("SOL 103\nCEND\nTITLE = clamped square plate %d x %d CQUAD4\nSPC = 1\nMETHOD = 1\nBEGIN BULK\n" % (n, n))
        f.write("EIGRL,1,,,%d\n" % MODES)
        f.write("MAT1,1,%.6e,,%.3f,%.1f\n" % (E, NU, RHO))
        f.write("PSHELL,1,1,%s,1,,1\n" % real(THICKNESS))
        out = []
        for j in range(n + 1):
            for i in range(n + 1):
                out.append("GRID,%d,,%s,%s,0.\n" % (grid_id(i, j, n), real(i * h), real(j * h)))
        eid = 1
        for j in range(n):
            for i in range(n):
                g = grid_id(i, j, n)
                out.append("CQUAD4,%d,1,%d,%d,%d,%d\n" % (eid, g, g + 1, g + n + 2, g + n + 1))
                eid += 1
        for g in boundary(n):
            out.append("SPC1,1,123456,%d\n" % g)
        f.write("".join(out))
        f.write("ENDDATA\n")


def write_calculix(path, n):
    h = SIDE / n
    with open(path, "w") as f:
        f.write("*HEADING\nclamped square plate %d x %d S4\n*NODE\n" % (n, n))
        out = []
        for j in range(n + 1):
            for i in range(n + 1):
                out.append("%d,%.9g,%.9g,0.\n" % (grid_id(i, j, n), i * h, j * h))
        out.append("*ELEMENT,TYPE=S4,ELSET=PLATE\n")
        eid = 1
        for j in range(n):
            for i in range(n):
                g = grid_id(i, j, n)
                out.append("%d,%d,%d,%d,%d\n" % (eid, g, g + 1, g + n + 2, g + n + 1))
                eid += 1
        out.append("*NSET,NSET=EDGE\n")
        b = boundary(n)
        for k in range(0, len(b), 16):
            out.append(",".join(str(g) for g in b[k:k + 16]) + "\n")
        f.write("".join(out))
        f.write("*BOUNDARY\nEDGE,1,6\n*MATERIAL,NAME=STEEL\n*ELASTIC\n%.6e,%.3f\n*DENSITY\n%.1f\n" % (E, NU, RHO))
        f.write("*SHELL SECTION,ELSET=PLATE,MATERIAL=STEEL\n%g\n*STEP\n*FREQUENCY\n%d\n*END STEP\n" % (THICKNESS, MODES))


def timed(cmd, cwd, env):
    """Run cmd under /usr/bin/time -v; returns (wall seconds, peak RSS in MB, stdout)."""
    t0 = time.monotonic()
    p = subprocess.run(["/usr/bin/time", "-v"] + cmd, cwd=cwd, env=env, capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s\n%s" % (p.returncode, " ".join(cmd), p.stdout[-2000:], p.stderr[-2000:]))
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)
    return wall, int(m.group(1)) / 1024.0, p.stdout


def seflex_frequencies(csv):
    with open(csv) as f:
        next(f)
        return [float(line.split(",")[2]) for line in f]


def ccx_frequencies(dat):
    freqs, on = [], False
    with open(dat) as f:
        for line in f:
            if "E I G E N V A L U E   O U T P U T" in line:
                on = True
                continue
            if on:
                w = line.split()
                if len(w) == 5 and w[0].isdigit():
                    freqs.append(float(w[3]))
                elif freqs and not w:
                    break
    return freqs


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
