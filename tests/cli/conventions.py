#!/usr/bin/python3
"""Checks the output conventions of docs/conventions.md on run folders.

    conventions.py RUN_DIR [RUN_DIR ...] [--analysis ANALYSIS_DIR ...]

The folders after --analysis are output folders of `shockfield analyze atoms` (no case file, LAMMPS
metal units): their CSV tables (structures, clusters, profiles, tracks, growth, burgers, domains,
voids) and .vtp surfaces are checked as an MD run's, as the method "analyze_atoms".

A folder of `shockfield analyze geometry` (summary.txt with its simplices) is checked as such: every
name of summary.txt and column of clusters.csv a count or label (GEOMETRY_COUNTS) or a quantity of
GEOMETRY_QUANTITIES with its unit's suffix (x_m, total_volume_A3, _1, _unknown), units on its VTK
arrays.

The tables of the field analyses (`shockfield analyze minkowski|similarity|stats`: FIELD_TABLES),
in any folder given, are in the units of the field they read: every column is a pure number
(FIELD_DIMENSIONLESS) or a quantity of FIELD_QUANTITIES followed by its unit's suffix, `_1` (a pure
number or model unit) or `_unknown` (an input that names no unit); one time column `time_<unit>`.

Every .vti/.vtp file: each DataArray but a vertex cell's connectivity and offsets and VTK's
blanking array vtkGhostType carries a units attribute (an image its grid's, <ImageData
length_units>; every .pvd its times', <Collection time_units>, s / ps / 1 by the unit system), and an array named ux/uy/uz is not a
velocity (u is a displacement, v a velocity). Every .csv file: at most one time column (time,
time_s, time_ps, Time), and its name is the one of the method's unit system (the method is read
from the run folder's config.resolved.toml; a method without a unit system in UNIT_SYSTEM is
itself a violation, so the next method is checked from its first run). Every column of every CSV
of a method in SI or metal units carries its unit as a suffix (time_s, kinetic_J, rot2_per_s2,
then in 1D/2D totals the per-area or per-length label) or is a pure number (DIMENSIONLESS, or
a name ending in "count" or "fraction"); a column ux/uy/uz does not carry a velocity unit.
Exceptions, each named: the thermo table under LAMMPS's names (Step, Time, ...), a long-format
table (a "quantity" column: each row's quantity names the unit its values are in, and is checked
in place of the header), methods in dimensionless model units (no unit to name, but a column or
array named ux/uy/uz there is a velocity named u, reported) and the files
listed in NOT_YET_UNIFORM, which must still break the rule (an entry that passes is reported,
so the list only shrinks). The keys of summary.json's results that hold numbers follow the same
rule (docs/summary-json.md: units in the key names). The totals of the MPM and PD series and
summary.json results: a unit suffix and, in 1D or 2D, the per-area or per-length label. Every checkpoint.h5
(docs/checkpoints.md; read with h5py): the root attributes format, method (the run's), format_version, shockfield_version, git_commit, case (the text of the
run's config.resolved.toml), case_sha256 (its SHA-256) and case_input (the case as read: TOML,
naming the run's method); integer counters (step, format_version)
stored as integers; a units attribute on every dataset. Prints each violation with its file and
exits 1 if there is any.
"""
import fnmatch
import hashlib
import pathlib
import re
import sys
import tomllib

TIME_COLUMNS = {"time", "time_s", "time_ps", "Time"}
# The unit system of each method (docs/conventions.md): SI, LAMMPS metal units or dimensionless
# model units. A run of a method missing here is a violation.
UNIT_SYSTEM = {"md": "metal", "mpm": "si", "pd": "si", "granular": "si", "macroparticle": "si",
               "dbm": "model", "phasefield": "model", "analyze_atoms": "metal"}
