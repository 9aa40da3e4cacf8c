#!/usr/bin/python3
"""The demo panel's free-free frequencies: seflex against CalculiX, an independent solver (issue 13).

    bench/panel_modes_vs_calculix.py [--seflex build/apps/seflex] [--ccx ccx] [--refine 1,2,4]
                                     [--ccx-refine 6] [--modes 8] [--keep DIR]

The panel is meshes/panel.bdf (the demo's: 4 x 4 CQUAD4 sandwich plate, PSHELL T = 0.36 mm of face
sheet, 12I/T^3 = 11200, TS/T = 19.13; CBAR edge members; 25 CONM2 of 0.55 kg with rotary inertia;
no structural density). This script reads its GRID, CQUAD4, CBAR, PBAR, PSHELL, MAT1 and CONM2 cards
and writes

- for seflex: the panel with each CQUAD4 split r x r and each CBAR in r pieces (r = 1 is the demo
  deck itself), the CONM2s on the demo's 25 grids, SOL 103 free-free;
- for CalculiX (Debian package calculix-ccx, 2.20): the same panel with S8R shells, each demo CQUAD4
  as r x r of them, of the homogeneous section with the PSHELL's membrane and bending stiffness
  (thickness t_eq = sqrt(12I/T^3) T, modulus E T / t_eq; CalculiX has no PSHELL with 12I/T^3 and its
  composite shells refuse MASS elements). CalculiX expands the S8R into C3D20R solids, so bending
  and shear come from 3-D elasticity, not from a plate theory like seflex's. Its transverse shear
  stiffness (5/6) G_eq t_eq is 23x below the PSHELL's G3 TS, but both are so stiff that shear does
  not show in these modes (D/(S L^2) = 4e-4). Edge members: B32R beams of the PIPE section with the
  PBAR's A, I1 = I2 and J = 2 I; point masses: MASS elements. CalculiX 2.20 has no *ROTARY INERTIA,
  so seflex is run without the CONM2s' rotary inertia for the comparison, and once with it (the
  demo panel as it is) to show what it changes. The hinge brackets (massless CBARs to the hinge
  points) are left out of both: they carry no mass and do not change the free-free modes.

It prints the first elastic frequencies (the six rigid-body modes skipped) of seflex for each r and
of CalculiX, and the relative differences.
"""
import argparse
import itertools
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))  # bench/: the shared helpers in bench/lib/
from lib.plate import ccx_frequencies, real, seflex_frequencies  # noqa: E402


def fields(line):
    """Small-field fixed format: 8-character fields."""
    return [line[i:i + 8].strip() for i in range(0, 80, 8)]


def num(s, default=0.0):
    if not s:
        return default
    s = s.upper().replace("D", "E")
    for i in range(1, len(s)):  # Nastran's 1.2-3 = 1.2e-3
        if s[i] in "+-" and s[i - 1] not in "E":
            s = s[:i] + "E" + s[i:]
            break
    return float(s)


def read_panel(path):
    p = {"grid": {}, "quad": [], "bar": [], "conm2": []}
    lines = [l.rstrip("\n") for l in open(path) if not l.startswith("$")]
    for k, line in enumerate(lines):
        f = fields(line)
        card = f[0]
        if card == "GRID":
            p["grid"][int(f[1])] = (num(f[3]), num(f[4]), num(f[5]))
        elif card == "CQUAD4":
            p["quad"].append([int(x) for x in f[3:7]])
        elif card == "CBAR":
            p["bar"].append((int(f[3]), int(f[4]), (num(f[5]), num(f[6]), num(f[7]))))
        elif card == "PBAR":
            p["pbar"] = dict(A=num(f[3]), I1=num(f[4]), I2=num(f[5]), J=num(f[6]))
        elif card == "PSHELL":
            p["pshell"] = dict(mid=int(f[2]), T=num(f[3]), bend=num(f[5]), tst=num(f[7]))
        elif card == "MAT1":
            p.setdefault("mat1", {})[int(f[1])] = dict(E=num(f[2]), nu=num(f[4]))
        elif card == "PARAM" and f[1] == "K6ROT":
            p["k6rot"] = num(f[2])
        elif card == "CONM2":
            c = fields(lines[k + 1])
            p["conm2"].append((int(f[2]), num(f[4]), num(c[1]), num(c[3]), num(c[6])))  # I11, I22, I33
    p["mat_bar"] = p["mat1"][10]
    p["mat_shell"] = p["mat1"][p["pshell"]["mid"]]
    return p


