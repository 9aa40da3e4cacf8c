#!/usr/bin/python3
"""A thin plate whose root rotation is held only by a shell skin on solid grids, refined.

The situation of pyNastran's nx_sine deck (docs/nastran-support.md, "Public decks"): a 1 mm
aluminium panel (20 x 20 mm, CQUAD4, PSHELL with MID3: transverse shear flexible) cantilevers from
the edge of a solid block; the grids of its root are the block's, which have no rotations, so the
root rotation is held by the 1 mm CQUAD4 skin glued on the block's side face (all its grids'
translations held by the solid). That skin can only resist a rotation through its transverse shear
(w = 0 at every corner, theta free), and how much a coarse element gives there depends on its
shear treatment. Here the block is an SPC 123 on the skin's grids; the skin (10 mm deep) and the
panel are refined together (N x N panel elements, N/2 x N skin elements); the root clamped
(SPC 123456) is the reference, which converges to Leissa's cantilever square plate
(NASA SP-160, 1969, Table 4.56: omega a^2 sqrt(rho t / D) = 3.492, 8.525, 21.43 for nu = 0.3).

usage: bench/shell_skin_root.py SEFLEX   (prints the table and the commands; ~1 s)
"""
import math
import os
import subprocess
import sys
import tempfile

L, T, E, NU, RHO = 0.02, 0.001, 7.0e10, 0.3, 2700.0


def deck(n, clamp, mid3):
    h = L / n
    grids, lines, els = {}, [], []

    def grid(x, y, z):
        key = (round(x, 12), round(y, 12), round(z, 12))
        if key not in grids:
            grids[key] = len(grids) + 1
            lines.append("GRID,%d,,%.9e,%.9e,%.9e" % (grids[key], x, y, z))
        return grids[key]

    for i in range(n):
        for j in range(n):
            c = [grid(i * h, j * h, 0), grid((i + 1) * h, j * h, 0), grid((i + 1) * h, (j + 1) * h, 0), grid(i * h, (j + 1) * h, 0)]
            els.append("CQUAD4,%d,1,%d,%d,%d,%d" % (len(els) + 1, *c))
    held = {v for k, v in grids.items() if abs(k[0]) < 1e-12}
    if not clamp:
        for k in range(max(1, n // 2)):
            for j in range(n):
                c = [grid(0, j * h, -k * h), grid(0, (j + 1) * h, -k * h), grid(0, (j + 1) * h, -(k + 1) * h), grid(0, j * h, -(k + 1) * h)]
                els.append("CQUAD4,%d,1,%d,%d,%d,%d" % (len(els) + 1, *c))
                held |= set(c)
    out = ["SOL 103", "CEND", "SPC = 1", "METHOD = 1", "BEGIN BULK", "EIGRL,1,,,3"] + lines + els
    out.append("PSHELL,1,1,%.6g,1,,%s" % (T, "1" if mid3 else ""))
    out.append("MAT1,1,%.6e,,%.6e,%.6e" % (E, NU, RHO))
    out += ["SPC1,1,%s,%d" % ("123456" if clamp else "123", g) for g in sorted(held)]
    return "\n".join(out + ["ENDDATA", ""])


def frequencies(seflex, text):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "p.bdf")
        with open(path, "w") as f:
            f.write(text)
        r = subprocess.run([seflex, "modes", path, "--count", "3"], capture_output=True, text=True, check=True)
    return [float(w.split()[4]) for w in r.stdout.splitlines() if len(w.split()) == 7 and w.split()[0].isdigit()]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    seflex = sys.argv[1]
    D = E * T**3 / (12 * (1 - NU * NU))
    leissa = [lam / (2 * math.pi * L * L) * math.sqrt(D / (RHO * T)) for lam in (3.492, 8.525, 21.43)]
    print("command: bench/shell_skin_root.py %s" % seflex)
    print("Leissa, clamped root (Kirchhoff): %s Hz" % " / ".join("%.1f" % f for f in leissa))
    print("f1/f2/f3 Hz, N x N panel CQUAD4")
    print("%-32s %s" % ("root, PSHELL", "".join("N = %-17d" % n for n in (2, 4, 8, 16, 32))))
    for clamp in (True, False):
        for mid3 in (True, False):
            row = ["/".join("%.0f" % f for f in frequencies(seflex, deck(n, clamp, mid3))) for n in (2, 4, 8, 16, 32)]
            name = "%s, %s" % ("clamped" if clamp else "held by the skin", "MID3 = 1" if mid3 else "MID3 blank")
            print("%-32s %s" % (name, "".join("%-21s" % r for r in row)))


if __name__ == "__main__":
    main()
