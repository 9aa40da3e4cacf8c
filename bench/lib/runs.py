"""Running seflex from the bench scripts: a command with a timeout, a history CSV, scene edits, a chart
stamped with the command that made it."""
import csv
import re
import shutil
import subprocess
import os

import numpy as np


def sh(cmd, timeout=None):
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, f"killed after {timeout:g} s (--timeout)"
    return r.returncode, r.stdout + r.stderr


def read_history(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    names = rows[0]
    data = np.array([[float(x) if x else np.nan for x in r] for r in rows[1:]])
    return {n: data[:, i] for i, n in enumerate(names)}


def edit_scene(text, tol=None, method=None, step=None, stop=None, t_end=None, max_step=None):
    if tol is not None:
        text = re.sub(r"tolerance: \{position: [^,]+, angle: [^}]+\}", f"tolerance: {{position: {tol:g}, angle: {tol:g}}}", text)
    if stop is not None:
        text = re.sub(r"stop: \{after_all_locked: [^}]+\}", f"stop: {{after_all_locked: {stop:g}}}", text)
    if method == "rk4":
        text = re.sub(r"method: generalized-alpha\n", "", text)
        text = re.sub(r"integrator: \{", "integrator: {method: rk4, ", text) if "integrator: {" in text else text.replace("integrator:\n", "integrator:\n  method: rk4\n")
        text = re.sub(r"step: [0-9.eE+-]+", f"step: {step:g}", text, count=1)
    if t_end is not None:
        text = re.sub(r"t_end: [0-9.eE+-]+", f"t_end: {t_end:g}", text, count=1)
    if max_step is not None:
        text, k = re.subn(r"max_step: [0-9.eE+-]+", f"max_step: {max_step:g}", text, count=1)
        if not k:
            raise SystemExit("edit_scene: the scene has no max_step to change")
    return text


def save_figure(fig, out, name, img, cmd, bottom=0.03):
    """Save a chart with the command that made it under out/ (and a copy in img/ if given); bottom: the
    fraction of the height kept below the axes (the command, a figure legend)."""
    fig.text(0.01, 0.01, cmd, fontsize=6)
    fig.tight_layout(rect=(0, bottom, 1, 1))
    png = os.path.join(out, name)
    fig.savefig(png, dpi=110)
    if img:
        shutil.copy(png, img)
    return png