def plate_of(p):
    """The plate's structured grid: the CQUAD4 grids lie on y = const, z = const lines."""
    gids = sorted({g for q in p["quad"] for g in q})
    ys = sorted({round(p["grid"][g][1], 9) for g in gids})
    zs = sorted({round(p["grid"][g][2], 9) for g in gids})
    return ys, zs


def subdivide(vals, r):
    out = []
    for a, b in zip(vals, vals[1:]):
        out += [a + (b - a) * k / r for k in range(r)]
    return out + [vals[-1]]


def edge_bars(p):
    """Edge members (the CBARs between plate grids) as (y, z0, z1)."""
    plate = {g for q in p["quad"] for g in q}
    out = []
    for a, b, _ in p["bar"]:
        if a in plate and b in plate:
            ya, za = p["grid"][a][1:]
            yb, zb = p["grid"][b][1:]
            assert abs(ya - yb) < 1e-12
            out.append((ya, min(za, zb), max(za, zb)))
    return out


def write_seflex(path, p, r, modes, rotary=True):
    ys, zs = plate_of(p)
    Y, Z = subdivide(ys, r), subdivide(zs, r)
    gid = {}
    lines = ["SOL 103\nCEND\nTITLE = demo panel free-free, plate %dx%d CQUAD4\nMETHOD = 1\nBEGIN BULK\n" % (
        len(Y) - 1, len(Z) - 1), "EIGRL,1,,,%d\n" % (modes + 6)]
    if "k6rot" in p:
        lines.append("PARAM,K6ROT,%s\n" % real(p["k6rot"]))
    for j, y in enumerate(Y):
        for i, z in enumerate(Z):
            gid[(j, i)] = 1 + i + len(Z) * j
            lines.append("GRID,%d,,0.,%s,%s\n" % (gid[(j, i)], real(y), real(z)))
    e = 1
    for j in range(len(Y) - 1):
        for i in range(len(Z) - 1):
            lines.append("CQUAD4,%d,1,%d,%d,%d,%d\n" % (e, gid[(j, i)], gid[(j + 1, i)], gid[(j + 1, i + 1)], gid[(j, i + 1)]))
            e += 1
    for y, z0, z1 in edge_bars(p):
        j = min(range(len(Y)), key=lambda k: abs(Y[k] - y))
        for i in range(len(Z) - 1):
            if Z[i] >= z0 - 1e-9 and Z[i + 1] <= z1 + 1e-9:
                lines.append("CBAR,%d,2,%d,%d,1.,0.,0.\n" % (e, gid[(j, i)], gid[(j, i + 1)]))
                e += 1
    for g, m, i11, i22, i33 in p["conm2"]:
        _, y, z = p["grid"][g]
        j = min(range(len(Y)), key=lambda k: abs(Y[k] - y))
        i = min(range(len(Z)), key=lambda k: abs(Z[k] - z))
        if not rotary:
            i11 = i22 = i33 = 0.0
        lines.append("CONM2,%d,%d,0,%s\n,%s,0.,%s,0.,0.,%s\n" % (e, gid[(j, i)], real(m), real(i11), real(i22), real(i33)))
        e += 1
    ps, b, ms, mb = p["pshell"], p["pbar"], p["mat_shell"], p["mat_bar"]
    lines.append("PSHELL,1,1,%s,1,%s,1,%s\n" % (real(ps["T"]), real(ps["bend"]), real(ps["tst"])))
    lines.append("MAT1,1,%s,,%s\n" % (real(ms["E"]), real(ms["nu"])))
    lines.append("PBAR,2,2,%s,%s,%s,%s\n" % (real(b["A"]), real(b["I1"]), real(b["I2"]), real(b["J"])))
    lines.append("MAT1,2,%s,,%s\nENDDATA\n" % (real(mb["E"]), real(mb["nu"])))
    open(path, "w").write("".join(lines))


