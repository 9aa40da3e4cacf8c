#!/usr/bin/python3
"""seflex against MYSTRAN's published benchmark answers (issue 13).

MYSTRAN (github.com/MYSTRANsolver/MYSTRAN_Benchmark, Archive/Benchmark_Runs_12.0/MYSTRAN_12.0_TestRuns.zip)
publishes its test decks (TestRuns/<Eigen|Static>/<Sparse|Banded>/Current/*.DAT) with MYSTRAN 12.0's
answers (TestRuns/.../Archive/*.arc: MYSTRAN's ANS output, the F06 tables of the results).
The decks are fetched data: unpack the zip outside the repository and point --decks at it:

    git clone https://github.com/MYSTRANsolver/MYSTRAN_Benchmark /tmp/MYSTRAN_Benchmark
    git -C /tmp/MYSTRAN_Benchmark show \\
        HEAD:Archive/Benchmark_Runs_12.0/MYSTRAN_12.0_TestRuns.zip > /tmp/mystran.zip
    mkdir -p /work/data/mystran && cd /work/data/mystran && unzip -q /tmp/mystran.zip
    bench/mystran_benchmark.py --decks /work/data/mystran/TestRuns/Eigen/Sparse \\
        --decks /work/data/mystran/TestRuns/Static/Sparse [--seflex build/apps/seflex] [--markdown]

Every *.DAT below each --decks folder with an answer file (../Archive/<name>.arc, or <name>.arc,
.ans or .f06 beside it) is run:
- SOL 1/101/STATIC(S): `seflex static DECK --subcase ID --system global` for each subcase MYSTRAN
  printed; the displacement tables are compared. Error of a subcase = the largest difference over
  all grids of the translations (resp. rotations) divided by MYSTRAN's largest translation
  (rotation), that scale being at least 1e-9 of the largest value of either kind (so that
  round-off rotations of 1e-19 beside translations of 1e-2 do not count).
- SOL 3/103/MODES/SEMODES: `seflex modes DECK --csv`; every eigenvalue MYSTRAN printed is compared
  (relative error; an eigenvalue below both 1e-8 of the largest and (2 pi 1 mHz)^2 is a rigid-body
  mode, and seflex's must be below 100 times that bound).
- SOL 5/105/BUCKLING: `seflex buckling DECK --csv` when the command exists (eigenvalues = load factors).
- Other SOLs (e.g. MYSTRAN's SOL 31 Craig-Bampton) are listed as not compared.

Status of a deck:
  reproduced            every compared quantity within 1 %
  differs with warning  > 1 % off and seflex printed at least one warning (shown) explaining it
  differs silently      > 1 % off and no warning
  refused               seflex exited non-zero (its one-line reason is shown)
  not compared          a solution seflex does not offer, or no MYSTRAN answer in the file
Totals follow the table. Exit status 0 whatever the results (it is a measurement, not a gate).

--mystran-elements: each deck is copied to the temporary folder with `PARAM,QUAD4TYP,MIN4T` added
after BEGIN BULK, i.e. MYSTRAN 12.0's own default plate elements stated explicitly (CQUAD4 = MIN4T,
CTRIA3 = MIN3: PARAMS.f90 has QUAD4TYP = 'MIN4T' from MYSTRAN's first public commit ac37198 until
f593988 of April 2025 made MIN4 the default, after 12.0), and that copy is run. Without the flag
the decks run as published (seflex's default Nastran-like MITC4/MITC3 plates).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

TOL_REPRODUCED = 0.01
TOL_LOUD = 0.05


def find_answer(deck):
    d, name = os.path.split(deck)
    stem = os.path.splitext(name)[0]
    candidates = [os.path.join(os.path.dirname(d), "Archive", stem + ext) for ext in (".arc", ".ARC")]
    candidates += [os.path.join(d, stem + ext) for ext in (".arc", ".ARC", ".ans", ".ANS", ".f06", ".F06")]
    for c in candidates:
        if os.path.exists(c):
            return c
    return None


def solution_of(deck):
    """The SOL of the executive control, upper case ('1', '103', 'MODES', ...), or None."""
    with open(deck, errors="replace") as f:
        for line in f:
            t = line.split("$", 1)[0].strip().upper()
            if t.startswith("CEND") or t.startswith("BEGIN"):
                break
            m = re.match(r"SOL\s*,?\s*(\S+)", t)
            if m:
                return m.group(1)
    return None


def kind_of(sol):
    if sol in ("1", "101", "STATIC", "STATICS", "SESTATIC", "SESTATICS"):
        return "statics"
    if sol in ("3", "103", "MODES", "SEMODES", "NORMAL"):
        return "modes"
    if sol in ("5", "105", "BUCKLING", "SEBUCKL"):
        return "buckling"
    return None


NUM = r"[-+]?\d+\.\d*E[-+]\d+"


def parse_eigenvalues(text):
    """Eigenvalues of the first REAL EIGENVALUES table."""
    i = text.find("R E A L   E I G E N V A L U E S")
    if i < 0:
        return []
    vals = []
    for line in text[i:].splitlines()[3:]:
        m = re.match(r"\s+(\d+)\s+(\d+)\s+(" + NUM + ")", line)
        if m:
            vals.append(float(m.group(3)))
        elif vals and line.strip() == "":
            break
        elif vals:
            break
    return vals


def parse_displacements(text):
    """{subcase: {grid: [t1..r3]}} from the DISPLACEMENTS tables."""
    out = {}
    subcase = None
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        m = re.match(r"\s*OUTPUT FOR SUBCASE\s+(\d+)", lines[i])
        if m:
            subcase = int(m.group(1))
        if "D I S P L A C E M E N T S" in lines[i] and subcase is not None:
            table = out.setdefault(subcase, {})
            j = i + 1
            while j < len(lines) and not re.match(r"\s+GRID\s+COORD", lines[j]):
                j += 1
            j += 2
            while j < len(lines):
                m = re.match(r"\s+(\d+)\s+(-?\d+)((\s+" + NUM + "){6})\s*$", lines[j])
                if not m:
                    break
                table[int(m.group(1))] = [float(x) for x in m.group(3).split()]
                j += 1
            i = j
            continue
        i += 1
    return out


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    warnings = [l for l in p.stderr.splitlines() + p.stdout.splitlines() if l.lstrip().startswith("warning")]
    return p.returncode, p.stdout, p.stderr, warnings


def first_error(stderr):
    for l in stderr.splitlines():
        if l.startswith("error"):
            return l
    return stderr.strip().splitlines()[-1] if stderr.strip() else "no message"


def compare_statics(seflex, deck, answer, tmp):
    ref = parse_displacements(answer)
    if not ref:
        return "not compared", "no DISPLACEMENTS table in MYSTRAN's answer", [], None
    worst, all_warnings, notes = 0.0, [], []
    for sc in sorted(ref):
        out = os.path.join(tmp, "u.csv")
        cmd = [seflex, "static", deck, "-o", out, "--force", "--system", "global"]
        if len(ref) > 1 or sc != 0:
            cmd += ["--subcase", str(sc)]
        rc, so, se, warns = run(cmd)
        if rc == 2 and "'--system'" in se:  # an older seflex: basic system only
            cmd.remove("--system")
            cmd.remove("global")
            rc, so, se, warns = run(cmd)
        all_warnings += [w for w in warns if w not in all_warnings]
        if rc != 0 and "--subcase" in cmd and "SUBCASE %d is not defined" % sc in se:
            rc, so, se, warns = run(cmd[:-2])  # MYSTRAN numbers a deck without SUBCASE as subcase 1
            all_warnings += [w for w in warns if w not in all_warnings]
        if rc != 0:
            return "refused", first_error(se), all_warnings, None
        mine = {}
        with open(out) as f:
            r = csv.reader(f)
            header = next(r)
            gi = header.index("grid")
            for row in r:
                if "subcase" in header and int(float(row[header.index("subcase")])) != sc:
                    continue
                mine[int(float(row[gi]))] = [float(x) for x in row[gi + 1:gi + 7]]
        overall = max((abs(v) for u in ref[sc].values() for v in u), default=0.0)
        for part in (slice(0, 3), slice(3, 6)):
            # a part that is round-off in MYSTRAN's answer (e.g. rotations of 1e-19 beside
            # translations of 1e-2) is compared on the scale of 1e-9 of the largest value
            scale = max(max((abs(v) for u in ref[sc].values() for v in u[part]), default=0.0), 1e-9 * overall)
            if scale == 0.0:
                continue
            err = 0.0
            for g, u in ref[sc].items():
                if g not in mine:
                    return "refused", "grid %d missing from seflex output" % g, all_warnings, None
                err = max(err, max(abs(a - b) for a, b in zip(mine[g][part], u[part])) / scale)
            worst = max(worst, err)
        notes.append("sc %d" % sc)
    return None, ", ".join(notes), all_warnings, worst


def compare_eigen(seflex, deck, answer, tmp, command):
    ref = parse_eigenvalues(answer)
    if not ref:
        return "not compared", "no eigenvalues in MYSTRAN's answer", [], None
    out = os.path.join(tmp, "e.csv")
    cmd = [seflex, command, deck, "--csv", out, "--force"]
    rc, so, se, warns = run(cmd)
    if rc != 0 and command == "modes" and "--count" in se:
        rc, so, se, warns = run(cmd + ["--count", str(len(ref))])
    if rc != 0:
        return "refused", first_error(se), warns, None
    mine = []
    with open(out) as f:
        r = csv.reader(f)
        header = next(r)
        k = header.index("eigenvalue") if "eigenvalue" in header else 1
        for row in r:
            mine.append(float(row[k]))
    n = min(len(ref), len(mine))
    # rigid-body modes: below 1e-8 of the largest eigenvalue and below 1 mHz (any unit system)
    rigid = max(1e-8 * max(abs(x) for x in ref), (2 * math.pi * 1e-3) ** 2)
    worst = 0.0
    for a, b in zip(mine[:n], ref[:n]):
        if abs(b) < rigid:
            err = 0.0 if abs(a) < 100 * rigid else 1.0
        else:
            err = abs(a - b) / abs(b)
        worst = max(worst, err)
    note = "%d eigenvalues" % n
    if len(mine) < len(ref):
        note += " (MYSTRAN %d, seflex %d)" % (len(ref), len(mine))
        worst = max(worst, 1.0)
    return None, note, warns, worst


def has_command(seflex, name):
    p = subprocess.run([seflex, "help"], capture_output=True, text=True)
    return re.search(r"^\s+" + name + r"\b", p.stdout + p.stderr, re.M) is not None


def with_mystran_elements(deck, tmp):
    """A copy of deck in tmp with PARAM,QUAD4TYP,MIN4T after BEGIN BULK (the decks have no INCLUDE)."""
    out_dir = os.path.join(tmp, "mystran-elements")
    os.makedirs(out_dir, exist_ok=True)
    out = os.path.join(out_dir, os.path.basename(deck))
    lines = open(deck, errors="replace").read().splitlines(True)
    for i, line in enumerate(lines):
        if re.match(r"\s*BEGIN\s*,?\s*BULK", line.upper()):
            lines.insert(i + 1, "PARAM,QUAD4TYP,MIN4T\n")
            break
    else:
        raise SystemExit("%s: no BEGIN BULK" % deck)
    with open(out, "w") as f:
        f.writelines(lines)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--decks", action="append", required=True, help="folder searched recursively for *.DAT")
    ap.add_argument("--seflex", default="build/apps/seflex")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    ap.add_argument("--mystran-elements", action="store_true",
                    help="add PARAM,QUAD4TYP,MIN4T to each deck (MYSTRAN 12.0's plate elements, see above)")
    args = ap.parse_args()
    seflex = os.path.abspath(args.seflex)
    buckling = has_command(seflex, "buckling")

    decks = []
    for d in args.decks:
        for root, _, files in os.walk(d):
            for f in files:
                if f.upper().endswith(".DAT"):
                    decks.append(os.path.join(root, f))
    decks.sort()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for deck in decks:
            name = os.path.relpath(deck, os.path.commonpath(args.decks) if len(args.decks) > 1 else args.decks[0])
            answer_path = find_answer(deck)
            sol = solution_of(deck)
            kind = kind_of(sol)
            if answer_path is None:
                rows.append((name, sol, "not compared", "no MYSTRAN answer file found", [], None))
                continue
            answer = open(answer_path, errors="replace").read()
            if args.mystran_elements:
                deck = with_mystran_elements(deck, tmp)
            if kind == "statics":
                status, note, warns, err = compare_statics(seflex, deck, answer, tmp)
            elif kind == "modes":
                status, note, warns, err = compare_eigen(seflex, deck, answer, tmp, "modes")
            elif kind == "buckling" and buckling:
                status, note, warns, err = compare_eigen(seflex, deck, answer, tmp, "buckling")
            elif kind == "buckling":
                status, note, warns, err = ("refused", "SOL %s (buckling): this seflex has no buckling command" % sol,
                                            [], None)
            else:
                status, note, warns, err = ("not compared", "SOL %s is not statics, normal modes or buckling" % sol,
                                            [], None)
            if status is None:
                if err <= TOL_REPRODUCED:
                    status = "reproduced"
                elif warns:
                    status = "differs with warning"
                else:
                    status = "differs silently"
            # file names in messages relative to the deck's folder, for a readable table
            prefix = os.path.dirname(os.path.abspath(deck)) + os.sep
            note = note.replace(prefix, "")
            warns = [w.replace(prefix, "") for w in warns]
            rows.append((name, sol, status, note, warns, err))

    order = ["reproduced", "differs with warning", "differs silently", "refused", "not compared"]
    if args.markdown:
        print("| deck | SOL | status | max rel. error | notes |")
        print("|---|---|---|---|---|")
    for name, sol, status, note, warns, err in rows:
        e = "" if err is None else "%.2e" % err
        extra = note
        if warns and status != "reproduced":
            extra += "; " + " / ".join(w.strip() for w in warns[:3])
        if args.markdown:
            print("| %s | %s | %s | %s | %s |" % (name, sol, status, e, extra.replace("|", "/")))
        else:
            print("%-52s %-6s %-22s %-10s %s" % (name, sol, status, e, extra))
    print()
    total = len(rows)
    for s in order:
        n = sum(1 for r in rows if r[2] == s)
        print("%-22s %3d of %d" % (s, n, total))
    loud = sum(1 for r in rows if r[2] == "differs silently" and r[5] is not None and r[5] > TOL_LOUD)
    print("%-22s %3d (differs silently by more than %g %%)" % ("silent > 5 %", loud, 100 * TOL_LOUD))


if __name__ == "__main__":
    main()
