#!/usr/bin/env python3
"""Reference reader for seflex superelement files (docs/superelement-format.md), in Python with numpy.

Usage:  /usr/bin/python3 scripts/read_superelement.py body.se        (prints a summary)
As a module:  from read_superelement import read_superelement; header, data = read_superelement("body.se")
`data` maps dataset names to numpy arrays (matrices column-major as stored, returned with their
true shape); the M_fe.* datasets are returned as a scipy.sparse CSC matrix under "M_fe". Format 1.2:
the inertia invariants are the "inv.*" datasets (all or none); the mesh part (fe_node_ids,
fe_positions, recovery, M_fe, cells) may be absent (`seflex reduce --no-mesh`).
"""
import hashlib
import json
import struct
import sys

import numpy as np

MAGIC, TRAILER = b"SEFLEXSE", b"SEFLXEND"
DTYPES = {"float64": "<f8", "int32": "<i4", "int64": "<i8"}


def read_superelement(path):
    raw = open(path, "rb").read()
    if len(raw) < 64 or raw[:8] != MAGIC:
        raise ValueError(f"{path}: not a seflex superelement file")
    major, minor, hlen = struct.unpack_from("<IIQ", raw, 8)
    if major != 1:
        raise ValueError(f"{path}: format {major}.{minor} not supported")
    body = raw[:-40]
    if raw[-40:-32] != TRAILER or hashlib.sha256(body).digest() != raw[-32:]:
        raise ValueError(f"{path}: truncated or corrupted (checksum mismatch)")
    header = json.loads(raw[24:24 + hlen].decode("utf-8"))
    data = {}
    for name, d in header["datasets"].items():
        a = np.frombuffer(raw, dtype=DTYPES[d["dtype"]], count=int(np.prod(d["shape"])), offset=d["offset"])
        data[name] = a.reshape(d["shape"], order="F")
    inv = [k for k in data if k.startswith("inv.")]
    if inv and len(inv) < 44:  # 11 single datasets and 6 + 6 + 6 + 3 + 3 + 3 + 3 + 3 array members
        raise ValueError(f"{path}: incomplete inertia invariants ({len(inv)} of 44 datasets)")
    if "M_fe.values" in data:
        import scipy.sparse as sp
        n = 6 * header["num_fe_nodes"]
        data["M_fe"] = sp.csc_matrix((data["M_fe.values"], data["M_fe.rowind"], data["M_fe.colptr"]), shape=(n, n))
    return header, data


if __name__ == "__main__":
    header, data = read_superelement(sys.argv[1])
    n = data["K"].shape[0]
    print(f"{header['name']}: {len(header['interfaces'])} interface nodes, {header['num_modes']} modes, n = {n}")
    print("mass", header["mass_properties"]["mass"], "K[0,0]", repr(float(data["K"][0, 0])),
          "trace(M)", repr(float(np.trace(data["M"]))))
    inv = sum(a.nbytes for k, a in data.items() if k.startswith("inv."))
    nfe = header["num_fe_nodes"]
    print(f"format {header['format_version']}; inertia invariants: {f'{inv} bytes' if inv else 'absent'}; "
          f"mesh part: {f'{nfe} FE nodes' if nfe else 'absent'}")
