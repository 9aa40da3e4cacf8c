"""The clamped square plate of the modes benchmarks (bench/plate_modes_vs_calculix.py,
bench/distributed_modes.py, bench/panel_modes_vs_solvers.py): the same plate as a Nastran deck and as a
CalculiX input, and the frequencies read back from each program's output."""

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


def quads(n):
    """(element id, its four grids counter-clockwise) of the n x n plate, row by row."""
    return [(1 + i + n * j, grid_id(i, j, n), grid_id(i, j, n) + 1, grid_id(i, j, n) + n + 2, grid_id(i, j, n) + n + 1)
            for j in range(n) for i in range(n)]


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
        out += ["CQUAD4,%d,1,%d,%d,%d,%d\n" % q for q in quads(n)]
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
        out += ["%d,%d,%d,%d,%d\n" % q for q in quads(n)]
        out.append("*NSET,NSET=EDGE\n")
        b = boundary(n)
        for k in range(0, len(b), 16):
            out.append(",".join(str(g) for g in b[k:k + 16]) + "\n")
        f.write("".join(out))
        f.write("*BOUNDARY\nEDGE,1,6\n*MATERIAL,NAME=STEEL\n*ELASTIC\n%.6e,%.3f\n*DENSITY\n%.1f\n" % (E, NU, RHO))
        f.write("*SHELL SECTION,ELSET=PLATE,MATERIAL=STEEL\n%g\n*STEP\n*FREQUENCY\n%d\n*END STEP\n" % (THICKNESS, MODES))


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
