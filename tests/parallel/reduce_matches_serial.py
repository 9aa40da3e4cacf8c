#!/usr/bin/python3
"""`mpirun -n 1` and `-n 2 seflex reduce ... --backend slepc` against the serial `seflex reduce` (issue
16): the superelement files' reduced K and M agree to 1e-9 relative to their largest entry, after the
sign of each fixed-interface mode (arbitrary in any eigensolver) is matched through its mass coupling
to the interface; the FE mass M_fe (gathered from the ranks' element shares), the constraint-mode
columns of the recovery matrix and the mass properties too; and the distributed run says how it
assembled. The geometric-stiffness invariants (stiff.inertia.c, stiff.interface.j,
docs/geometric-stiffening.md) are in both files, each matrix equal to 1e-9 of its largest entry with
the same mode signs applied to its rows and columns (a matrix that is zero in the serial file - a flat
plate's out-of-plane cases carry no membrane stress - to 1e-9 of the largest of its kind), and
`seflex info` reports them present.
Decks: the yoke (CBAR + CONM2, 3 interface grids, 5 modes; also on 3 ranks, which share out the 30
stiffening projections unevenly; and with the interface given out of order, 4,1,3) and a 16 x 12 CQUAD4 plate with one short edge as the interface (10 modes; also with
the edge's grids in reverse order), all assembled by partition; the plate with an RBE2, which the
distributed run must assemble replicated (and say so).

usage: reduce_matches_serial.py MPIRUN SEFLEX OUTDIR   (exit 0 when all agree)
"""
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from read_superelement import read_superelement  # noqa: E402