# The time column of series-like CSVs per unit system. The thermo table keeps LAMMPS's "Time".
TIME_NAME = {"si": "time_s", "metal": "time_ps", "model": "time"}
# Unit suffixes per unit system, SI spelt with underscores for "/" and a trailing power
# (m_s = m/s, kg_m3 = kg/m³, per_s2 = 1/s²).
UNITS = {"si": ("s", "J", "m", "m2", "m3", "N", "Pa", "K", "kg", "m_s", "kg_m3", "J_kg", "kg_m_s", "per_s2"),
         "metal": ("ps", "eV", "bar", "A", "A2", "A3", "K", "A_ps", "eV_A", "GPa", "km_s", "g_cc")}
VELOCITY_UNITS = ("m_s", "A_ps", "km_s")
# Pure numbers: no unit suffix. Any name ending in "count" or "fraction" is one too. Indices and
# counts (MD's analyze tables: frame, timestep, atoms, a cluster's index and its size in atoms),
# then strains, ratios, crystal directions (PD's polycrystal grain_summary.csv: axis_h/k/l) and
# unit vectors (the principal axes of a cluster in clusters.csv: axis1_x ... axis3_z).
PURE_NUMBER_ENDINGS = ("count", "fraction")
DIMENSIONLESS = {"step", "steps", "profile", "grain", "bin", "particles", "plastic_bonds", "broken_bonds",
                 "damaged_points", "neighbor_rebuilds", "width_grains", "frame", "timestep", "atoms", "cluster", "size",
                 "collapsibility", "plastic", "max_plastic", "damage", "mean_damage", "strain", "lateral_strain",
                 "end_strain", "widest_spread_strain",
                 "poisson_secant", "energy_error", "schmid_factor", "accumulated_slip", "mean_accumulated_slip",
                 "axis_h", "axis_k", "axis_l", "final_axis_h", "final_axis_k", "final_axis_l",
                 # analyze atoms: growth time in timesteps (tracks.csv without --timestep-size), a
                 # growth law's exponent and its points, indices and counts of domains, voids and
                 # Burgers circuits, topology, b in a/6 on crystal axes, a circuit's unit axis, its
                 # largest step error in nearest-neighbour distances and its 0/1 flag.
                 "elapsed_timesteps", "exponent", "exponent_stderr", "points", "track", "domain", "void", "cells",
                 "surface_atoms", "euler_characteristic", "manifold", "circuit", "b_h6", "b_k6", "b_l6",
                 "axis_x", "axis_y", "axis_z", "max_step_error", "reliable"} | {
                 f"axis{k}_{d}" for k in (1, 2, 3) for d in "xyz"}
# Files known to break the unit rule, with the reason; each entry must still break it. The last CSV
# and JSON ones (MD's clusters.csv and structures.csv, PD's summary.json) follow it since issue 15.
NOT_YET_UNIFORM = {}
PER_MISSING_LABELS = ("_per_m", "_per_m2")

# The tables of `shockfield analyze minkowski|similarity|stats` (docs/conventions.md, "Field analysis
# tables"): in the units of the field read, named after its array's `units`, the grid's `length_units`
# and the .pvd's `time_units` (core/unit_names: Pa, kg_m3, m2, per_m, kg2_m6; 1; unknown).
FIELD_TABLES = {"minkowski.csv", "similarity.csv", "stats.csv", "histogram.csv", "structure_factor.csv",
                "correlation.csv"}
FIELD_QUANTITIES = ("domain_size_R", "threshold", "time", "mean", "std", "lo", "hi", "L", "S", "b", "M", "k", "r")
FIELD_DIMENSIONLESS = {"file", "candidate", "A", "V", "chi", "chi_per_black", "d_P", "S_D", "cells", "void_cells",
                       "skewness", "kurtosis", "count", "shell_points", "C"}
FIELD_UNIT = re.compile(r"1|unknown|(per_)?[A-Za-z]+\d*(_[A-Za-z]+\d*)*")


