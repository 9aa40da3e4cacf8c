"""seflex from Python: FE models, normal modes, statics, Craig-Bampton superelements and scene runs.

    import seflex
    model = seflex.read_model("meshes/yoke.bdf")
    print(seflex.modes(model, 10).frequencies)            # Hz
    se = seflex.reduce(model, interface=[1, 3, 4], modes=5)
    se.K, se.M                                             # numpy views, owned by se
    se.save("yoke.se")
    r = seflex.run("scene.yaml", t_end=1.0)              # r.history["hinge1.phi_deg"], r.locks, r.summary

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
    RunResult,
    StaticResult,
    Superelement,
    load_superelement,
    modes,
    read_model,
    reduce,
    run,
    static,
)

__all__ = [
    "ConvergenceError", "Error", "GridValues", "InputError", "Model", "ModesResult", "RunResult", "StaticResult",
    "Superelement", "load_superelement", "modes", "read_model", "reduce", "run", "static",
]