def write_calculix(path, p, r, modes):
    """S8R of the equivalent homogeneous section (r x r per demo CQUAD4), B32R PIPE edge members, MASS."""
    ys, zs = plate_of(p)
    Y, Z = subdivide(ys, 2 * r), subdivide(zs, 2 * r)  # corner and mid-side nodes of the S8R
    nid = {}
    out = ["*HEADING\nseflex demo panel, S8R of the sandwich PSHELL's membrane and bending stiffness (bench/panel_modes_vs_calculix.py)\n*NODE\n"]
    for j, y in enumerate(Y):
        for i, z in enumerate(Z):
            if j % 2 and i % 2:
                continue  # S8R: no centre node
            nid[(j, i)] = 1 + i + len(Z) * j
            out.append("%d,0.,%.12g,%.12g\n" % (nid[(j, i)], y, z))
    out.append("*ELEMENT,TYPE=S8R,ELSET=PLATE\n")
    e = 1
    for j in range(0, len(Y) - 1, 2):
        for i in range(0, len(Z) - 1, 2):
            c = [nid[(j, i)], nid[(j + 2, i)], nid[(j + 2, i + 2)], nid[(j, i + 2)],
                 nid[(j + 1, i)], nid[(j + 2, i + 1)], nid[(j + 1, i + 2)], nid[(j, i + 1)]]
            out.append("%d,%s\n" % (e, ",".join(map(str, c))))
            e += 1
    out.append("*ELEMENT,TYPE=B32R,ELSET=EDGE\n")
    for y, z0, z1 in edge_bars(p):
        j = min(range(len(Y)), key=lambda k: abs(Y[k] - y))
        for i in range(0, len(Z) - 1, 2):
            if Z[i] >= z0 - 1e-9 and Z[i + 2] <= z1 + 1e-9:
                out.append("%d,%d,%d,%d\n" % (e, nid[(j, i)], nid[(j, i + 1)], nid[(j, i + 2)]))
                e += 1
    for g, m, _, _, _ in p["conm2"]:
        _, y, z = p["grid"][g]
        j = min(range(len(Y)), key=lambda k: abs(Y[k] - y))
        i = min(range(len(Z)), key=lambda k: abs(Z[k] - z))
        out.append("*ELEMENT,TYPE=MASS,ELSET=M%d\n%d,%d\n*MASS,ELSET=M%d\n%.12g\n" % (e, e, nid[(j, i)], e, m))
        e += 1
    ps, b, ms, mb = p["pshell"], p["pbar"], p["mat_shell"], p["mat_bar"]
    T, E, nu = ps["T"], ms["E"], ms["nu"]
    t_eq = math.sqrt(ps["bend"]) * T                   # E_eq t_eq = E T and E_eq t_eq^3/12 = E I
    E_eq = E * T / t_eq
    # Transverse shear: the 3-D expansion gives (5/6) G13 t_eq; G13 = G23 make it the PSHELL's G3 TS.
    G3 = ms["E"] / (2.0 * (1.0 + nu))
    G13 = G3 * ps["tst"] * T / (5.0 / 6.0 * t_eq)
    out.append("*MATERIAL,NAME=PLATE\n*ELASTIC,TYPE=ENGINEERING CONSTANTS\n%.9g,%.9g,%.9g,%.6g,0.,0.,%.9g,%.9g\n%.9g\n*DENSITY\n1e-9\n"
               % (E_eq, E_eq, E_eq, nu, E_eq / (2.0 * (1.0 + nu)), G13, G13))
    out.append("*ORIENTATION,NAME=SHELLAXES\n0.,1.,0.,0.,0.,1.\n")  # local 1 = y, 2 = z, 3 = x, the shell normal
    out.append("*SHELL SECTION,ELSET=PLATE,MATERIAL=PLATE,ORIENTATION=SHELLAXES\n%.12g\n" % t_eq)
    A, Ib = b["A"], b["I1"]
    ro2 = (4.0 * Ib / A + A / math.pi) / 2.0           # PIPE: A = pi (ro^2 - ri^2), I = A (ro^2 + ri^2)/4
    ri2 = (4.0 * Ib / A - A / math.pi) / 2.0
    ro, ri = math.sqrt(ro2), math.sqrt(ri2)
    out.append("*MATERIAL,NAME=BAR\n*ELASTIC\n%.9g,%.6g\n*DENSITY\n1e-9\n" % (mb["E"], mb["nu"]))
    out.append("*BEAM SECTION,ELSET=EDGE,MATERIAL=BAR,SECTION=PIPE\n%.12g,%.12g\n1.,0.,0.\n" % (ro, ro - ri))
    out.append("*STEP\n*FREQUENCY\n%d\n*END STEP\n" % (modes + 6))
    open(path, "w").write("".join(out))
    return dict(t_eq=t_eq, E_eq=E_eq, G13=G13, pipe_ro=ro, pipe_ri=ri)


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("failed (%d): %s\n%s\n%s" % (p.returncode, " ".join(cmd), p.stdout[-3000:], p.stderr[-3000:]))
    return p.stdout