def check_field_table(path):
    header = next(csv_lines(path), [])
    times = [c for c in header if c == "time" or c.startswith("time_")]
    if len(times) != (0 if path.name == "similarity.csv" else 1):
        yield f"{path}: time columns {times}; expected one, time_<unit>"
    for c in header:
        if c in FIELD_DIMENSIONLESS:
            continue
        if not any(c.startswith(q + "_") and FIELD_UNIT.fullmatch(c[len(q) + 1:]) for q in FIELD_QUANTITIES):
            yield (f"{path}: column '{c}' has no unit suffix (a quantity of FIELD_QUANTITIES, then _<unit>, _1 "
                   "or _unknown) and is not a pure number")


# The outputs of `shockfield analyze geometry` (a folder with summary.txt, clusters.csv, delaunay.vtu,
# surface.vtp), in the length unit of the points read (core/unit_names: x_m, total_volume_A3, _1,
# _unknown): summary.txt's names and clusters.csv's columns are counts and labels (GEOMETRY_COUNTS)
# or a quantity of GEOMETRY_QUANTITIES with its unit's suffix.
GEOMETRY_COUNTS = {"index", "points", "duplicates", "simplices", "surface_triangles", "surface_euler_characteristic",
                   "surface_manifold", "seed_rule", "single_linkage", "seed_rule_clusters", "seed_rule_largest",
                   "seed_rule_shared_points", "single_linkage_clusters", "single_linkage_largest", "check"}
GEOMETRY_QUANTITIES = ("x", "y", "z", "total_volume", "total_area", "surface_area", "surface_volume")


def is_geometry_analysis(run):
    summary = run / "summary.txt"
    return summary.exists() and re.search(r"^simplices ", summary.read_text(), re.M) is not None


def check_geometry_analysis(run):
    names = [("summary.txt", line.split()[0]) for line in (run / "summary.txt").read_text().splitlines() if line.split()]
    if (run / "clusters.csv").exists():
        names += [("clusters.csv", c) for c in next(csv_lines(run / "clusters.csv"), [])]
    for file, name in names:
        if name not in GEOMETRY_COUNTS and not any(name.startswith(q + "_") and FIELD_UNIT.fullmatch(name[len(q) + 1:])
                                                   for q in GEOMETRY_QUANTITIES):
            yield (f"{run / file}: '{name}' has no unit suffix (a quantity of GEOMETRY_QUANTITIES, then _<unit>, _1 "
                   "or _unknown) and is not a count")
    for path in sorted(run.glob("*.vt[up]")):
        yield from check_vtk(path, None)


def unit_problem(column, system):
    """Why a column name breaks the unit rule of a unit system, or None."""
    if column in DIMENSIONLESS or column.endswith(PURE_NUMBER_ENDINGS):
        return None
    units = UNITS[system]
    base = next((column[: -len(p)] for p in PER_MISSING_LABELS
                 if column.endswith(p) and any(column[: -len(p)].endswith("_" + u) for u in units)), column)
    unit = next((u for u in sorted(units, key=len, reverse=True) if base.endswith("_" + u)), None)
    if unit is None:
        return f"column '{column}' has no unit suffix (_{', _'.join(units)}) and is not a pure number"
    if re.match(r"^(.*_)?u[xyz]_", base) and unit in VELOCITY_UNITS:
        return f"column '{column}' names a velocity u; u is a displacement, name a velocity v (vx, vy, vz)"
    return None


# The extensive totals of the MPM and PD series (docs/conventions.md, "Per length and per area"):
# a unit suffix, then in a 1D or 2D run the label of the missing dimensions.
TOTAL_UNITS = ("kg", "kg_m_s", "J")
PER_MISSING = {1: "_per_m2", 2: "_per_m", 3: ""}


