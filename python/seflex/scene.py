"""Scenes from Python: seflex.Scene (load, build, edit, save) and seflex.run.

A Scene holds the scene file's YAML as Python data, with the names and units of docs/scenes.md
(degrees at the interface): entries are edited as attributes (``scene.springs["HL1"].preload = 10``)
and checked by the library when the scene is run, checked (``scene.check()``) or saved, with the
messages ``seflex run`` gives for the same file. seflex.run writes the command's files and returns the
histories as numpy arrays by column name.
"""
from __future__ import annotations

import collections
import copy
import csv
import json
import math
import os
import pathlib
import re
import shutil
import tempfile
from typing import Callable

from . import _seflex

__all__ = ["Scene", "Item", "Spring", "Items", "RunResult", "Event", "Lock", "run"]

_ORDER = ("title", "bodies", "ground", "connections", "hinges", "springs", "locks", "cables", "dampers", "loads",
          "drives", "integrator", "output")
_DEG = math.pi / 180.0


def _plain(v):
    """A value as YAML data (Items and Scenes become their dicts, tuples and arrays lists)."""
    if isinstance(v, Item):
        return copy.deepcopy(v._d)
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if hasattr(v, "tolist") and not isinstance(v, (str, bytes)):  # numpy arrays and scalars
        return _plain(v.tolist())
    if isinstance(v, os.PathLike):
        return os.fspath(v)
    return v


class Item:
    """One entry of a scene (a body, hinge, lock, cable, the integrator settings, ...): its YAML keys
    as attributes and items (``lock.stiffness``, ``lock["angle_deg"]``); nested maps are Items too
    (``scene.integrator.tolerance.position``). Assigning writes the scene; the library checks the
    value when the scene is run or checked."""

    __slots__ = ("_d",)

    def __init__(self, data: dict):
        object.__setattr__(self, "_d", data)

    def __getattr__(self, key):
        if key.startswith("__"):
            raise AttributeError(key)
        try:
            return self[key]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no '{key}' (keys: {', '.join(self._d)})") from None

    def __setattr__(self, key, value):
        if isinstance(getattr(type(self), key, None), property):
            object.__setattr__(self, key, value)
        else:
            self[key] = value

    def __delattr__(self, key):
        del self._d[key]

    def __getitem__(self, key):
        v = self._d[key]
        return Item(v) if isinstance(v, dict) else v

    def __setitem__(self, key, value):
        self._d[key] = _plain(value)

    def __contains__(self, key):
        return key in self._d

    def __dir__(self):
        return [*super().__dir__(), *self._d]

    def __eq__(self, other):
        return isinstance(other, Item) and self._d == other._d

    def get(self, key, default=None):
        """The value of `key`, or `default` when the scene does not give it."""
        return self[key] if key in self._d else default

    def to_dict(self) -> dict:
        """A deep copy of the entry's YAML data."""
        return copy.deepcopy(self._d)

    def __repr__(self):
        return f"{type(self).__name__}({self._d!r})"


class Spring(Item):
    """A hinge spring: torque_at_0, torque_at_ref and ref_angle_deg as in the YAML (the torque is linear
    in the angle: torque_at_0 + (torque_at_ref - torque_at_0) * angle / ref_angle), or a table; and,
    for the linear law, `preload` (the torque at angle 0, N m) and `stiffness` (N m/rad, positive when
    the torque falls as the hinge opens). Setting one keeps the other."""

    __slots__ = ()

    def _linear(self):
        if "table" in self._d:
            raise ValueError(f"spring '{_entry_name(self._d, 'spring', 0)}' is given by a table: edit spring.table")

    @property
    def preload(self) -> float:
        self._linear()
        return self._d["torque_at_0"]

    @preload.setter
    def preload(self, value: float):
        self._linear()
        k = self.stiffness if "torque_at_ref" in self._d else None
        value = _plain(value)
        self._d["torque_at_0"] = value
        if k is not None:
            self._d["torque_at_ref"] = value - k * self._d["ref_angle_deg"] * _DEG

    @property
    def stiffness(self) -> float:
        self._linear()
        if "torque_at_ref" not in self._d:
            return 0.0
        return (self._d["torque_at_0"] - self._d["torque_at_ref"]) / (self._d["ref_angle_deg"] * _DEG)

    @stiffness.setter
    def stiffness(self, value: float):
        self._linear()
        ref = self._d.setdefault("ref_angle_deg", 90.0)
        self._d["torque_at_ref"] = self._d["torque_at_0"] - _plain(value) * ref * _DEG


