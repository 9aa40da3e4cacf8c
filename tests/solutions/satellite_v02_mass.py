#!/usr/bin/env python3
"""Mass, centre of gravity and GRAV load resultants of pyNastran's Satellite_V02 SOL 101 job, computed
from its cards independently of seflex (tests/solutions/satellite_v02_test.cpp compares seflex's).

    tests/solutions/satellite_v02_mass.py MAIN_DECK

A reader of just what this deck holds (small-field cards, '+' continuations, INCLUDE resolved against
the main deck's folder as MSC Nastran does) and the mass of each element from its definition:
  - CONM2: M at its grid (the deck's offsets are 0, CID 0);
  - CQUAD4: (RHO T + NSM) of its PSHELL times its area on its mean plane, |d1 x d2| / 2 for the
    diagonals d1, d2 (Nastran's QUAD4 is formulated on its mean plane: QRG CQUAD4, element
    coordinate system; the satellite's quads have corners up to 0.013 in off it, and the bilinear
    surface's area would give 1.1e-8 more mass), at the centroid of the bilinear surface through its
    corners (Gauss-Legendre 6 x 6);
  - CBAR: (RHO A + NSM) of its PBARL over its length, A of the section (TUBE: pi (r_o^2 - r_i^2);
    BOX: w h - (w - 2 t_w)(h - 2 t_h), QRG PBARL figures), at its mid-point (no offsets in this deck).
Mass units are the deck's (as Nastran's grid point weight generator prints them; PARAM WTMASS 1.).
Prints "mass M", "cg X Y Z" and, for each LOAD of the deck, "load SID FX FY FZ": the resultant of
its GRAV combination, M times the acceleration (rigid translation: the same whatever the mass matrix).
"""
import math
import os
import re
import sys


def number(text):
    t = text.strip().upper().replace("D", "E")
    if "E" not in t:  # Nastran's 1.5-3 = 1.5E-3
        m = re.match(r"^([+-]?[0-9.]+)([+-][0-9]+)$", t)
        if m:
            t = m.group(1) + "E" + m.group(2)
    return float(t)


def cards(path, main_dir, out):
    """Append (name, fields) of every bulk-data card of `path` (and its INCLUDEs) to `out`."""
    in_bulk = os.path.abspath(path) != os.path.abspath(main_path)
    current = None
    lines = open(path, encoding="latin-1").read().splitlines()
    k = 0
    while k < len(lines):
        line = lines[k].split("$")[0].rstrip().expandtabs(8)
        k += 1
        if not in_bulk:
            in_bulk = re.match(r"^\s*BEGIN\s+BULK", line, re.I) is not None
            continue
        if not line.strip():
            continue
        if line.upper().startswith("INCLUDE"):
            name = line[7:].strip()
            while name.count("'") < 2:  # a quoted name continued on the next line
                name += lines[k].split("$")[0].strip()
                k += 1
            name = name.strip("'")
            cards(os.path.join(main_dir, name), main_dir, out)
            continue
        if line.upper().startswith("ENDDATA"):
            break
        fields = [line[8 * i:8 * i + 8].strip() for i in range(1, 9)]
        if line[0] in "+ ":
            current[1].extend(fields)
        else:
            current = (line[:8].strip().upper(), fields)
            out.append(current)


main_path = sys.argv[1]
deck = []
cards(main_path, os.path.dirname(main_path), deck)

