#!/usr/bin/python3
"""Refined solar-array panel for the reduction benchmark (stands in for the gmsh panel of issue 4).

Same geometry and properties as meshes/panel.bdf: a 1.0 x 1.2 m plate in the x = 0 plane (y across
the width, z along the hinge lines), CQUAD4 with PSHELL 100 / MAT1 100 of the seed's Table 2, CBAR
edge members (PBAR 10 / MAT1 10) along both hinge edges, and six CBAR brackets (0.02 m along x) to
the hinge points 1-6 at the same positions. The panel's 13.75 kg, on 25 CONM2 in the coarse deck,
is spread as PSHELL non-structural mass (13.75 / 1.2 kg/m^2). Grid ids 100000 + (nz + 1) * iy + iz.

usage: bench/refined_panel.py NY NZ OUT.bdf   (NY even, NZ a multiple of 4; 372 x 448 ~ 1.0M dofs)
"""
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    ny, nz, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    if ny < 2 or ny % 2 or nz < 4 or nz % 4:
        sys.exit("NY must be even and NZ a multiple of 4 (grid lines at z = -0.3, 0, 0.3 and y = 0)")
    width, length = 1.0, 1.2

    def gid(iy, iz):
        return 100000 + (nz + 1) * iy + iz

    def y(iy):
        return -0.5 * width + width * iy / ny

    def z(iz):
        return -0.5 * length + length * iz / nz

    def real(x):
        s = "%.10g" % x
        return s if ("." in s or "e" in s) else s + "."

    lines = [
        "$ seflex reduction benchmark: refined demonstration panel (bench/refined_panel.py %d %d)" % (ny, nz),
        "$ %d x %d CQUAD4, %d grids, %d dofs. Units SI." % (ny, nz, (ny + 1) * (nz + 1) + 6, 6 * ((ny + 1) * (nz + 1) + 6)),
        "BEGIN BULK",
    ]
    add = lines.append
    for iy in range(ny + 1):
        for iz in range(nz + 1):
            add("GRID,%d,,0.0,%s,%s" % (gid(iy, iz), real(y(iy)), real(z(iz))))
    hinge = {1: (ny, nz // 4), 2: (ny, 3 * nz // 4), 3: (0, nz // 4), 4: (0, 3 * nz // 4), 5: (ny, nz // 2), 6: (0, nz // 2)}
    for h, (iy, iz) in hinge.items():
        add("GRID,%d,,%s,%s,%s" % (h, real(-0.02 if iy == ny else 0.02), real(y(iy)), real(z(iz))))
    eid = 1000000
    for iy in range(ny):
        for iz in range(nz):
            add("CQUAD4,%d,100,%d,%d,%d,%d" % (eid, gid(iy, iz), gid(iy + 1, iz), gid(iy + 1, iz + 1), gid(iy, iz + 1)))
            eid += 1
    bar = 2000000
    for iy in (0, ny):
        for iz in range(nz):
            add("CBAR,%d,10,%d,%d,1.0,0.0,0.0" % (bar, gid(iy, iz), gid(iy, iz + 1)))
            bar += 1
    for h, (iy, iz) in hinge.items():
        add("CBAR,%d,10,%d,%d,0.0,0.0,1.0" % (bar, gid(iy, iz), h))
        bar += 1
    add("PBAR,10,10,0.00054,7.E-8,7.E-8,1.4E-7,0.0")
    add("MAT1,10,7.1E10,,0.3")
    add("PSHELL,100,100,0.00036,100,11200.0,100,19.13,%s" % real(13.75 / (width * length)))
    add("MAT1,100,1.21E11,,0.3")
    add("ENDDATA")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