def dim_of(run):
    """The run's dimensions: [grid] dim (mpm, pd), dimensions (phasefield); 2 for dbm (its D2V16
    lattice is 2D for every case); else 3."""
    resolved = run / "config.resolved.toml"
    if resolved.exists():
        text = resolved.read_text()
        m = re.search(r"^(dim|dimensions) = (\d)", text, re.M)
        if m:
            return int(m.group(2))
        if re.search(r'^method = ["\x27]dbm["\x27]', text, re.M):
            return 2
    return 3


def check_totals(path, header, dim, where="column"):
    per = PER_MISSING.get(dim, "")
    for c in header:
        base = c[: len(c) - len(per)] if per and c.endswith(per) else c
        if not re.match(r"^(mass|momentum|kinetic|internal|total)", c):
            continue
        if not any(base.endswith("_" + u) for u in TOTAL_UNITS):
            yield f"{path}: {where} '{c}' has no unit suffix (_{', _'.join(TOTAL_UNITS)})"
        elif per and not c.endswith(per):
            yield f"{path}: {where} '{c}' is a total of a {dim}D run; name it '{c}{per}'"


# The totals of the methods in model units (dbm, phasefield), and their label in 1D and 2D: no unit
# to name, "_per_length" (2D) or "_per_area" (1D) alone (core/units.hpp, units::model).
MODEL_TOTAL = re.compile(r"^(mass|momentum|energy|chemical_energy|total_energy|free_energy|hcp_volume|total_volume)")
MODEL_PER_MISSING = {1: "_per_area", 2: "_per_length", 3: ""}


def check_model_totals(path, names, dim, where="column"):
    per = MODEL_PER_MISSING.get(dim, "")
    for c in names:
        if per and MODEL_TOTAL.match(c) and not c.endswith(per):
            yield f"{path}: {where} '{c}' is a total of a {dim}D run (model units); name it '{c}{per}'"


def method_of(run):
    resolved = run / "config.resolved.toml"
    if resolved.exists():
        m = re.search(r'^method = ["\x27](\w+)["\x27]', resolved.read_text(), re.M)
        if m:
            return m.group(1)
    return None


# In dimensionless model units (dbm, phasefield) no unit tells a velocity from a displacement, and
# neither method has a displacement: a name u_x, u_y, u_z there is a velocity named u.
MODEL_UNIT_U = re.compile(r"^(.*_)?u[xyz](_.*)?$")


def model_unit_velocity(name, method, where):
    if UNIT_SYSTEM.get(method) == "model" and MODEL_UNIT_U.match(name):
        return (f"{where} '{name}' is a velocity in model units (a {method} run has no displacement); "
                "u is a displacement, name a velocity v (vx, vy, vz)")
    return None


def check_vtk(path, method):
    text = path.read_bytes().split(b"<AppendedData")[0].decode("utf-8", "replace")
    image = re.search(r"<P?ImageData[^>]*>", text)
    if image and "length_units=" not in image.group(0):
        yield from exempted(path, method, [f"{path}: <ImageData> names no length_units (the unit of its Origin and Spacing)"])
    for tag in re.findall(r"<DataArray[^>]*>", text):
        name = re.search(r'Name="([^"]+)"', tag)
        name = name.group(1) if name else "?"
        if name not in ("connectivity", "offsets", "types", "vtkGhostType") and "units=" not in tag:
            yield f"{path}: DataArray '{name}' has no units attribute"
        if re.fullmatch(r"u[xyz]", name) and re.search(r'units="[^"]*/s"', tag):
            yield f"{path}: DataArray '{name}' is a velocity; u is a displacement, name a velocity v (vx, vy, vz)"
        problem = model_unit_velocity(name, method, "DataArray")
        if problem:
            yield f"{path}: {problem}"


# The unit of a .pvd's times (<Collection time_units="...">) per unit system.
PVD_TIME_UNITS = {"si": "s", "metal": "ps", "model": "1"}


