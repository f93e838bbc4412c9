#!/usr/bin/python3
"""Checks the output conventions of docs/conventions.md on run folders.

    conventions.py RUN_DIR [RUN_DIR ...]

Every .vti/.vtp file: each DataArray but a vertex cell's connectivity and offsets and VTK's
blanking array vtkGhostType carries a units attribute. Every .csv file: at most one time column (time, time_s, time_ps, Time), and
its name is the one of the method's unit system (the method is read from the run folder's
config.resolved.toml). The series.csv of a method listed in UNITS_IN_COLUMNS (and its other
files in UNITS_IN_FILES): every column carries its unit as a suffix (time_s, kinetic_J,
signal_depth_m) or is a pure number listed in DIMENSIONLESS. The totals of the MPM and PD series:
a unit suffix and, in 1D or 2D, the per-area or per-length label. Every checkpoint.h5 (docs/checkpoints.md; read with h5py): the root attributes
format, method (the run's), format_version, shockfield_version, git_commit, case (the text of the
run's config.resolved.toml), case_sha256 (its SHA-256) and case_input (the case as read: TOML,
naming the run's method); integer counters (step, format_version)
stored as integers; a units attribute on every dataset. Prints each violation with its file and
exits 1 if there is any.
"""
import hashlib
import pathlib
import re
import sys
import tomllib

TIME_COLUMNS = {"time", "time_s", "time_ps", "Time"}
# The time column of series-like CSVs per method: SI methods "time_s", MD (metal units)
# "time_ps", methods in model units "time". The thermo table keeps LAMMPS's "Time".
TIME_NAME = {"md": "time_ps", "mpm": "time_s", "pd": "time_s", "granular": "time_s", "macroparticle": "time_s",
             "dbm": "time", "phasefield": "time"}

# Methods whose series.csv names every column with its unit (docs/conventions.md, "Units in
# column names"); the others are listed there as not uniform yet.
UNITS_IN_COLUMNS = {"granular"}
SI_UNITS = ("s", "J", "m", "N", "Pa", "K", "kg", "m_s", "kg_m3", "J_kg", "kg_m_s")
DIMENSIONLESS = {"step", "steps", "profile", "grain", "count", "width_grains"}
# The files of those methods that follow the rule besides series.csv.
UNITS_IN_FILES = {"granular": {"series.csv", "probes.csv", "signal.csv", "energy_above.csv", "spacetime_force.csv",
                               "spacetime_velocity.csv"}}


# The extensive totals of the MPM and PD series (docs/conventions.md, "Per length and per area"):
# a unit suffix, then in a 1D or 2D run the label of the missing dimensions.
TOTAL_UNITS = ("kg", "kg_m_s", "J")
PER_MISSING = {1: "_per_m2", 2: "_per_m", 3: ""}


def dim_of(run):
    resolved = run / "config.resolved.toml"
    if resolved.exists():
        m = re.search(r"^dim = (\d)", resolved.read_text(), re.M)
        if m:
            return int(m.group(1))
    return 3


def check_totals(path, header, dim):
    per = PER_MISSING.get(dim, "")
    for c in header:
        base = c[: len(c) - len(per)] if per and c.endswith(per) else c
        if not re.match(r"^(mass|momentum|kinetic|internal|total)", c):
            continue
        if not any(base.endswith("_" + u) for u in TOTAL_UNITS):
            yield f"{path}: column '{c}' has no unit suffix (_{', _'.join(TOTAL_UNITS)})"
        elif per and not c.endswith(per):
            yield f"{path}: column '{c}' is a total of a {dim}D run; name it '{c}{per}'"


def method_of(run):
    resolved = run / "config.resolved.toml"
    if resolved.exists():
        m = re.search(r'^method = ["\x27](\w+)["\x27]', resolved.read_text(), re.M)
        if m:
            return m.group(1)
    return None


def check_vtk(path):
    text = path.read_bytes().split(b"<AppendedData")[0].decode("utf-8", "replace")
    for tag in re.findall(r"<DataArray[^>]*>", text):
        name = re.search(r'Name="([^"]+)"', tag)
        name = name.group(1) if name else "?"
        if name not in ("connectivity", "offsets", "vtkGhostType") and "units=" not in tag:
            yield f"{path}: DataArray '{name}' has no units attribute"


def check_csv(path, method, dim=3):
    with open(path) as f:
        header = f.readline().strip().split(",")
    times = [c for c in header if c in TIME_COLUMNS]
    if len(times) > 1:
        yield f"{path}: {len(times)} time columns {times}; expected one"
    if path.name == "thermo.csv" and times == ["Time"]:
        return  # the thermo table, LAMMPS's column names (docs/architecture.md)
    if times and method in TIME_NAME and times[0] != TIME_NAME[method]:
        yield f"{path}: time column '{times[0]}'; a {method} run names it '{TIME_NAME[method]}'"
    if path.name == "series.csv" and method in ("mpm", "pd"):
        yield from check_totals(path, header, dim)
    if path.name in UNITS_IN_FILES.get(method, {"series.csv"}) and method in UNITS_IN_COLUMNS:
        for c in header:
            if c not in DIMENSIONLESS and not any(c.endswith("_" + u) for u in SI_UNITS):
                yield f"{path}: column '{c}' has no unit suffix (_{', _'.join(SI_UNITS)})"


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
    for run in map(pathlib.Path, sys.argv[1:]):
        method = method_of(run)
        for path in sorted(run.rglob("*")):
            if path.suffix in (".vti", ".vtp"):
                problems += check_vtk(path)
            elif path.suffix == ".csv":
                problems += check_csv(path, method, dim_of(run))
            elif path.name == "checkpoint.h5":
                problems += check_checkpoint(path, method)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"ok: {len(sys.argv) - 1} run folders follow the output conventions")


if __name__ == "__main__":
    main()
