"""Helpers the bench scripts share (bench/lib/): runs.py (run seflex, read a history, edit a scene, save
a chart), measures.py (the studies' error measures), plate.py (the clamped plate of the modes
benchmarks). A script imports them with bench/ on sys.path (`from lib import runs`); the scripts never
import each other (bench/lib/check_imports.py checks it)."""
