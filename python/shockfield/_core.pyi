"""Type stubs of the compiled module shockfield._core (python/src/*.cpp). Use it through
shockfield.analysis, which documents each function."""

from typing import Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

Field = npt.NDArray[np.float64]  # float64, C-contiguous, (ny, nx) or (nz, ny, nx)

def minkowski(field: Field, thresholds: Optional[Sequence[float]] = None, count: int = 0,
              boundary: str = "periodic", connectivity: int = 8, adjacency: int = 26, dimension: int = 0,
              spacing: Sequence[float] = (1.0,), void: Optional[npt.NDArray[np.bool_]] = None,
              threads: int = 0) -> dict[str, np.ndarray]: ...
def similarity(reference: Sequence[Field], reference_threshold: float, candidate: Sequence[Field],
               times: Sequence[float], thresholds: Optional[Sequence[float]] = None, count: int = 0,
               t1: Optional[float] = None, t2: Optional[float] = None, boundary: str = "periodic",
               connectivity: int = 8, adjacency: int = 26, dimension: int = 0,
               spacing: Sequence[float] = (1.0,), threads: int = 0) -> dict[str, Union[np.ndarray, float]]: ...
def statistics(field: Field, bins: int = 64, dimension: int = 0, spacing: Sequence[float] = (1.0,),
               void: Optional[npt.NDArray[np.bool_]] = None, threads: int = 0) -> dict[str, object]: ...
def read_field(path: str, array: str = "") -> tuple[Field, Optional[npt.NDArray[np.bool_]],
                                                    tuple[float, float, float], tuple[float, float, float]]: ...
def read_series(path: str) -> list[tuple[float, str]]: ...
def gaussian_random_field(nx: int, ny: int, nz: int, correlation_length: float,
                          seed: int) -> tuple[Field, float]: ...
def atoms_structure(positions: npt.NDArray[np.float64], lo: Sequence[float], hi: Sequence[float], boundary: str,
                    types: Optional[Sequence[int]], ids: Optional[Sequence[int]], coordination: Optional[float],
                    cna: Optional[float], adaptive_cna: bool, csp: Optional[str], bond_pairs: Optional[float],
                    diamond: bool, clusters: Optional[float], cluster_select: Optional[str], cluster_min_size: int,
                    domains: Optional[float], domains_surface: str, domains_min_atoms: int, profile_axis: str,
                    profile_width: float, pe: Optional[Sequence[float]], excess_auto: bool,
                    excess_reference: Optional[float], excess_crystal: str, burgers: Optional[dict[str, object]],
                    voxel: Optional[dict[str, object]], threads: int) -> dict[str, object]: ...
def atoms_voids(positions: npt.NDArray[np.float64], lo: Sequence[float], hi: Sequence[float], boundary: str,
                types: Optional[Sequence[int]], ids: Optional[Sequence[int]], probe: float,
                atomic_volume: Optional[float], margin: Optional[float], min_volume: float) -> dict[str, object]: ...
def delaunay(points: npt.NDArray[np.float64], cluster_distance: float, rule: str) -> dict[str, object]: ...
def surface(points: npt.NDArray[np.float64], method: str, length: float) -> dict[str, object]: ...

class Simulation:
    """A case run in-process (python/src/simulation_bindings.cpp); use shockfield.Simulation."""
    method: str
    step_number: int
    time: float
    time_unit: str
    steps_left: int
    finished: bool
    closed: bool
    folder: str
    def __init__(self, case_file: str, overrides: Sequence[str], output: str, threads: int, overwrite: bool,
                 quiet: bool, resume: bool) -> None: ...
    def thermo(self) -> dict[str, float]: ...
    def step(self, n: int = 1) -> int: ...
    def finish(self) -> None: ...
    def stop(self) -> str: ...
    def arrays(self) -> dict[str, np.ndarray]: ...
    def fields(self) -> dict[str, np.ndarray]: ...
    def units(self) -> dict[str, str]: ...
