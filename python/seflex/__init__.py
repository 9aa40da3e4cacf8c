"""seflex from Python: FE models, normal modes, statics, Craig-Bampton superelements and scene runs.

    import seflex
    model = seflex.read_model("meshes/yoke.bdf")
    print(seflex.modes(model, 10).frequencies)            # Hz
    se = seflex.reduce(model, interface=[1, 3, 4], modes=5)
    se.K, se.M                                             # numpy views, owned by se
    se.save("yoke.se")
    scene = seflex.Scene.load("sync-3d.yaml")
    scene.springs["HL1"].preload = 15.0                    # N m, names as in the YAML
    r = seflex.run(scene, progress=lambda t, t_end: None)
    r.histories["HL1.phi_deg"], r.locks["lock.HL1"].t_latch, r.events, r.summary

Errors of the library are raised as seflex.InputError (a ValueError), seflex.ConvergenceError (a
RuntimeError) or seflex.Error (a RuntimeError) with the message the command line prints.
docs/python.md describes the API.
"""
from ._seflex import (  # noqa: F401
    ConvergenceError,
    Error,
    GridValues,
    InputError,
    Model,
    ModesResult,
    StaticResult,
    Superelement,
    load_superelement,
    modes,
    read_model,
    reduce,
    static,
)
from .scene import Event, Item, Items, Lock, RunResult, Scene, Spring, run  # noqa: F401

__all__ = [
    "ConvergenceError", "Error", "Event", "GridValues", "InputError", "Item", "Items", "Lock", "Model", "ModesResult",
    "RunResult", "Scene", "Spring", "StaticResult", "Superelement", "load_superelement", "modes", "read_model", "reduce",
    "run", "static",
]
