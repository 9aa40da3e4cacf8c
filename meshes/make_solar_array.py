#!/usr/bin/env python3
"""Writes meshes/yoke.bdf and meshes/panel.bdf: the demonstration solar array of
../shared/docs/solar-array.md (geometry fixed there; properties from the seed paper's Tables 1-2).

Run from the repository root:  /usr/bin/python3 meshes/make_solar_array.py
The decks are committed; this script documents how they were made and regenerates them.
Units: SI (m, kg, s, N).
"""
from pathlib import Path

HERE = Path(__file__).resolve().parent
K6ROT_NOTE = """$ Drilling stiffness (PARAM K6ROT, Nastran's penalty 1e-6 K6ROT G T on the rotation about the plate
$ normal): the CONM2s' I11 = 1.98e-4 about the normal rests on it alone. With Nastran's default
$ K6ROT = 100 those inertias make spurious drilling modes from 43 Hz on, among the panel's elastic
$ modes (33, 56, 71 Hz); K6ROT = 1e5 moves them above 1 kHz and leaves the other modes below
$ 500 Hz as they were (to 1e-11: the plate is flat; bench/panel_modes_vs_solvers.py).
"""


def f8(x):
    """A value in an 8-character small-field slot (reals always carry a decimal point)."""
    if isinstance(x, int):
        s = str(x)
    elif isinstance(x, str):
        s = x
    else:
        x = round(float(x), 12)
        s = repr(x)
        if "e" in s or len(s) > 8:
            for p in range(6, -1, -1):
                m, e = ("%.*E" % (p, x)).split("E")
                if "." in m:
                    m = m.rstrip("0")
                s = "%sE%d" % (m, int(e))
                if len(s) <= 8:
                    break
        if "." not in s:
            s = s.replace("E", ".E") if "E" in s else s + "."
    assert len(s) <= 8, s
    return s.ljust(8)


def card(name, *fields):
    """Small-field card; fields beyond 8 go to continuation lines."""
    fields = list(fields)
    lines = []
    first, rest = fields[:8], fields[8:]
    lines.append(name.ljust(8) + "".join(f8(v) if v is not None else " " * 8 for v in first))
    while rest:
        chunk, rest = rest[:8], rest[8:]
        lines.append(" " * 8 + "".join(f8(v) if v is not None else " " * 8 for v in chunk))
    return "\n".join(l.rstrip() for l in lines) + "\n"


def grid(gid, x, y, z):
    return card("GRID", gid, None, x, y, z)


def cbar(eid, pid, ga, gb, v):
    return card("CBAR", eid, pid, ga, gb, v[0], v[1], v[2])


def write_yoke():
    out = []
    out.append("$ seflex demonstration solar array: YOKE (../shared/docs/solar-array.md)\n")
    out.append("$ Frame = global stowed frame. Units SI (m, kg, s, N).\n")
    out.append("$ Hinge points (interface nodes): 1 root (HL1), 3 and 4 (HL2 hinges), 5 (HL2 mid).\n")
    out.append("$ Node 2: strut mid-point, the floating-frame node.\n")
    out.append("$ Interface sets: beam-like {1,5}; 3D {1,3,4}.\n")
    out.append("BEGIN BULK\n")
    x = 0.05
    nodes = {1: (x, 0.0, 0.0), 3: (0.07, 1.1, -0.3), 4: (0.07, 1.1, 0.3), 5: (0.07, 1.1, 0.0)}
    nid = 10
    members = []  # lists of grid ids along each member

    def line(p0, p1, nel, start_id, first_gid):
        ids = [first_gid]
        for k in range(1, nel):
            t = k / nel
            nodes[start_id + k - 1] = tuple(a + t * (b - a) for a, b in zip(p0, p1))
            ids.append(start_id + k - 1)
        return ids

    # corners and the cross-bar centre
    cL, cR, cC = 20, 21, 22
    nodes[cL] = (x, 1.1, -0.3)
    nodes[cR] = (x, 1.1, 0.3)
    nodes[cC] = (x, 1.1, 0.0)
    # arms (4 elements each): 1 -> corner
    arm_l = line(nodes[1], nodes[cL], 4, 11, 1) + [cL]          # grids 11,12,13
    arm_r = line(nodes[1], nodes[cR], 4, 14, 1) + [cR]          # grids 14,15,16
    # central strut (4 elements): 1 -> centre, node 2 at the mid-point
    nodes[2] = (x, 0.55, 0.0)
    nodes[17] = (x, 0.275, 0.0)
    nodes[18] = (x, 0.825, 0.0)
    strut = [1, 17, 2, 18, cC]
    # cross bar: corner L - centre - corner R, 2 elements each side
    nodes[23] = (x, 1.1, -0.15)
    nodes[24] = (x, 1.1, 0.15)
    cross = [cL, 23, cC, 24, cR]
    members = [("arm -z", arm_l), ("arm +z", arm_r), ("strut", strut), ("cross bar", cross)]
    out.append("$\n$ ---- grids ----\n")
    for gid in sorted(nodes):
        out.append(grid(gid, *nodes[gid]))
    out.append("$\n$ ---- members: CBAR, orientation vector normal to the yoke plane (global X) ----\n")
    eid = 100
    for name, ids in members:
        out.append("$ %s\n" % name)
        for a, b in zip(ids[:-1], ids[1:]):
            out.append(cbar(eid, 10, a, b, (1.0, 0.0, 0.0)))
            eid += 1
    out.append("$ hinge brackets (0.02 long, along global X)\n")
    for a, b in ((cL, 3), (cR, 4), (cC, 5)):
        out.append(cbar(eid, 10, a, b, (0.0, 0.0, 1.0)))
        eid += 1
    out.append("$\n$ ---- properties (seed Table 1) ----\n")
    out.append(card("PBAR", 10, 10, 5.0e-4, 7.0e-8, 7.0e-8, 1.4e-7, 0.0))
    out.append(card("MAT1", 10, 7.1e10, None, 0.3))
    out.append("$\n$ ---- concentrated masses: every grid except the hinge points 1, 3, 4, 5 (14 x 0.9 = 12.6 kg) ----\n")
    mid = 1000
    for gid in sorted(nodes):
        if gid in (1, 3, 4, 5):
            continue
        out.append(card("CONM2", mid, gid, 0, 0.9, None, None, None, None,
                        3.24e-4, None, 3.24e-4, None, None, 3.24e-4))
        mid += 1
    out.append("ENDDATA\n")
    (HERE / "yoke.bdf").write_text("".join(out))


