"""Field analysis on numpy arrays: the C++ functions ``shockfield analyze`` calls, in-process.

A field is a float64, C-contiguous numpy array of shape (ny, nx) (2D) or (nz, ny, nx) (3D), so
that x varies fastest as in the field files; anything else raises TypeError or ValueError before
any work (convert with ``numpy.ascontiguousarray(a, dtype=numpy.float64)``). Bad values (NaN in a
cell, thresholds out of order) raise ``shockfield.InputError`` with the command line's message.
The computation releases the GIL and runs on ``threads`` OpenMP threads (0: OMP_NUM_THREADS, else
all cores). Estimators and conventions: docs/analysis-minkowski.md (Xu et al. (2015), §3.1).
"""

import numpy as np

from .box import Box
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

    Returns a numpy structured array, one row per threshold, with the columns of minkowski.csv
    under their bare names (minkowski.csv adds each one's unit, ``threshold_K``, ``L_m``; a numpy
    array carries none: docs/conventions.md):
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


def _table(columns, integers=()):
    """A dict of float64 columns as a structured array, the columns named in `integers` as int64."""
    return _structured({n: c.astype(np.int64) if n in integers else c for n, c in columns.items()})


_CLUSTER_INTEGERS = ("cluster", "size")
_DOMAIN_INTEGERS = ("domain", "atoms", "euler_characteristic", "manifold")
_VOID_INTEGERS = ("void", "cells", "surface_atoms", "euler_characteristic", "manifold")