def plate_deck(path, nx=16, ny=12, a=0.6, b=0.4, rbe2=False):
    lines = ["SOL 103", "CEND", "BEGIN BULK", "MAT1,1,7.0e10,,0.33,2700.", "PSHELL,1,1,0.003,1,,1"]
    gid = lambda i, j: 1 + i + (nx + 1) * j  # noqa: E731
    for j in range(ny + 1):
        for i in range(nx + 1):
            lines.append("GRID,%d,,%.6f,%.6f,0." % (gid(i, j), a * i / nx, b * j / ny))
    e = 1
    for j in range(ny):
        for i in range(nx):
            lines.append("CQUAD4,%d,1,%d,%d,%d,%d" % (e, gid(i, j), gid(i + 1, j), gid(i + 1, j + 1), gid(i, j + 1)))
            e += 1
    if rbe2:  # a rigid link between two interior grids: dependent dofs, the replicated path
        lines.append("RBE2,90001,%d,123456,%d" % (gid(nx // 2, ny // 2), gid(nx // 2 + 1, ny // 2)))
    lines.append("ENDDATA")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return ",".join(str(gid(0, j)) for j in range(ny + 1))


def reduce(cmd, out):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("FAIL: %s exited %d\n%s\n%s" % (" ".join(cmd), p.returncode, p.stdout[-2000:], p.stderr[-2000:]))
    header, data = read_superelement(out)
    return header, data, p.stdout


def close(a, b, tol=1e-9):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.abs(a - b).max() <= tol * max(np.abs(a).max(), 1e-300)


def stiffening_agrees(name, serial, dist, nb, signs):
    """The stiff.* datasets of both files: the same set, each matrix to 1e-9 (see the docstring)."""
    keys = sorted(k for k in serial if k.startswith("stiff."))
    if len(keys) != 12 + nb or sorted(k for k in dist if k.startswith("stiff.")) != keys:
        print("FAIL %s: stiffening datasets: serial %d, distributed %d (expected %d)" % (
            name, len(keys), len([k for k in dist if k.startswith("stiff.")]), 12 + nb))
        return False
    kind_max = {}
    for k in keys:
        kind = k.split(".")[1]
        kind_max[kind] = max(kind_max.get(kind, 0.0), np.abs(serial[k]).max())
    worst, worst_key = 0.0, ""
    S = np.outer(signs, signs)
    for k in keys:
        G1, G2 = serial[k], dist[k] * S
        scale = np.abs(G1).max() or kind_max[k.split(".")[1]]
        err = np.abs(G2 - G1).max() / scale
        if err > worst:
            worst, worst_key = err, k
    ok = worst <= 1e-9
    print("%s %s: %d stiffening invariants, max |dG|/max|G| = %.2e%s" % ("ok  " if ok else "FAIL", name, len(keys),
                                                                       worst, " (" + worst_key + ")" if worst_key else ""))
    return ok


def info_reports_stiffening(name, seflex, path, nb):
    p = subprocess.run([seflex, "info", path], capture_output=True, text=True)
    want = "stiffening invariants        present: 12 inertia load cases, %d constraint modes" % nb
    if p.returncode != 0 or want not in p.stdout:
        print("FAIL %s: `seflex info %s` does not say '%s':\n%s%s" % (name, path, want, p.stdout, p.stderr))
        return False
    return True


def compare(name, serial_run, dist_run, nb, assembly):
    (h1, serial, _), (h2, dist, out) = serial_run, dist_run
    if "assembly: " + assembly not in out:
        print("FAIL %s: the distributed run did not say 'assembly: %s':\n%s" % (name, assembly, out))
        return False
    for what, a, b in (("M_fe", serial["M_fe"].toarray(), dist["M_fe"].toarray()),
                       ("recovery (constraint modes)", serial["recovery"][:, :nb], dist["recovery"][:, :nb]),
                       ("mass", [h1["mass_properties"]["mass"]], [h2["mass_properties"]["mass"]])):
        if not close(a, b):
            print("FAIL %s: %s differs" % (name, what))
            return False
    K1, M1, K2, M2 = serial["K"], serial["M"], dist["K"].copy(), dist["M"].copy()
    if K1.shape != K2.shape:
        print("FAIL %s: K is %s serial, %s distributed" % (name, K1.shape, K2.shape))
        return False
    signs = np.ones(K1.shape[0])
    for k in range(nb, K1.shape[0]):  # a mode's sign: match the coupling row M[k, :nb]
        if np.dot(M1[k, :nb], M2[k, :nb]) < 0:
            signs[k] = -1
    M2 = M2 * np.outer(signs, signs)
    dk = np.abs(K2 - K1).max() / np.abs(K1).max()
    dm = np.abs(M2 - M1).max() / np.abs(M1).max()
    ok = dk <= 1e-9 and dm <= 1e-9
    print("%s %s: %d x %d, max |dK|/max|K| = %.2e, max |dM|/max|M| = %.2e" % ("ok  " if ok else "FAIL", name,
                                                                              K1.shape[0], K1.shape[1], dk, dm))
    return stiffening_agrees(name, serial, dist, nb, signs) and ok


def main():
    mpirun, seflex, out = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(out, exist_ok=True)
    plate = os.path.join(out, "cb_plate.bdf")
    edge = plate_deck(plate)
    linked = os.path.join(out, "cb_plate_rbe2.bdf")
    plate_deck(linked, rbe2=True)
    part, repl = "partitioned by METIS over %d ranks", "replicated on every rank (the model has RBE2 cards"
    yoke = os.path.join(ROOT, "meshes", "yoke.bdf")
    reversed_edge = ",".join(reversed(edge.split(",")))
    cases = [("yoke", yoke, "1,3,4", 5, 18, part, (1, 2, 3)),
             ("yoke 4,1,3", yoke, "4,1,3", 5, 18, part, (1, 2)),
             ("plate", plate, edge, 10, 6 * 13, part, (1, 2)),
             ("plate reversed edge", plate, reversed_edge, 10, 6 * 13, part, (1, 2)),
             ("plate with RBE2", linked, edge, 10, 6 * 13, repl, (1, 2))]
    ok = True
    for name, deck, iface, modes, nb, assembly, rank_counts in cases:
        tag = name.replace(" ", "_").replace(",", "")
        a = os.path.join(out, tag + "_serial.se")
        args = ["reduce", deck, "--interface", iface, "--modes", str(modes), "--force"]
        serial = reduce([seflex] + args + ["-o", a], a)
        for ranks in rank_counts:
            b = os.path.join(out, "%s_mpi%d.se" % (tag, ranks))
            dist = reduce([mpirun, "-n", str(ranks), seflex] + args + ["--backend", "slepc", "-o", b], b)
            label = "%s, %d rank%s" % (name, ranks, "" if ranks == 1 else "s")
            ok = compare(label, serial, dist, nb, assembly % ranks if "%d" in assembly else assembly) and ok
            ok = info_reports_stiffening(label, seflex, b, nb) and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
