"""seflex from Python: FE models, normal modes, statics and Craig-Bampton superelements.

    import seflex
    model = seflex.read_model("meshes/yoke.bdf")
    print(seflex.modes(model, 10).frequencies)            # Hz
    se = seflex.reduce(model, interface=[1, 3, 4], modes=5)
    se.K, se.M                                             # numpy views, owned by se
    se.save("yoke.se")

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

__all__ = [
    "ConvergenceError", "Error", "GridValues", "InputError", "Model", "ModesResult", "StaticResult",
    "Superelement", "load_superelement", "modes", "read_model", "reduce", "static",
]
