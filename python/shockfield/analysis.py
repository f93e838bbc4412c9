"""Field analysis on numpy arrays: the C++ functions ``shockfield analyze`` calls, in-process.

A field is a float64, C-contiguous numpy array of shape (ny, nx) (2D) or (nz, ny, nx) (3D), so
that x varies fastest as in the field files; anything else raises TypeError or ValueError before
any work (convert with ``numpy.ascontiguousarray(a, dtype=numpy.float64)``). Bad values (NaN in a
cell, thresholds out of order) raise ``shockfield.InputError`` with the command line's message.
The computation releases the GIL and runs on ``threads`` OpenMP threads (0: OMP_NUM_THREADS, else
all cores). Estimators and conventions: docs/analysis-minkowski.md (Xu et al. (2015), §3.1).
"""

import numpy as np

from .errors import InputError  # noqa: F401  (raised by _core under this name)

try:
    from . import _core
except ImportError as error:  # built without pybind11: Case and Run still work
    _core = None
    _import_error = error

__version__ = _core.__version__ if _core is not None else "unknown"


def _require_core():
    if _core is None:
        raise ImportError(
            "shockfield.analysis and shockfield.Simulation need the compiled module shockfield._core, "
            f"which this build lacks ({_import_error}); install pybind11-dev and python3-pybind11 and rebuild")
    return _core


def _structured(columns):
    names = list(columns)
    out = np.empty(len(columns[names[0]]), dtype=[(n, columns[n].dtype) for n in names])
    for n in names:
        out[n] = columns[n]
    return out


def _spacing(spacing):
    return [float(s) for s in np.atleast_1d(spacing)]


def minkowski(field, thresholds=None, count=None, boundary="periodic", connectivity=8, adjacency=26,
              dimension=None, spacing=1.0, void=None, threads=0):
    """Minkowski functionals of the white set {field >= threshold} for every threshold, in one pass.

    Parameters are those of ``shockfield analyze minkowski``: ``thresholds`` (strictly increasing)
    or ``count`` evenly spaced over the field's range (32 when neither is given); ``boundary``
    "periodic" or "open"; ``connectivity`` 4 or 8 (2D white set); ``adjacency`` 26 or 6 (3D white
    set); ``dimension`` 3 analyses a 2D array as one layer of voxels; ``spacing`` h or (hx, hy, hz);
    ``void`` a bool array of the field's shape marking cells without material (black at every
    threshold).

    Returns a numpy structured array, one row per threshold, with the columns of minkowski.csv:
    2D ``threshold, A, L, chi, chi_per_black`` (area fraction, boundary length, Euler
    characteristic χ = N_W − N_B of eq. (32), χ/N of eq. (33)); 3D ``threshold, V, S, b, M, chi,
    chi_per_black`` (volume fraction, surface area, mean breadth, M = 2πb, χ, χ/N).
    """
    core = _require_core()
    columns = core.minkowski(field, None if thresholds is None else [float(t) for t in thresholds],
                             int(count or 0), boundary, int(connectivity), int(adjacency),
                             int(dimension or 0), _spacing(spacing), void, int(threads))
    return _structured(columns)


def similarity(reference, reference_threshold, candidate, times, thresholds=None, count=None, t1=None,
               t2=None, boundary="periodic", connectivity=8, adjacency=26, dimension=None, spacing=1.0,
               threads=0):
    """Dynamic similarity (Xu et al. (2015), §3.1, Figs. 42–45), as ``shockfield analyze similarity``.

    ``reference`` and ``candidate`` are sequences of fields, one per time in ``times``; the
    reference process is taken at ``reference_threshold``, the candidate at every threshold of
    ``thresholds`` (or ``count`` evenly spaced over the range of all the candidate fields). Returns a
    dict: ``thresholds``, the process distance ``d_P`` over [t1, t2] (default: the whole time
    range) and ``S_D = 1/d_P`` per candidate threshold, ``best_threshold`` and ``best_distance``.
    """
    core = _require_core()
    return core.similarity(list(reference), float(reference_threshold), list(candidate),
                           [float(t) for t in times],
                           None if thresholds is None else [float(t) for t in thresholds], int(count or 0),
                           t1, t2, boundary, int(connectivity), int(adjacency), int(dimension or 0),
                           _spacing(spacing), int(threads))


