# Type stubs of the seflex package (the compiled module seflex._seflex, re-exported).
from os import PathLike
from typing import Sequence

import numpy as np
import numpy.typing as npt

_Path = str | PathLike[str]
_F = npt.NDArray[np.float64]
_I = npt.NDArray[np.int32]

class Error(RuntimeError): ...
class InputError(ValueError): ...
class ConvergenceError(RuntimeError): ...

class Model:
    path: str
    ignore_unknown: bool
    files: list[str]
    grid_ids: _I
    counts: dict[str, int]
    element_counts: dict[str, int]
    warnings: list[str]
    def mass_properties(self, reference_grid: int | None = None) -> dict[str, float | _F]: ...

class GridValues:
    grids: _I
    values: _F  # n_grids x 6, read-only view
    def __len__(self) -> int: ...
    def __getitem__(self, grid: int) -> _F: ...

class ModesResult:
    eigenvalues: _F
    frequencies: _F
    radians: _F
    generalized_mass: _F
    generalized_stiffness: _F
    grids: _I
    shapes: _F  # modes x grids x 6, read-only view
    subcase: int
    warnings: list[str]
    def __len__(self) -> int: ...

class StaticResult:
    subcase: int
    displacements: GridValues
    loads: GridValues
    spc_forces: GridValues
    backward_error: float
    warnings: list[str]

class Superelement:
    name: str
    seflex_version: str
    source_file: str
    source_hash: str
    created: str
    source_warnings: list[str]
    frame_node: int
    num_modes: int
    size: int
    K: _F
    M: _F
    Phi_f: _F
    mode_frequencies: _F
    interface: _I
    interface_positions: _F
    frame_position: _F
    mass: float
    center_of_mass: _F
    inertia: _F
    fe_node_ids: list[int]
    recovery: _F
    def save(self, path: _Path, *, overwrite: bool = False) -> None: ...

def read_model(path: _Path, *, symbols: Sequence[str] | None = None, properties: _Path | None = None,
               parameters: dict[str, float] | None = None, ignore_unknown: bool = False) -> Model: ...
def modes(model: Model, count: int | None = None, *, subcase: int | None = None) -> ModesResult: ...
def static(model: Model, *, subcase: int | None = None) -> StaticResult: ...
def reduce(model: Model, *, interface: str | Sequence[int | str], modes: int | None = None, fmax: float | None = None,
           frame: int | str | None = None, name: str | None = None, eigensolver: str = "spectra",
           stiffening: bool = True, mesh: bool = True) -> Superelement: ...
def load_superelement(path: _Path) -> Superelement: ...

# Scenes and runs: python/seflex/scene.py (annotated Python).
from .scene import Event as Event, Item as Item, Items as Items, Lock as Lock, RunResult as RunResult
from .scene import Scene as Scene, Spring as Spring, run as run
