#!/usr/bin/env python3
"""Writes an MSH 4.0 text mesh (as gmsh >= 4.1 writes it: `-format msh40`) in MSH 4.0 binary.

gmsh 4.1 and later neither write nor read MSH 4.0 binary ("Can only write/read MSH 4.0 format in
ASCII mode"), so tests/data/gmsh/panel_msh40_binary.msh is made by this script from panel_msh40.msh,
by the layout of the gmsh reference manual of gmsh 4.0 ("MSH file format (version 4)", 4.0 text):
every number not marked ASCII in binary, little-endian; int = 4 bytes, unsigned long and double = 8.

  $MeshFormat: "4 1 8", then the int 1 and a newline (as in format 2 and 4.1)
  $Entities:   4 unsigned long; per entity: tag (int), its box (6 doubles, points too),
               numPhysicals (unsigned long) and the tags (int), curves and up: numBounding
               (unsigned long) and the tags (int)
  $Nodes:      numEntityBlocks numNodes (unsigned long); per block: tagEntity dimEntity parametric
               (int) numNodes (unsigned long); per node: tag (int), x y z (double) [u v (double)]
  $Elements:   numEntityBlocks numElements (unsigned long); per block: tagEntity dimEntity typeEle
               (int) numElements (unsigned long); per element: tag and its nodes (int)
Sections other than these are copied as they are ($PhysicalNames is ASCII in binary files too).

usage: msh40_to_binary.py panel_msh40.msh panel_msh40_binary.msh
"""
import struct
import sys

# Nodes of the element types panel.geo's mesh holds (the manual's table): point, line, triangle, quad.
NODES = {15: 1, 1: 2, 2: 3, 3: 4}


def sections(text):
    lines = text.split("\n")
    k = 0
    while k < len(lines):
        if lines[k].startswith("$") and not lines[k].startswith("$End"):
            name = lines[k][1:]
            end = lines.index("$End" + name, k)
            yield name, lines[k + 1:end]
            k = end + 1
        else:
            k += 1


def main(src, dst):
    text = open(src).read()
    out = bytearray()
    i32 = lambda v: out.extend(struct.pack("<i", int(v)))
    u64 = lambda v: out.extend(struct.pack("<Q", int(v)))
    f64 = lambda v: out.extend(struct.pack("<d", float(v)))
    for name, body in sections(text):
        out += ("$" + name + "\n").encode()
        if name == "MeshFormat":
            assert body[0].split() == ["4", "0", "8"], "expected an MSH 4.0 text file"
            out += b"4 1 8\n"
            i32(1)
            out += b"\n"
        elif name in ("Entities", "Nodes", "Elements"):
            t = iter(" ".join(body).split())
            if name == "Entities":
                counts = [next(t) for _ in range(4)]
                for c in counts:
                    u64(c)
                for dim, c in enumerate(counts):
                    for _ in range(int(c)):
                        i32(next(t))
                        for _ in range(6):
                            f64(next(t))
                        for _ in range(1 if dim == 0 else 2):
                            n = int(next(t))
                            u64(n)
                            for _ in range(n):
                                i32(next(t))
            elif name == "Nodes":
                blocks = int(next(t))
                u64(blocks)
                u64(next(t))
                for _ in range(blocks):
                    tag, dim, parametric, n = (int(next(t)) for _ in range(4))
                    i32(tag), i32(dim), i32(parametric), u64(n)
                    for _ in range(n):
                        i32(next(t))
                        for _ in range(3 + (dim if parametric else 0)):
                            f64(next(t))
            else:
                blocks = int(next(t))
                u64(blocks)
                u64(next(t))
                for _ in range(blocks):
                    tag, dim, typ, n = (int(next(t)) for _ in range(4))
                    i32(tag), i32(dim), i32(typ), u64(n)
                    for _ in range(n * (1 + NODES[typ])):
                        i32(next(t))
            assert next(t, None) is None, "$" + name + ": numbers left over"
            out += b"\n"
        else:
            out += ("\n".join(body) + "\n").encode()
        out += ("$End" + name + "\n").encode()
    open(dst, "wb").write(out)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