def check_pvd(path, method):
    system = UNIT_SYSTEM.get(method)
    if system is None:
        return
    m = re.search(r'<Collection[^>]*time_units="([^"]*)"', path.read_text())
    if not m:
        problem = f"{path}: <Collection> names no time_units; a {method} run's times are in '{PVD_TIME_UNITS[system]}'"
    elif m.group(1) != PVD_TIME_UNITS[system]:
        problem = f"{path}: time_units '{m.group(1)}'; a {method} run's times are in '{PVD_TIME_UNITS[system]}'"
    else:
        problem = None
    yield from exempted(path, method, [problem] if problem else [])


def csv_lines(path):
    """The lines of a CSV split at commas, comment lines (#) skipped."""
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                yield line.rstrip("\n").split(",")


def is_number(cell):
    try:
        float(cell)
        return True
    except ValueError:
        return False


def text_columns(path, header):
    """Columns holding text (a label, not a quantity: burgers.csv's source, b, kind): a cell that is
    not empty and not a number. A long-format table's quantity column is read separately."""
    rows = list(csv_lines(path))[1:]
    return {c for k, c in enumerate(header)
            if any(len(row) > k and row[k] and not is_number(row[k]) for row in rows)}


def check_units(path, header, system):
    """The unit rule on a CSV's columns, or on each row's quantity in a long-format table."""
    if "quantity" in header:
        k = header.index("quantity")
        names = sorted({row[k] for row in list(csv_lines(path))[1:] if len(row) > k})
        where = "quantity"
    else:
        text = text_columns(path, header)
        names, where = [c for c in header if c not in text], "column"
    for c in names:
        problem = unit_problem(c, system)
        if problem:
            yield f"{path}: {problem.replace('column', where, 1)}"


def check_csv(path, method, dim=3):
    header = next(csv_lines(path), [])
    times = [c for c in header if c in TIME_COLUMNS]
    if len(times) > 1:
        yield f"{path}: {len(times)} time columns {times}; expected one"
    if path.name == "thermo.csv" and header[:1] == ["Step"]:
        return  # the thermo table, LAMMPS's column names (docs/architecture.md)
    system = UNIT_SYSTEM.get(method)
    if system is None:
        return  # reported once per run folder (main)
    if times and times[0] != TIME_NAME[system]:
        yield f"{path}: time column '{times[0]}'; a {method} run names it '{TIME_NAME[system]}'"
    if path.name == "series.csv" and method in ("mpm", "pd"):
        yield from check_totals(path, header, dim)
    if system == "model":  # dimensionless model units: no unit to name, but velocities are v and totals labelled
        yield from (f"{path}: {p}" for p in filter(None, (model_unit_velocity(c, method, "column") for c in header)))
        yield from check_model_totals(path, header, dim)
        return
    yield from exempted(path, method, list(check_units(path, header, system)))


def result_keys(value, key=None):
    """The keys of summary.json's results that hold numbers (a list's elements count as its key's)."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from result_keys(v, k)
    elif isinstance(value, list):
        for v in value:
            yield from result_keys(v, key)
    elif isinstance(value, (int, float)) and not isinstance(value, bool) and key is not None:
        yield key


def check_summary(path, method, dim=3):
    """The unit rule on the keys of summary.json's results (docs/summary-json.md: units in the key
    names); for MPM and PD the totals' per-length or per-area labels in 1D and 2D, as their series."""
    import json
    system = UNIT_SYSTEM.get(method)
    if system is None:
        return
    keys = sorted(set(result_keys(json.loads(path.read_text()).get("results", {}))))
    if system == "model":
        yield from check_model_totals(path, keys, dim, "results key")
        return
    problems = [f"{path}: results {p.replace('column', 'key', 1)}"
                for p in filter(None, (unit_problem(k, system) for k in keys))]
    if method in ("mpm", "pd"):  # the per-area or per-length label of the totals that have a unit
        problems += check_totals(path, [k for k in keys if not unit_problem(k, system)], dim, "results key")
    yield from exempted(path, method, problems)