def statistics(field, bins=64, dimension=None, spacing=1.0, void=None, threads=0):
    """Statistics of the non-void cells, as ``shockfield analyze stats``.

    Returns a dict: ``cells``, ``void_cells``, ``mean``, ``std``, ``skewness``, ``kurtosis``
    (3 for a Gaussian), ``domain_size_R`` (2π/k₁ from the structure factor's first moment; 0 for a
    constant field), ``histogram_edges`` and ``histogram_counts`` (``bins`` bins over the range),
    ``structure_factor`` and ``correlation`` (dicts of ``x``, ``values``, ``count``; None for a
    constant field).
    """
    core = _require_core()
    return core.statistics(field, int(bins), int(dimension or 0), _spacing(spacing), void, int(threads))


def gaussian_random_field(shape, correlation_length, seed=1):
    """A periodic Gaussian random field of zero mean and unit variance with covariance
    ≈ exp(−r²/(2ℓ²)), ℓ = ``correlation_length`` cells, deterministic for a seed — the reference
    field of the Minkowski tests and benchmarks (docs/analysis-minkowski.md). ``shape`` is
    (ny, nx) or (nz, ny, nx). Returns the array."""
    shape = tuple(int(n) for n in shape)
    if len(shape) not in (2, 3):
        raise ValueError(f"shape: expected (ny, nx) or (nz, ny, nx), got {shape}")
    nz, ny, nx = (1,) + shape if len(shape) == 2 else shape
    return _require_core().gaussian_random_field(nx, ny, nz, float(correlation_length), int(seed))[0]


def structure(positions, box, boundary="ppp", types=None, ids=None, coordination=None, cna=None,
              adaptive_cna=False, csp=None, bond_pairs=None, threads=0):
    """Per-atom structure of atoms, as ``shockfield analyze atoms`` computes it for one frame
    (docs/analysis-atoms.md), over one neighbour pass.

    ``positions``: float64 C-contiguous (n, 3) in Å; ``box``: ((xlo, ylo, zlo), (xhi, yhi, zhi));
    ``boundary``: LAMMPS codes per axis ("ppp", "pps", ...); ``types`` 1-based and ``ids``
    (default all 1 and 1..n). Analyses (at least one): ``coordination`` (cutoff Å), ``cna``
    (conventional CNA cutoff Å), ``adaptive_cna``, ``csp`` ("fcc", "bcc" or an even N),
    ``bond_pairs`` (cutoff Å). Returns a dict of arrays named like the CLI's dump columns:
    ``coord`` (int32), ``cna``/``acna``/``bpa`` (uint8 codes 1 fcc, 2 hcp, 3 bcc, 4 ico, 5
    other) with ``<name>_counts`` dicts, ``csp`` (float64, Å²), and for bond pairs the CSR
    ``bond_offset``, ``bond_partner``, ``bond_index`` (Honeycutt–Andersen index).
    """
    lo, hi = box
    return _require_core().atoms_structure(
        positions, [float(v) for v in lo], [float(v) for v in hi], boundary,
        None if types is None else np.asarray(types).tolist(), None if ids is None else np.asarray(ids).tolist(),
        coordination, cna, bool(adaptive_cna), None if csp is None else str(csp), bond_pairs, int(threads))


def delaunay(points, cluster_distance=None, rule="both"):
    """The Delaunay division of ``points`` (float64 C-contiguous (n, 2) or (n, 3)) and, with a
    ``cluster_distance``, its point clusters, as ``shockfield analyze geometry`` computes them
    (docs/geometry-giso.md; Xu et al. (2015) §3.2.3). ``rule``: "xu2015" (the paper's seed rule),
    "single-linkage" or "both".

    Returns a dict: ``simplices`` (int32 (m, d+1), positively oriented, point indices),
    ``neighbours`` (int32 (m, d+1), the simplex across the face opposite each vertex, -1 on the
    hull), ``representative`` (per point, the first equal point), ``duplicates``,
    ``total_area``/``total_volume``, and per rule (``seed_rule``, ``single_linkage``) a dict with
    ``label`` per point, ``count``, ``size`` per cluster (seed rule also ``simplex_set``,
    ``shared_points``). Runs with the GIL released, on one thread (the division is serial).
    """
    return _require_core().delaunay(points, 0.0 if cluster_distance is None else float(cluster_distance), rule)
