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