def mystran_frequencies(f06):
    """CYCLES column of MYSTRAN's REAL EIGENVALUES table."""
    freqs, on = [], False
    for line in open(f06, errors="replace"):
        if "R E A L   E I G E N V A L U E S" in line:
            on, freqs = True, []
            continue
        w = line.split()
        if on and len(w) >= 6 and w[0].isdigit() and w[1].isdigit():
            freqs.append(float(w[4]))
        elif on and freqs and not w:
            on = False
    return freqs


def match_rigid(freqs, ref, modes):
    """MYSTRAN's elastic frequencies (above 1 Hz) aligned with seflex's: when it finds fewer than six
    rigid-body modes, the missing ones appear among the elastic modes; leave out those whose removal
    matches seflex's frequencies best. Returns (frequencies, left-out frequencies)."""
    elastic = [f for f in freqs if f > 1.0]
    k = 6 - (len(freqs) - len(elastic))
    best = None
    for drop in itertools.combinations(range(min(len(elastic), modes + k)), max(k, 0)):
        rest = [f for i, f in enumerate(elastic) if i not in drop][:modes]
        cost = sum(abs(math.log(a / b)) for a, b in zip(rest, ref))
        if best is None or cost < best[0]:
            best = (cost, rest, [elastic[i] for i in drop])
    return best[1], best[2]