def structure(positions, box, boundary="ppp", types=None, ids=None, coordination=None, cna=None,
              adaptive_cna=False, csp=None, bond_pairs=None, diamond=False, clusters=None, cluster_select=None,
              cluster_min_size=1, domains=None, domains_surface="rolling", domains_min_atoms=4, profile=None,
              pe=None, excess_energy=None, excess_crystal="fcc", burgers_lines=(), burgers_ids=(),
              burgers_clusters=False, burgers_orient=((1, 0, 0), (0, 1, 0), (0, 0, 1)), burgers_lattice=None,
              burgers_band=None, burgers_slab=None, burgers_spacing=None, voxel=None, voxel_smooth=0.0,
              voxel_select="acna:hcp", tracker=None, timestep=0, threads=0):
    """Per-atom structure of atoms, as ``shockfield analyze atoms`` computes it for one frame
    (docs/analysis-atoms.md), over one neighbour pass.

    ``positions``: float64 C-contiguous (n, 3) in Å; ``box``: ((xlo, ylo, zlo), (xhi, yhi, zhi)) or,
    for a LAMMPS restricted triclinic cell, (lo, hi, (xy, xz, yz)) — a shockfield.box.Box, as
    ``read_lammps_dump`` and ``read_lammps_data`` give, fits (lo, hi: the cell's corners, not its
    bounding box). In a tilted cell the neighbour analyses, clusters and profiles along z run;
    profiles along x or y, domains, voxels and Burgers circuits raise InputError (they grid or bin
    along the axes);
    ``boundary``: LAMMPS codes per axis ("ppp", "pps", ...); ``types`` 1-based and ``ids``
    (default all 1 and 1..n). Analyses (at least one): ``coordination`` (cutoff Å), ``cna``
    (conventional CNA cutoff Å), ``adaptive_cna``, ``csp`` ("fcc", "bcc" or an even N),
    ``bond_pairs`` (cutoff Å), ``diamond`` (cubic/hexagonal diamond, Maras et al. 2016).
    ``clusters`` (cutoff Å) with ``cluster_select`` (the CLI's ``--cluster-select`` language:
    "acna:hcp", "acna:!fcc", "csp>4", "dia:cubic", ...) and ``cluster_min_size`` clusters the
    selected atoms (Xu et al. (2015) §4.4.2); ``domains`` (Å: ball radius, or sculpting depth with
    ``domains_surface="packing"``) adds the clusters' surfaces (``--domains``), for clusters of at
    least ``domains_min_atoms`` atoms. ``profile`` (AXIS, WIDTH), e.g. ("z", 5.0): the atoms binned
    along the axis in bins of WIDTH Å from the box's lo face (``--profile z:5``). ``excess_energy``
    ("auto" or a reference e0 in eV) with ``pe`` (per-atom potential energies, eV): the per-atom
    excess energy pe − e0, e0 the median pe of the ``excess_crystal`` atoms ("fcc", "hcp", "bcc")
    for "auto" (``--excess-energy``, Xu et al. (2015) §3.2.3); ``cluster_select`` may then read
    "excess>VALUE". Burgers circuits (``--burgers-*``, Frank scheme FS/RH, Xu et al. (2015)
    §3.2.3): ``burgers_lines`` [(centre, axis, radius)] Å, ``burgers_ids`` [[id, id, id, ...]],
    ``burgers_clusters`` (around the line of each cluster), in the crystal of ``burgers_orient``
    (the crystal directions of x, y, z) with ``burgers_lattice`` (a, Å; default √2 × the median
    nearest-neighbour distance), ``burgers_band``, ``burgers_slab``, ``burgers_spacing``.
    ``voxel`` (node spacing h, Å; ``--voxel``): the fraction of the ``voxel_select`` atoms
    (default the hcp atoms of the adaptive CNA) on a grid by cloud-in-cell, Gaussian-smoothed by
    ``voxel_smooth`` Å — the phase field's order parameter ξ (Xu et al. (2015) §4.4.3).
    ``tracker`` (a ``ClusterTracker``, with ``clusters``): this frame's clusters continue its tracks
    (``--track``); ``timestep`` is the frame's (for the tracks' time).

    Returns a dict of arrays named like the CLI's dump columns: ``coord`` (int32),
    ``cna``/``acna``/``bpa`` (uint8 codes 1 fcc, 2 hcp, 3 bcc, 4 ico, 5 other) with
    ``<name>_counts`` dicts, ``csp`` (float64, Å²), ``dia`` (uint8, OVITO's codes 0 other, 1 cubic,
    2/3 its first/second neighbours, 4 hexagonal, 5/6 its neighbours), ``cluster`` (int32, 1, 2, ...
    largest first, 0 none), for bond pairs the CSR ``bond_offset``, ``bond_partner``,
    ``bond_index`` (Honeycutt–Andersen index); ``counts`` (dict: the count and fraction columns
    of structures.csv, ``<method>_<structure>_count`` and ``<method>_<structure>_fraction``);
    ``clusters`` (structured array: clusters.csv's columns after frame and timestep, ``cluster,
    size, x_A, y_A, z_A, a_A, b_A, c_A, axis1_x ... axis3_z, ellipsoid_volume_A3,
    ellipsoid_surface_A2, atomic_volume_A3``); ``domains`` (structured array: domains.csv's columns after frame and timestep),
    ``domain_surfaces`` (dict ``points``, ``triangles``: domains_<timestep>.vtp's triangles) and
    ``flat_domains`` (why each flat cluster has no surface; the CLI's warnings); ``profile``
    (structured array: profiles.csv's columns after frame and timestep, ``bin, lo_A, hi_A, centre_A,
    atoms`` and ``<method>_<structure>_fraction`` of each structure method that ran, then
    ``mean_excess_eV`` with an excess energy); ``excess`` (float64, eV; ``counts`` then has
    ``excess_reference_eV`` and ``excess_mean_eV``); ``burgers`` (structured array: burgers.csv's
    columns after frame and timestep, ``source``, ``b`` and ``kind`` as text), ``burgers_circuit``
    (int32 per atom: the circuit through it, 0 none) and ``burgers_skipped`` (automatic circuits
    that could not close, with why); ``voxels`` (dict: ``fraction`` and ``density`` shaped (nz,
    ny, nx), ``origin``, ``spacing``, ``stretch``, ``empty_nodes``, ``selected``: voxels_<timestep>.vti);
    with a tracker ``track`` (int32 per atom: its cluster's track, 0 none; the dump column).
    """
    box = Box.coerce(box)
    if domains_surface not in ("rolling", "packing"):
        raise ValueError(f"domains_surface: expected 'rolling' or 'packing', got {domains_surface!r}")
    profile_axis, profile_width = ("", 0.0) if profile is None else (str(profile[0]), float(profile[1]))
    if excess_crystal not in ("fcc", "hcp", "bcc"):
        raise ValueError(f"excess_crystal: expected 'fcc', 'hcp' or 'bcc', got {excess_crystal!r}")
    if excess_energy is not None and excess_energy != "auto" and not isinstance(excess_energy, (int, float)):
        raise ValueError(f"excess_energy: expected 'auto' or a reference energy in eV, got {excess_energy!r}")
    excess_auto = excess_energy == "auto"
    excess_reference = None if excess_energy is None or excess_auto else float(excess_energy)
    if pe is not None:
        pe = np.asarray(pe, dtype=np.float64)
        if pe.ndim != 1:
            raise ValueError(f"pe: expected one value per atom, an (n,) array, got shape {pe.shape}")
        pe = pe.tolist()
    burgers = None
    if len(burgers_lines) or len(burgers_ids) or burgers_clusters:
        burgers = {"lines": [(tuple(map(float, c)), tuple(map(float, a)), float(radius)) for c, a, radius in burgers_lines],
                   "ids": [[int(i) for i in ids] for ids in burgers_ids], "clusters": bool(burgers_clusters),
                   "orient": [tuple(int(v) for v in row) for row in burgers_orient], "lattice": burgers_lattice,
                   "band": burgers_band, "slab": burgers_slab, "spacing": burgers_spacing}
    r = _require_core().atoms_structure(
        positions, box.lo.tolist(), box.hi.tolist(), box.tilt.tolist(), boundary,
        None if types is None else np.asarray(types).tolist(), None if ids is None else np.asarray(ids).tolist(),
        coordination, cna, bool(adaptive_cna), None if csp is None else str(csp), bond_pairs, bool(diamond),
        clusters, cluster_select, int(cluster_min_size), domains, domains_surface, int(domains_min_atoms),
        profile_axis, profile_width, pe, excess_auto, excess_reference, excess_crystal, burgers,
        None if voxel is None else {"spacing": float(voxel), "smoothing": float(voxel_smooth), "select": str(voxel_select)},
        None if tracker is None else tracker._core, int(timestep), int(threads))
    if "clusters" in r:
        r["clusters"] = _table(r["clusters"], _CLUSTER_INTEGERS)
    if "domains" in r:
        d = r.pop("domains")
        r["domain_surfaces"], r["flat_domains"] = d.pop("surfaces"), d.pop("flat")
        r["domains"] = _table(d, _DOMAIN_INTEGERS)
    if "burgers" in r:
        r["burgers"] = _table({k: np.asarray(v) for k, v in r["burgers"].items()},
                              ("circuit", "atoms", "b_h6", "b_k6", "b_l6", "reliable"))
    if "profile" in r:
        r["profile"] = _table(r["profile"], ("bin", "atoms"))
    return r


