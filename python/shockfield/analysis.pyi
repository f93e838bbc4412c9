"""Type stubs of shockfield.analysis (docstrings in analysis.py)."""

from typing import Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from .box import Box

__version__: str
Field = npt.NDArray[np.float64]
# (lo, hi), (lo, hi, (xy, xz, yz)) or a Box
BoxLike = Union[Box, tuple[Sequence[float], Sequence[float]], tuple[Sequence[float], Sequence[float], Sequence[float]]]

def minkowski(field: Field, thresholds: Optional[Sequence[float]] = None, count: Optional[int] = None,
              boundary: str = "periodic", connectivity: int = 8, adjacency: int = 26,
              dimension: Optional[int] = None, spacing: Union[float, Sequence[float]] = 1.0,
              void: Optional[npt.NDArray[np.bool_]] = None, threads: int = 0) -> np.ndarray: ...
def similarity(reference: Sequence[Field], reference_threshold: float, candidate: Sequence[Field],
               times: Sequence[float], thresholds: Optional[Sequence[float]] = None, count: Optional[int] = None,
               t1: Optional[float] = None, t2: Optional[float] = None, boundary: str = "periodic",
               connectivity: int = 8, adjacency: int = 26, dimension: Optional[int] = None,
               spacing: Union[float, Sequence[float]] = 1.0, threads: int = 0) -> dict[str, object]: ...
def statistics(field: Field, bins: int = 64, dimension: Optional[int] = None,
               spacing: Union[float, Sequence[float]] = 1.0, void: Optional[npt.NDArray[np.bool_]] = None,
               threads: int = 0) -> dict[str, object]: ...
def gaussian_random_field(shape: Sequence[int], correlation_length: float, seed: int = 1) -> Field: ...
def structure(positions: npt.NDArray[np.float64],
              box: BoxLike, boundary: str = "ppp",
              types: Optional[Sequence[int]] = None, ids: Optional[Sequence[int]] = None,
              coordination: Optional[float] = None, cna: Optional[float] = None, adaptive_cna: bool = False,
              csp: Optional[Union[str, int]] = None, bond_pairs: Optional[float] = None, diamond: bool = False,
              clusters: Optional[float] = None, cluster_select: Optional[str] = None, cluster_min_size: int = 1,
              domains: Optional[float] = None, domains_surface: str = "rolling", domains_min_atoms: int = 4,
              profile: Optional[tuple[str, float]] = None, pe: Optional[Sequence[float]] = None,
              excess_energy: Optional[Union[str, float]] = None, excess_crystal: str = "fcc",
              burgers_lines: Sequence[tuple[Sequence[float], Sequence[float], float]] = (),
              burgers_ids: Sequence[Sequence[int]] = (), burgers_clusters: bool = False,
              burgers_orient: Sequence[Sequence[int]] = ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
              burgers_lattice: Optional[float] = None, burgers_band: Optional[float] = None,
              burgers_slab: Optional[float] = None, burgers_spacing: Optional[float] = None,
              voxel: Optional[float] = None, voxel_smooth: float = 0.0, voxel_select: str = "acna:hcp",
              tracker: Optional["ClusterTracker"] = None, timestep: int = 0, threads: int = 0) -> dict[str, object]: ...
class ClusterTracker:
    frames: int
    def __init__(self) -> None: ...
    def tracks(self, origin: int = 0, dt: Optional[float] = None) -> np.ndarray: ...
    def growth(self, origin: int = 0, dt: float = 1.0) -> np.ndarray: ...
def voids(positions: npt.NDArray[np.float64], box: BoxLike, probe: float,
          boundary: str = "ppp", types: Optional[Sequence[int]] = None, ids: Optional[Sequence[int]] = None,
          atomic_volume: Optional[float] = None, margin: Optional[float] = None,
          min_volume: float = 0.0) -> dict[str, object]: ...
def delaunay(points: npt.NDArray[np.float64], cluster_distance: Optional[float] = None,
             rule: str = "both") -> dict[str, object]: ...
def surface(points: npt.NDArray[np.float64], radius: Optional[float] = None, method: str = "delaunay",
            depth: Optional[float] = None) -> dict[str, object]: ...