def _entry_name(d: dict, kind: str, index: int) -> str:
    """The name an entry is known by: bodies and hinges their name; springs, locks and dampers their
    name or else their hinge's; cables their name or loop1, loop2, ... (docs/scenes.md)."""
    if kind in ("bodies", "hinges"):
        return str(d.get("name", ""))
    if "name" in d:
        return str(d["name"])
    return f"loop{index + 1}" if kind == "cables" else str(d.get("hinge", ""))


_PREFIX = {"springs": "spring.", "locks": "lock.", "cables": "cable.", "dampers": "damper."}


class Items:
    """The entries of one list of a scene (bodies, hinges, springs, locks, cables, dampers, drives),
    in the file's order, also found by name: ``scene.springs["HL1"]`` (the name, or the hinge's for a
    spring, lock or damper without one; the output name ``spring.HL1`` works too), ``scene.springs[0]``.
    ``add(**keys)`` appends an entry, ``remove(name)`` deletes one."""

    def __init__(self, root: dict, key: str, item_type=Item):
        self._root, self._key, self._type = root, key, item_type

    def _list(self) -> list:
        return self._root.setdefault(self._key, [])

    def _index(self, name) -> int:
        if isinstance(name, int):
            return range(len(self._list()))[name]
        prefix = _PREFIX.get(self._key, "")
        for i, d in enumerate(self._list()):
            n = _entry_name(d, self._key, i)
            if name == n or (prefix and (prefix + name == n or name == prefix + n)):
                return i
        raise KeyError(f"no {self._key[:-1]} named '{name}' (there are: {', '.join(self.names()) or 'none'})")

    def names(self) -> list[str]:
        """The entries' names, in order."""
        return [_entry_name(d, self._key, i) for i, d in enumerate(self._list())]

    keys = names

    def __getitem__(self, name):
        return self._type(self._list()[self._index(name)])

    def __contains__(self, name):
        try:
            self._index(name)
            return True
        except (KeyError, IndexError):
            return False

    def __iter__(self):
        return (self._type(d) for d in self._list())

    def __len__(self):
        return len(self._list())

    def add(self, **keys):
        """Append an entry with these YAML keys (e.g. springs.add(hinge="HL1", torque_at_0=13.0)); returns it."""
        d = _plain(keys)
        self._list().append(d)
        return self._type(d)

    def remove(self, name):
        """Delete the entry `name` (or index)."""
        del self._list()[self._index(name)]

    def __repr__(self):
        return f"<{self._key}: {', '.join(self.names())}>"


_PLAIN_STR = re.compile(r"^[A-Za-z_/][A-Za-z0-9_./+-]*$")
_KEYWORDS = {"true", "false", "null", "yes", "no", "on", "off", "y", "n", "~"}