def table(title, ref_name, ref, cols, modes):
    print("\n" + title)
    head = "| mode | %s Hz |" % ref_name + "".join(" %s Hz | diff |" % n for n, _ in cols)
    print(head + "\n|---:|---:|" + "---:|---:|" * len(cols))
    for k in range(modes):
        print("| %d | %.3f |" % (7 + k, ref[k]) + "".join(" %.3f | %+.2f %% |" % (f[k], 100.0 * (f[k] / ref[k] - 1.0)) for _, f in cols))
    for n, f in cols:
        print("%s: largest |difference| over the %d elastic modes %.2f %%" % (
            n, modes, 100.0 * max(abs(a / b - 1.0) for a, b in zip(f, ref))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seflex", default=os.path.join(ROOT, "build", "apps", "seflex"))
    ap.add_argument("--ccx", default=os.environ.get("CCX", "ccx"))
    ap.add_argument("--mystran", help="a MYSTRAN executable: also run MYSTRAN on seflex's decks (same input)")
    ap.add_argument("--panel", default=os.path.join(ROOT, "meshes", "panel.bdf"))
    ap.add_argument("--refine", default="1,2,4", help="seflex: each demo CQUAD4 split r x r")
    ap.add_argument("--ccx-refine", type=int, default=6, help="CalculiX: each demo CQUAD4 as r x r S8R")
    ap.add_argument("--modes", type=int, default=8, help="elastic modes compared")
    ap.add_argument("--keep")
    args = ap.parse_args()
    ccx = shutil.which(args.ccx)
    if ccx is None:
        sys.exit("CalculiX not found (--ccx, $CCX or `ccx` on PATH; Debian package calculix-ccx)")
    work = args.keep or tempfile.mkdtemp(prefix="seflex-panel-")
    os.makedirs(work, exist_ok=True)
    print("command: %s" % " ".join([os.path.relpath(os.path.abspath(sys.argv[0]), ROOT)] + sys.argv[1:]))
    p = read_panel(args.panel)
    cols, myst, notes = [], [], []
    runs = [(1, True)] + [(r, False) for r in [int(x) for x in args.refine.split(",")]]
    for r, rotary in runs:
        d = os.path.join(work, "seflex-r%d%s" % (r, "-rotary" if rotary else ""))
        os.makedirs(d, exist_ok=True)
        write_seflex(os.path.join(d, "panel.bdf"), p, r, args.modes, rotary)
        csv = os.path.join(d, "modes.csv")
        if os.path.exists(csv):
            os.remove(csv)
        run([args.seflex, "modes", "panel.bdf", "--csv", "modes.csv"], d)
        name = "%dx%d%s" % (4 * r, 4 * r, " demo CONM2" if rotary else "")
        cols.append((name, seflex_frequencies(csv)[6:6 + args.modes]))
        if args.mystran:
            shutil.copy(os.path.join(d, "panel.bdf"), os.path.join(d, "PANEL.DAT"))
            run([os.path.abspath(args.mystran), "PANEL.DAT"], d)
            g, dropped = match_rigid(mystran_frequencies(os.path.join(d, "PANEL.F06")), cols[-1][1], args.modes)
            if dropped:
                notes.append("MYSTRAN %s: %d rigid-body mode(s) at %s Hz (its rotation about the plate normal is "
                             "not free), left out of the comparison" % (name, len(dropped), ", ".join("%.2f" % x for x in dropped)))
            myst.append((name, g))
    d = os.path.join(work, "ccx")
    os.makedirs(d, exist_ok=True)
    geo = write_calculix(os.path.join(d, "panel.inp"), p, args.ccx_refine, args.modes)
    run([ccx, "-i", "panel"], d)
    ref = ccx_frequencies(os.path.join(d, "panel.dat"))[6:6 + args.modes]
    print("CalculiX: %dx%d S8R, t_eq %.4g mm, E_eq %.4g GPa, G13 = G23 %.4g GPa; edge members B32R PIPE ro %.4g mm ri %.4g mm" % (
        4 * args.ccx_refine, 4 * args.ccx_refine, 1e3 * geo["t_eq"], 1e-9 * geo["E_eq"], 1e-9 * geo["G13"],
        1e3 * geo["pipe_ro"], 1e3 * geo["pipe_ri"]))
    print("seflex/MYSTRAN NxN: the demo's CQUAD4 split, CONM2 without rotary inertia (as CalculiX); "
          "'demo CONM2': the demo deck's CONM2 (with rotary inertia)")
    if myst:
        for (n, f), (_, g) in zip(cols, myst):
            table("seflex against MYSTRAN on the same deck, plate %s" % n, "MYSTRAN", g, [("seflex", f)], args.modes)
        table("seflex and MYSTRAN against the finest MYSTRAN mesh", "MYSTRAN %s" % myst[-1][0], myst[-1][1],
              [("seflex " + n, f) for n, f in cols] + [("MYSTRAN " + n, g) for n, g in myst[:-1]], args.modes)
    table("seflex against CalculiX (S8R, %dx%d)" % (4 * args.ccx_refine, 4 * args.ccx_refine), "CalculiX", ref,
          [("seflex " + n, f) for n, f in cols] + [("MYSTRAN " + n, g) for n, g in myst], args.modes)
    for n in notes:
        print(n)
    print("(modes 1-6 are the rigid-body modes; files in %s)" % work)


if __name__ == "__main__":
    main()