class ClusterTracker:
    """Clusters followed through a series of frames (``shockfield analyze atoms --track``; Xu et al.
    (2015) §4.4.2, Figs 71–72): pass it to ``structure(..., clusters=..., cluster_select=...,
    tracker=tracker, timestep=t)`` frame by frame, in order. A cluster continues the track of the
    previous frame's cluster it shares most atom ids with."""

    def __init__(self):
        self._core = _require_core().ClusterTracker()

    @property
    def frames(self):
        """Frames added so far."""
        return self._core.frames

    def tracks(self, origin=0, dt=None):
        """tracks.csv as a structured array: ``track, frame, timestep, time_ps, cluster, size, x_A,
        y_A, z_A, a_A, b_A, c_A, L_A, ellipsoid_surface_A2, ellipsoid_volume_A3, atomic_volume_A3``,
        time_ps = (timestep − ``origin``) · ``dt`` with ``dt`` the MD time step in ps; without ``dt``
        the column is ``elapsed_timesteps`` = timestep − ``origin``."""
        core = self._core.tracks(int(origin), 1.0 if dt is None else float(dt), dt is not None)
        return _table(core, ("track", "frame", "timestep", "cluster", "size"))

    def growth(self, origin=0, dt=1.0):
        """growth.csv as a structured array: the power law y = C t^k of each quantity of each track
        with 3 or more points at t > 0: ``track, exponent, exponent_stderr, prefactor, points,
        quantity`` (named as its column of tracks.csv, ``L_A``, ``ellipsoid_volume_A3``, ...; C in its
        unit per (time unit)^k)."""
        g = self._core.growth(int(origin), float(dt))
        return _table({k: np.asarray(v) for k, v in g.items()}, ("track", "points"))