def _flow(v) -> str:
    """A value in YAML flow style (the subset yaml-cpp and docs/scenes.md use)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if v is None:
        return "null"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            return ".nan" if v != v else (".inf" if v > 0 else "-.inf")
        return repr(v)  # shortest decimal that reads back as the same double
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_flow(str(k))}: {_flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(_flow(x) for x in v) + "]"
    s = str(v)
    return s if _PLAIN_STR.match(s) and s.lower() not in _KEYWORDS else json.dumps(s)


def _yaml(d: dict) -> str:
    lines = []
    keys = [k for k in _ORDER if k in d] + [k for k in d if k not in _ORDER]
    for k in keys:
        v = d[k]
        if isinstance(v, list) and v:
            lines.append(f"{_flow(k)}:")
            lines += [f"  - {_flow(x)}" for x in v]
        elif isinstance(v, dict) and v:
            lines.append(f"{_flow(k)}:")
            lines += [f"  {_flow(str(kk))}: {_flow(x)}" for kk, x in v.items()]
        else:
            lines.append(f"{_flow(k)}: {_flow(v)}")
    return "\n".join(lines) + "\n"


class Scene:
    """A scene (docs/scenes.md) as Python data: ``Scene.load(path)`` or built here, edited, then
    ``seflex.run(scene)``.

        scene = seflex.Scene.load("sync-3d.yaml")
        scene.springs["HL1"].preload = 15.0           # N m at angle 0, the stiffness kept
        scene.locks["HL1"].stiffness = 8000.0         # N m/rad
        scene.integrator.t_end = 5.0
        r = seflex.run(scene)

    Lists (Items, by name or index): bodies, hinges, springs (Spring), locks, cables, dampers, drives.
    Maps (Item): integrator, output, loads. Also title, ground, connections. Relative superelement
    paths are relative to ``folder`` (the scene file's folder, or the one given to Scene()).
    Errors in the data are found by the library when the scene is run, checked or saved (InputError
    naming the key; line numbers are those of ``to_yaml()``, which ``save`` writes)."""

    def __init__(self, title: str | None = None, *, folder: str | os.PathLike | None = None):
        self._d: dict = {} if title is None else {"title": title}
        self.folder = folder if folder is not None else os.getcwd()
        self.path: pathlib.Path | None = None

    @property
    def folder(self) -> pathlib.Path:
        """The folder relative superelement paths start from (absolute)."""
        return self._folder

    @folder.setter
    def folder(self, value: str | os.PathLike):
        self._folder = pathlib.Path(value).absolute()

    @classmethod
    def load(cls, path: str | os.PathLike) -> "Scene":
        """Read a scene file, checked as `seflex run` checks it (InputError with its message)."""
        s = cls(folder=pathlib.Path(path).absolute().parent)
        s._d = _seflex._scene_tree(os.fspath(path))
        s.path = pathlib.Path(path)
        return s

    bodies = property(lambda self: Items(self._d, "bodies"), doc="the bodies (name, superelement, placement, inertia, ...)")
    hinges = property(lambda self: Items(self._d, "hinges"), doc="the hinges (name, parent, child, axis, angle_deg, rate_deg_s)")
    springs = property(lambda self: Items(self._d, "springs", Spring), doc="the hinge springs (Spring: preload, stiffness, ...)")
    locks = property(lambda self: Items(self._d, "locks"), doc="the hinge locks (hinge, angle_deg, stiffness, damping)")
    cables = property(lambda self: Items(self._d, "cables"), doc="the cable loops (name, pulley_a, pulley_b, stiffness, preload)")
    dampers = property(lambda self: Items(self._d, "dampers"), doc="the rotational dampers (hinge, coefficient)")
    drives = property(lambda self: Items(self._d, "drives"), doc="the hinge drives (hinge, kind, rate_deg_s, ramp_time)")
    integrator = property(lambda self: Item(self._d.setdefault("integrator", {})),
                          doc="the integrator settings (method, t_end, step, max_step, tolerance, stop, ...)")
    output = property(lambda self: Item(self._d.setdefault("output", {})), doc="the output settings (interval, animation)")
    loads = property(lambda self: Item(self._d.setdefault("loads", {})), doc="gravity and nodal loads")

    @property
    def title(self) -> str:
        return self._d.get("title", self.path.stem if self.path else "")

    @title.setter
    def title(self, value: str):
        self._d["title"] = str(value)

    @property
    def ground(self) -> list:
        """Interface nodes fixed to the ground ('body.node')."""
        return self._d.setdefault("ground", [])

    @property
    def connections(self) -> list:
        """Groups of interface nodes that are one node (['a.1', 'b.2'])."""
        return self._d.setdefault("connections", [])

    def to_dict(self) -> dict:
        """A deep copy of the scene's YAML data."""
        return copy.deepcopy(self._d)

    def to_yaml(self) -> str:
        """The scene as YAML text (what save writes, relative paths relative to ``folder``)."""
        return _yaml({k: v for k, v in self._d.items() if v not in ([], {})})

    def copy(self) -> "Scene":
        """An independent copy (for a sweep: edit the copy, keep the original)."""
        s = copy.copy(self)
        s._d = copy.deepcopy(self._d)
        return s

    def _source(self) -> tuple[str, str]:
        """(name in messages, whose folder anchors relative paths; the YAML text)."""
        name = f"{self.path.name} (edited)" if self.path else "scene (built in Python)"
        return os.fspath(self.folder / name), self.to_yaml()

    def check(self) -> None:
        """Check the scene as `seflex run` reads it (not the superelement files); raises InputError."""
        _seflex._check_scene(*self._source())

    def save(self, path: str | os.PathLike, *, overwrite: bool = False) -> None:
        """Write the scene as a YAML file that `seflex run` reads (checked first; relative superelement
        paths rewritten relative to the new file's folder). Refuses to replace a file unless overwrite."""
        path = pathlib.Path(path)
        if path.exists() and not overwrite:
            raise _seflex.InputError(f"{path}: exists already; refusing to overwrite it (use overwrite=True to replace it)")
        self.check()
        out = self.copy()
        for b in out._d.get("bodies", []):
            p = b.get("superelement")
            if isinstance(p, str) and not os.path.isabs(p):
                b["superelement"] = os.path.relpath(self.folder / p, path.absolute().parent)
        path.write_text(out.to_yaml())

    def __repr__(self):
        return (f"<seflex.Scene '{self.title}': {len(self.bodies)} bodies, {len(self.hinges)} hinges, "
                f"{len(self.springs)} springs, {len(self.locks)} locks, {len(self.cables)} cables>")


Event = collections.namedtuple("Event", "t kind name detail")
Event.__doc__ = "A line of events.csv: time [s], kind (lock, stop, warning, error, ...), name, detail."
Lock = collections.namedtuple("Lock", "t_latch peak_torque")
Lock.__doc__ = "A lock's latch time [s] (None: never latched) and peak |torque| after latching [N m] (None: never latched)."


class RunResult:
    """What seflex.run returns.

    histories  {column of history.csv: numpy array over the samples}, "t" included; read-only views of
               one block the result owns, equal to the CSV's numbers (which print the shortest decimal)
    columns    the column names in history.csv's order
    events     [Event(t, kind, name, detail)] as events.csv
    locks      {lock name: Lock(t_latch, peak_torque)} as summary.json
    summary    summary.json as a dict (status, final_t, steps, newton_iterations, cpu_time_s, ...)
    folder     where the files are (None: written to a temporary folder, since removed)
    """

    def __init__(self, data, folder, keep):
        rows = data.rows
        self.columns: list[str] = list(data.columns)
        self.histories: dict = {c: rows[:, j] for j, c in enumerate(self.columns)}
        with open(os.path.join(folder, "summary.json")) as f:
            self.summary: dict = json.load(f)
        with open(os.path.join(folder, "events.csv"), newline="") as f:
            self.events: list = [Event(float(r[0]), r[1], r[2], r[3]) for r in list(csv.reader(f))[1:]]
        self.locks: dict = {k: Lock(v["t_latch"], v["peak_abs_torque_after_latch"])
                            for k, v in self.summary.get("locks", {}).items()}
        self.folder = pathlib.Path(folder) if keep else None

    def __getitem__(self, column: str):
        return self.histories[column]

    def __repr__(self):
        n = len(self.histories.get("t", ()))
        return f"<seflex.RunResult: {n} samples x {len(self.columns)} columns, status {self.summary.get('status')}>"


def run(scene: Scene | str | os.PathLike, *, output: str | os.PathLike | None = None, overwrite: bool = False,
        t_end: float | None = None, step: float | None = None, formulation: str = "aic", animation: bool = False,
        progress: Callable[[float, float], object] | None = None, progress_interval: float = 0.2) -> RunResult:
    """Simulate a scene (a Scene, or the path of a scene file) as `seflex run SCENE -o OUTPUT` does.

    output       folder for history.csv, events.csv, poses.csv, summary.json/txt (default: a temporary
                 folder, removed after reading); results already there are replaced only if overwrite
    t_end, step  override integrator.t_end and the initial step (the command's --t-end, --step)
    formulation  "aic" (default), "ffrf-lm" or "rigid-lm" (--formulation)
    animation    write the VTK series the scene asks for (default False: --no-animation)
    progress     progress(t, t_end) is called with the GIL held at most every progress_interval s of
                 wall time; an exception it raises (or Ctrl-C) stops the run at its next step, the files
                 are finished, and the exception propagates
    The GIL is released while the run computes. Returns a RunResult. Raises seflex.InputError (the
    command's message) and seflex.ConvergenceError (the files in `output` hold the run up to it).
    """
    if progress is not None and not callable(progress):
        raise TypeError(f"progress expects a callable progress(t, t_end), got {type(progress).__name__}")
    if isinstance(scene, Scene):
        file, text = scene._source()
    else:
        file, text = os.fspath(scene), None
    keep = output is not None
    folder = os.fspath(output) if keep else tempfile.mkdtemp(prefix="seflex-run-")
    try:
        data = _seflex._run(file, text, folder, overwrite or not keep, t_end, step, formulation, animation, progress,
                            progress_interval)
        return RunResult(data, folder, keep)
    finally:
        if not keep:
            shutil.rmtree(folder, ignore_errors=True)
