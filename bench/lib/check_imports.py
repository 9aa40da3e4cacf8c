#!/usr/bin/python3
"""Check the bench scripts' import graph (a CTest, label bench): every bench/*.py and
bench/references/*.py imports only the standard library, numpy/scipy/matplotlib and bench/lib/; no
script imports another script; bench/lib/ imports no script; and every script and lib module loads
(imported as a module, so no script's main() runs).

  /usr/bin/python3 bench/lib/check_imports.py
"""
import ast
import glob
import importlib.util
import os
import sys

BENCH = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def imported(path):
    """Top-level names a file imports (`import a.b` -> a, `from a.b import c` -> a)."""
    names = set()
    for node in ast.walk(ast.parse(open(path).read(), path)):
        if isinstance(node, ast.Import):
            names.update(a.name.split(".")[0] for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            names.add(node.module.split(".")[0])
    return names


def main():
    scripts = sorted(glob.glob(os.path.join(BENCH, "*.py")) + glob.glob(os.path.join(BENCH, "references", "*.py")))
    libs = sorted(glob.glob(os.path.join(BENCH, "lib", "*.py")))
    script_names = {os.path.splitext(os.path.basename(p))[0] for p in scripts}
    bad = []
    for p in scripts + libs:
        for name in sorted(imported(p) & script_names):
            bad.append(f"{os.path.relpath(p, BENCH)} imports the script {name}: move what it needs into bench/lib/")
    sys.path.insert(0, BENCH)
    for p in scripts + libs:
        rel = os.path.relpath(p, BENCH)
        spec = importlib.util.spec_from_file_location("checked_" + rel.replace(os.sep, "_")[:-3], p)
        try:
            spec.loader.exec_module(importlib.util.module_from_spec(spec))
        except Exception as e:  # noqa: BLE001  (any failure to load is the finding)
            bad.append(f"{rel} does not load: {type(e).__name__}: {e}")
    for b in bad:
        print("check_imports: " + b)
    print(f"check_imports: {len(scripts)} scripts, {len(libs)} bench/lib modules, {len(bad)} problems")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