def voids(positions, box, probe, boundary="ppp", types=None, ids=None, atomic_volume=None, margin=None,
          min_volume=0.0):
    """The voids of a frame of atoms, as ``shockfield analyze atoms --voids PROBE`` finds them
    (docs/analysis-atoms.md; Xu et al. (2015) §3.2.3): the cavities of the atoms' Delaunay
    division (periodic images within ``margin`` Å of the faces included, default 15, at most half
    the box) for a ball of radius ``probe`` Å — regions the ball moves in without reaching the
    outside. ``atomic_volume`` (Å³) for missing_volume: default (box volume − voids) / atoms;
    ``min_volume`` (Å³) leaves smaller voids out. ``positions``, ``box``, ``boundary``,
    ``types``, ``ids`` as for ``structure``.

    Returns a dict: ``voids`` (structured array, one row per void, largest first, the columns of
    voids.csv after frame and timestep: ``void, cells, volume_A3, area_A2, equivalent_radius_A,
    missing_volume_A3, missing_radius_A, x_A, y_A, z_A, surface_atoms, euler_characteristic, manifold``) and
    ``surfaces`` (dict ``points`` (atoms and images), ``triangles``: voids_<timestep>.vtp's
    triangles, normals out of the voids). Runs with the GIL released, on one thread.
    """
    box = Box.coerce(box)
    r = _require_core().atoms_voids(
        positions, box.lo.tolist(), box.hi.tolist(), box.tilt.tolist(), boundary,
        None if types is None else np.asarray(types).tolist(), None if ids is None else np.asarray(ids).tolist(),
        float(probe), None if atomic_volume is None else float(atomic_volume),
        None if margin is None else float(margin), float(min_volume))
    surfaces = r.pop("surfaces")
    return {"voids": _table(r, _VOID_INTEGERS), "surfaces": surfaces}


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


def surface(points, radius=None, method="delaunay", depth=None):
    """The surface of ``points`` (float64 C-contiguous (n, 3)), as ``shockfield analyze geometry
    --surface-method METHOD`` writes it to surface.vtp and summary.txt (docs/geometry-giso.md;
    Xu et al. (2015) §3.2.3).

    ``method``: "delaunay" (the rolling ball of ``radius`` on the Delaunay division: every
    component the ball touches from outside), "pivot" (the paper's pivoting ball of ``radius``:
    the component on the point of largest x) or "packing" (packing-sculpting to the ``depth``).

    Returns a dict: ``points`` (float64 (k, 3), the points the triangles use, in surface.vtp's
    order), ``point_index`` (int32 (k,), their rows in ``points`` given), ``triangles`` (int32
    (m, 3) into the returned ``points``, normals outwards by the right-hand rule), ``area``,
    ``volume`` (enclosed), ``euler_characteristic`` (V − E + F) and ``manifold`` (every edge on
    two triangles, once each way). Runs with the GIL released, on one thread. A radius or depth
    the points do not allow (the ball falls through, sculpting removes everything) raises
    ``shockfield.InputError`` with the command line's message.
    """
    if method == "packing":
        if depth is None or radius is not None:
            raise ValueError("method 'packing' takes depth (the sculpting depth, a positive length), not radius")
        length = depth
    else:
        if radius is None or depth is not None:
            raise ValueError(f"method '{method}' takes radius (the ball's radius, a positive length); "
                             "depth is for method 'packing'")
        length = radius
    return _require_core().surface(points, str(method), float(length))