def write_panel():
    out = []
    out.append("$ seflex demonstration solar array: PANEL (../shared/docs/solar-array.md), used twice\n")
    out.append("$ Panel frame: origin at the plate centre, x = stack normal, y across the width (1.0),\n")
    out.append("$ z along the hinge lines (1.2). Units SI (m, kg, s, N).\n")
    out.append("$ Hinge points: 1 = edge A (y=+0.5) z=-0.3, 2 = A z=+0.3, 3 = edge B (y=-0.5) z=-0.3,\n")
    out.append("$ 4 = B z=+0.3, 5 = A z=0, 6 = B z=0. Plate centre grid 112 is the floating-frame node.\n")
    out.append("$ Interface sets: beam-like {5,6}; 3D {1,2,3,4}.\n")
    out.append("BEGIN BULK\n")
    ys = [-0.5, -0.25, 0.0, 0.25, 0.5]
    zs = [-0.6, -0.3, 0.0, 0.3, 0.6]
    gid = {}
    out.append("$\n$ ---- plate grids (100 + 5*iy + iz) ----\n")
    for iy, y in enumerate(ys):
        for iz, z in enumerate(zs):
            g = 100 + 5 * iy + iz
            gid[(iy, iz)] = g
            out.append(grid(g, 0.0, y, z))
    out.append("$ ---- hinge points ----\n")
    hinge = {1: (-0.02, 0.5, -0.3), 2: (-0.02, 0.5, 0.3), 3: (0.02, -0.5, -0.3),
             4: (0.02, -0.5, 0.3), 5: (-0.02, 0.5, 0.0), 6: (0.02, -0.5, 0.0)}
    for h in sorted(hinge):
        out.append(grid(h, *hinge[h]))
    out.append("$\n$ ---- plate: 4 x 4 CQUAD4 ----\n")
    eid = 1000
    for iy in range(4):
        for iz in range(4):
            g1, g2, g3, g4 = gid[(iy, iz)], gid[(iy + 1, iz)], gid[(iy + 1, iz + 1)], gid[(iy, iz + 1)]
            out.append(card("CQUAD4", eid, 100, g1, g2, g3, g4))
            eid += 1
    out.append("$\n$ ---- edge members along the hinge edges (orientation: plate normal, x) ----\n")
    eid = 2000
    for iy, label in ((4, "edge A (y = +0.5)"), (0, "edge B (y = -0.5)")):
        out.append("$ %s\n" % label)
        for iz in range(4):
            out.append(cbar(eid, 10, gid[(iy, iz)], gid[(iy, iz + 1)], (1.0, 0.0, 0.0)))
            eid += 1
    out.append("$ ---- hinge brackets (one CBAR each, 0.02 long along x) ----\n")
    eid = 3000
    for h in sorted(hinge):
        y, z = hinge[h][1], hinge[h][2]
        iy = 4 if y > 0 else 0
        iz = zs.index(z)
        out.append(cbar(eid, 10, gid[(iy, iz)], h, (0.0, 0.0, 1.0)))
        eid += 1
    out.append("$\n$ ---- properties (seed Table 2) ----\n")
    out.append(card("PBAR", 10, 10, 5.4e-4, 7.0e-8, 7.0e-8, 1.4e-7, 0.0))
    out.append(card("MAT1", 10, 7.1e10, None, 0.3))
    out.append("$ PSHELL: MID1 T MID2 12I/T^3 MID3 TS/T (the seed's last value read as TS/T)\n")
    out.append(card("PSHELL", 100, 100, 3.6e-4, 100, 11200.0, 100, 19.13))
    out.append(card("MAT1", 100, 1.21e11, None, 0.3))
    out.append(K6ROT_NOTE)
    out.append(card("PARAM", "K6ROT", 1.0e5))
    out.append("$\n$ ---- concentrated masses on the 25 plate grids (25 x 0.55 = 13.75 kg) ----\n")
    mid = 5000
    for iy in range(5):
        for iz in range(5):
            out.append(card("CONM2", mid, gid[(iy, iz)], 0, 0.55, None, None, None, None,
                            1.98e-4, None, 1.98e-4, None, None, 1.98e-4))
            mid += 1
    out.append("ENDDATA\n")
    (HERE / "panel.bdf").write_text("".join(out))


if __name__ == "__main__":
    write_yoke()
    write_panel()
    print("wrote", HERE / "yoke.bdf", "and", HERE / "panel.bdf")