def exempted(path, method, problems):
    """The problems of a file, or for a file in NOT_YET_UNIFORM a note when it has none."""
    entry = next(((m, name) for m, name in NOT_YET_UNIFORM if m == method and fnmatch.fnmatch(path.name, name)), None)
    if entry is None:
        yield from problems
    elif not problems:
        yield f"{path}: follows the unit rule now; remove {entry!r} from NOT_YET_UNIFORM"


CHECKPOINT_ATTRIBUTES = ("format", "method", "format_version", "shockfield_version", "git_commit", "case",
                         "case_sha256", "case_input")


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def check_checkpoint(path, method):
    import h5py  # Debian python3-h5py (scripts/install-deps.sh)
    import numpy
    with h5py.File(path, "r") as f:
        attrs = f.attrs
        for a in CHECKPOINT_ATTRIBUTES:
            if a not in attrs:
                yield f"{path}: no root attribute '{a}'"
        if "format" in attrs and text(attrs["format"]) != "shockfield checkpoint":
            yield f"{path}: format '{text(attrs['format'])}', expected 'shockfield checkpoint'"
        for a in ("format_version", "step"):
            if a in attrs and not numpy.issubdtype(numpy.asarray(attrs[a]).dtype, numpy.integer):
                yield f"{path}: attribute '{a}' is not stored as an integer"
        if "case" in attrs:
            case = text(attrs["case"])
            resolved = path.parent / "config.resolved.toml"
            if resolved.exists() and case != resolved.read_text():
                yield f"{path}: attribute 'case' is not the run's config.resolved.toml"
            if "case_sha256" in attrs and hashlib.sha256(case.encode()).hexdigest() != text(attrs["case_sha256"]):
                yield f"{path}: attribute 'case_sha256' is not the SHA-256 of 'case'"
        if "case_input" in attrs:
            try:
                given = tomllib.loads(text(attrs["case_input"]))
                if method and given.get("method", method) != method:
                    yield f"{path}: attribute 'case_input' is not a {method} case"
            except tomllib.TOMLDecodeError as e:
                yield f"{path}: attribute 'case_input' is not TOML ({e})"
        # A variant of a method names itself after it: phasefield.sharp_front in a phasefield run.
        if method and "method" in attrs and text(attrs["method"]).split(".")[0] != method:
            yield f"{path}: method '{text(attrs['method'])}' in a {method} run"
        for name, dataset in f.items():
            if "units" not in dataset.attrs:
                yield f"{path}: dataset '{name}' has no units attribute"
            elif text(dataset.attrs["units"]) == "mixed":
                yield f"{path}: dataset '{name}' is an opaque mix ('mixed' units): store one dataset per quantity"


def main():
    problems = []
    args = sys.argv[1:]
    analysis = set(args[args.index("--analysis") + 1:]) if "--analysis" in args else set()
    folders = [a for a in args if a != "--analysis"]
    for run in map(pathlib.Path, folders):
        if is_geometry_analysis(run):
            problems += check_geometry_analysis(run)
            continue
        method = "analyze_atoms" if str(run) in analysis else method_of(run)
        if method not in UNIT_SYSTEM:
            problems.append(f"{run}: method {method!r} has no unit system in conventions.py (UNIT_SYSTEM); "
                            "give it one, so its outputs are checked")
        for path in sorted(run.rglob("*")):
            if path.suffix in (".vti", ".vtp", ".vtu"):
                problems += check_vtk(path, method)
            elif path.suffix == ".pvd":
                problems += check_pvd(path, method)
            elif path.suffix == ".csv" and path.name in FIELD_TABLES:
                problems += check_field_table(path)
            elif path.suffix == ".csv":
                problems += check_csv(path, method, dim_of(run))
            elif path.name == "summary.json":
                problems += check_summary(path, method, dim_of(run))
            elif path.name == "checkpoint.h5":
                problems += check_checkpoint(path, method)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"ok: {len(folders)} run and analysis folders follow the output conventions")


if __name__ == "__main__":
    main()