grid, mat_rho, pshell, pbarl, loads, grav = {}, {}, {}, {}, {}, {}
for name, f in deck:
    if name == "GRID":
        assert f[1] in ("", "0"), "grids in basic only"
        grid[int(f[0])] = [number(f[2]), number(f[3]), number(f[4])]
    elif name == "MAT1":
        mat_rho[int(f[0])] = number(f[4]) if f[4] else 0.0
    elif name == "PSHELL":
        pshell[int(f[0])] = (int(f[1]), number(f[2]), number(f[6]) if f[6] else 0.0)
    elif name == "PBARL":
        kind, dims = f[3].upper(), [number(x) for x in f[8:] if x]
        if kind == "TUBE":
            area = math.pi * (dims[0] ** 2 - dims[1] ** 2)
        elif kind == "BOX":
            area = dims[0] * dims[1] - (dims[0] - 2 * dims[3]) * (dims[1] - 2 * dims[2])
        else:
            raise SystemExit("PBARL " + kind + " not handled")
        nsm = dims[2] if kind == "TUBE" and len(dims) > 2 else (dims[4] if kind == "BOX" and len(dims) > 4 else 0.0)
        pbarl[int(f[0])] = (int(f[1]), area, nsm)
    elif name == "GRAV":
        grav[int(f[0])] = [number(f[2]) * number(x) for x in f[3:6]]
    elif name == "LOAD":
        s, terms = number(f[1]), f[2:]
        loads[int(f[0])] = [(s * number(terms[i]), int(terms[i + 1])) for i in range(0, len(terms) - 1, 2) if terms[i]]

gauss_x = [-0.9324695142, -0.6612093865, -0.2386191861, 0.2386191861, 0.6612093865, 0.9324695142]
gauss_w = [0.1713244924, 0.3607615730, 0.4679139346, 0.4679139346, 0.3607615730, 0.1713244924]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


mass, moment = 0.0, [0.0, 0.0, 0.0]


def add(m, at):
    global mass
    mass += m
    for i in range(3):
        moment[i] += m * at[i]


for name, f in deck:
    if name == "CONM2":
        assert f[2] in ("", "0") and all(x in ("", "0.0", "0.") for x in f[4:7]), "CONM2 offsets not handled"
        add(number(f[3]), grid[int(f[1])])
    elif name == "CQUAD4":
        mid, t, nsm = pshell[int(f[1])]
        per_area = mat_rho[mid] * t + nsm
        x = [grid[int(g)] for g in f[2:6]]
        mean_plane_area = 0.5 * math.sqrt(sum(c * c for c in cross(sub(x[2], x[0]), sub(x[3], x[1]))))
        surface, first = 0.0, [0.0, 0.0, 0.0]
        for a, wa in zip(gauss_x, gauss_w):
            for b, wb in zip(gauss_x, gauss_w):
                n = [(1 - a) * (1 - b) / 4, (1 + a) * (1 - b) / 4, (1 + a) * (1 + b) / 4, (1 - a) * (1 + b) / 4]
                dn_a = [-(1 - b) / 4, (1 - b) / 4, (1 + b) / 4, -(1 + b) / 4]
                dn_b = [-(1 - a) / 4, -(1 + a) / 4, (1 + a) / 4, (1 - a) / 4]
                xa = [sum(dn_a[j] * x[j][i] for j in range(4)) for i in range(3)]
                xb = [sum(dn_b[j] * x[j][i] for j in range(4)) for i in range(3)]
                p = [sum(n[j] * x[j][i] for j in range(4)) for i in range(3)]
                da = math.sqrt(sum(c * c for c in cross(xa, xb))) * wa * wb
                surface += da
                first = [first[i] + da * p[i] for i in range(3)]
        add(per_area * mean_plane_area, [c / surface for c in first])
    elif name == "CBAR":
        mid, area, nsm = pbarl[int(f[1])]
        a, b = grid[int(f[2])], grid[int(f[3])]
        length = math.sqrt(sum(c * c for c in sub(b, a)))
        add((mat_rho[mid] * area + nsm) * length, [(a[i] + b[i]) / 2 for i in range(3)])
    elif name in ("CTRIA3", "CROD", "CBEAM", "CONM1", "CMASS1", "CMASS2", "CHEXA", "CTETRA", "CPENTA"):
        raise SystemExit(name + " not handled")

print("mass %.15e" % mass)
print("cg %.15e %.15e %.15e" % tuple(m / mass for m in moment))
for sid in sorted(loads):
    acc = [0.0, 0.0, 0.0]
    for s, g in loads[sid]:
        for i in range(3):
            acc[i] += s * grav[g][i]
    print("load %d %.15e %.15e %.15e" % (sid, mass * acc[0], mass * acc[1], mass * acc[2]))
