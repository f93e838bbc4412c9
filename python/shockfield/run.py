"""Run folders: what a run of any method wrote, as numpy arrays.

    run = shockfield.Run.open("runs/al_800")
    run.method, run.config["mpm"], run.derived, run.summary["results"]
    run.series["time_s"]              # series.csv as a numpy structured array
    for frame in run.frames():        # fields (.pvd of .vti) or atom dumps, in time order
        frame.time, frame.data

Tables are numpy structured arrays, one field per CSV column (numbers as float64, text as str);
``Run.table(name, pandas=True)`` gives a pandas DataFrame instead when pandas is installed.
"""

import binascii
import csv
import functools
import json
import pathlib
import re
import tomllib
import zlib
from dataclasses import dataclass, field

import numpy as np

from .box import Box
from .errors import InputError


def _malformed(what):
    """Decorates a reader of one file (its first argument): a file it cannot parse (bad bytes,
    numbers, structure) raises InputError naming the file and `what` was expected, never another
    exception (tests/python/test_plot.py mutates every kind of file)."""
    def decorate(reader):
        @functools.wraps(reader)
        def read(path, *args, **kwargs):
            try:
                return reader(path, *args, **kwargs)
            except InputError:
                raise
            except FileNotFoundError:
                raise InputError(f"{path}: no such file") from None
            except (ValueError, KeyError, IndexError, TypeError, AttributeError, zlib.error, binascii.Error) as error:
                raise InputError(f"{path}: not {what} ({type(error).__name__}: {error})") from None
        return read
    return decorate


@_malformed("a CSV table with a header line")
def read_csv(path, text=()):
    """A CSV file with a header line (lines starting with '#' skipped) as a structured array: a
    column whose every value is a number (an empty value: NaN) is float64, any other str, and so
    are the columns named in ``text`` (a text column whose rows all happen to read as numbers,
    e.g. burgers.csv's ``b`` = "0" for a circuit that closes, kept as the file writes it)."""
    with open(path, newline="") as f:
        rows = [row for row in csv.reader(line for line in f if not line.startswith("#")) if row]
    if not rows:
        raise InputError(f"{path}: no header line")
    header, body = rows[0], rows[1:]
    for number, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise InputError(f"{path}: row {number} has {len(row)} values for {len(header)} columns")
    columns = [_column([row[k] for row in body], as_text=name in text) for k, name in enumerate(header)]
    out = np.empty(len(body), dtype=[(name, c.dtype) for name, c in zip(header, columns)])
    for name, c in zip(header, columns):
        out[name] = c
    return out


def _column(values, as_text):
    """One CSV column: float64 when every value is a number (an empty one NaN) and not as_text, else str."""
    if not as_text:
        try:
            return np.array([float(v) if v.strip() else np.nan for v in values], dtype=np.float64)
        except ValueError:
            pass
    return np.array(values, dtype=str)


@_malformed("TOML")
def read_toml(path):
    """A TOML file (config.resolved.toml, hugoniot_fit.toml, a material file) as a dict;
    InputError naming the file when it is missing or not TOML."""
    with open(path, "rb") as f:
        return tomllib.load(f)


@_malformed("JSON")
def read_json(path):
    """A JSON file (summary.json) as a dict or list."""
    return json.loads(pathlib.Path(path).read_text())


@_malformed("a ParaView collection (.pvd)")
def read_pvd(path):
    """The frames a ParaView collection (.pvd) lists, as (time, absolute file path) in its order."""
    path = pathlib.Path(path)
    entries = re.findall(r'<DataSet\b[^>]*?timestep="([^"]+)"[^>]*?file="([^"]+)"', path.read_text())
    return [(float(t), str(path.parent / f)) for t, f in entries]


@_malformed("VTK PolyData with point arrays (.vtp)")
def read_points(path):
    """The points of a VTK PolyData file (.vtp) as a structured array, one row per point: the
    field ``points`` (3,) and one field per point-data array (vectors and tensors as subarrays)."""
    from .vtk_arrays import read_vtk_arrays
    arrays = read_vtk_arrays(path)
    rows = len(arrays["points"])
    fields = {name: a for name, a in arrays.items()
              if len(a) == rows and name not in ("connectivity", "offsets", "types")}  # not the vertex cells
    out = np.empty(rows, dtype=[(name, a.dtype, a.shape[1:]) for name, a in fields.items()])
    for name, a in fields.items():
        out[name] = a
    return out


@dataclass
class Frame:
    """One output frame: ``time`` (the method's unit), ``step`` (None for fields), ``data`` (a
    field as an array shaped (ny, nx) or (nz, ny, nx), void cells NaN; atoms, particles or a
    profile as a structured array of the file's columns or arrays), ``file``, and for dumps
    ``box`` (a shockfield.box.Box: lo, hi, tilt; ``box.cell`` the edge vectors)."""
    time: float
    data: np.ndarray
    file: str
    step: int = None
    box: Box = None
    extra: dict = field(default_factory=dict)


@_malformed("a LAMMPS text dump")
def read_lammps_dump(path):
    """The frames of a LAMMPS text dump ([ITEM: UNITS] / [ITEM: TIME] / ITEM: TIMESTEP / [TIME] /
    NUMBER OF ATOMS / BOX BOUNDS / ATOMS ...) as (step, time or None, box, atoms structured array)
    tuples; ``box`` is a shockfield.box.Box (lo, hi, tilt): the cell, converted from the bounding
    box and tilts of ``ITEM: BOX BOUNDS xy xz yz`` as LAMMPS's read_dump does; a column of names
    (``element``) is a string field, every other column float."""
    lines = pathlib.Path(path).read_text().splitlines()
    frames, i = [], 0
    try:
        while i < len(lines):
            time = None
            while lines[i].startswith(("ITEM: UNITS", "ITEM: TIME")) and not lines[i].startswith("ITEM: TIMESTEP"):
                if lines[i].startswith("ITEM: TIME"):
                    time = float(lines[i + 1])
                i += 2
            if not lines[i].startswith("ITEM: TIMESTEP"):
                raise InputError(f"{path}:{i + 1}: expected 'ITEM: TIMESTEP', got {lines[i]!r}")
            step, i = int(lines[i + 1]), i + 2
            if lines[i].startswith("ITEM: TIME"):
                time, i = float(lines[i + 1]), i + 2
            count = int(lines[i + 1])  # lines[i]: ITEM: NUMBER OF ATOMS, then ITEM: BOX BOUNDS
            # BOX BOUNDS [xy xz yz]: per line the bounds and, for a tilted cell, a tilt (xy, xz, yz)
            tilted = "xy xz yz" in lines[i + 2]
            bounds = [[float(v) for v in lines[i + 3 + k].split()[:3 if tilted else 2]] for k in range(3)]
            box = Box.from_bounds([b[:2] for b in bounds], [b[2] for b in bounds] if tilted else (0.0, 0.0, 0.0))
            names = lines[i + 6].split()[2:]
            rows = [lines[i + 7 + a].split() for a in range(count)]
            if any(len(row) != len(names) for row in rows):
                raise ValueError(f"rows of other than {len(names)} values")
            columns = [[row[k] for row in rows] for k in range(len(names))]
            dtypes = [("U16" if n == "element" else np.float64) for n in names]
            atoms = np.empty(count, dtype=list(zip(names, dtypes)))
            for n, dtype, column in zip(names, dtypes, columns):
                atoms[n] = column if dtype == "U16" else np.array(column, dtype=np.float64)
            frames.append((step, time, box, atoms))
            i += 7 + count
    except (IndexError, ValueError) as error:
        raise InputError(f"{path}: not a LAMMPS text dump near line {i + 1} ({error})") from None
    return frames


def read_lammps_data(path, boundary="ppp"):
    """A LAMMPS data file (atom style atomic), read by the library's parser (``[system] data_file``'s,
    docs/md-system.md; needs the compiled module), as a dict: ``box`` (a shockfield.box.Box: lo,
    hi, tilt (xy, xz, yz) of LAMMPS's restricted triclinic cell), ``boundary`` (the LAMMPS
    ``boundary`` codes the file is read with, e.g. "ppp"), ``title``, ``ids`` (int64), ``types``
    (int32, 1-based), ``positions`` ((n, 3) Å), ``images`` ((n, 3) int32), ``velocities`` ((n, 3)
    Å/ps; None without a Velocities section), ``masses`` (per type, amu; 0 where the file gives
    none) and ``elements`` (per type, "" where none). As LAMMPS read_data does, atoms outside a
    periodic box are mapped into it (images updated); a malformed file raises InputError naming
    the file and the line."""
    from .analysis import _require_core
    r = _require_core().read_lammps_data(str(path), boundary)
    r["box"] = Box.of(r.pop("lo"), r.pop("hi"), r.pop("tilt"))
    return r


class Run:
    """A run folder written by ``shockfield run`` (any method). Open with ``Run.open(folder)``."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        resolved = self.folder / "config.resolved.toml"
        if not resolved.is_file():
            raise InputError(f"{self.folder}: not a run folder (no config.resolved.toml)")
        self.config = read_toml(resolved)
        self.method = self.config.get("method")
        self.derived = self.config.get("derived", {})
        summary = self.folder / "summary.json"
        self.summary = read_json(summary) if summary.is_file() else None

    @classmethod
    def open(cls, folder):
        """The run in ``folder``; InputError when it holds no config.resolved.toml."""
        return cls(folder)

    @property
    def case_name(self):
        """The case file's name (summary.json's ``case``; "<folder>/case.toml" for a file named
        case.toml, as examples name theirs), else the run folder's name."""
        case = (self.summary or {}).get("case")
        if not case:
            return self.folder.name
        case = pathlib.Path(case)
        return f"{case.parent.name}/{case.name}" if case.name == "case.toml" and case.parent.name else case.name

    def title(self, what):
        """A figure title naming the run: "<method> run <folder> (<case file>): <what>"."""
        return f"{self.method} run {self.folder.name} ({self.case_name}): {what}"

    def value(self, key):
        """The first number named ``key`` in config.resolved.toml, in the file's order through its
        tables and arrays of tables ([derived] included); None when it has none."""
        return _first_number(self.config, key)

    def tables(self):
        """The CSV files of the folder (relative names), sorted."""
        return sorted(str(p.relative_to(self.folder)) for p in self.folder.rglob("*.csv"))

    def table(self, name, pandas=False, text=()):
        """The CSV file ``name`` (relative to the folder, ".csv" optional) as a structured array
        (the columns named in ``text`` as str, read_csv; with pandas their dtype str), or a pandas DataFrame with
        ``pandas=True``. InputError naming the tables the run holds when it has no such file."""
        path = self.folder / (name if name.endswith(".csv") else name + ".csv")
        if not path.is_file():
            raise InputError(f"{self.folder}: this {self.method} run has no {path.name}; its tables: "
                             f"{', '.join(self.tables()) or 'none'}")
        if pandas:
            import pandas as pd  # optional
            return pd.read_csv(path, comment="#", **({"dtype": {name: str for name in text}} if text else {}))
        return read_csv(path, text)

    def toml(self, name):
        """The TOML file ``name`` of the folder (relative, ".toml" optional: hugoniot_shock.toml,
        hugoniot_fit.toml, ...) as a dict. InputError naming the TOML files the run holds when it
        has no such file."""
        path = self.folder / (name if name.endswith(".toml") else name + ".toml")
        if not path.is_file():
            held = sorted(str(p.relative_to(self.folder)) for p in self.folder.rglob("*.toml"))
            raise InputError(f"{self.folder}: this {self.method} run has no {path.name}; its TOML files: "
                             f"{', '.join(held) or 'none'}")
        return read_toml(path)

    @property
    def thermo(self):
        """thermo.csv: the thermo table (every method)."""
        return self.table("thermo")

    @property
    def series(self):
        """series.csv: the method's time series (mpm windows, pd probes, ...)."""
        return self.table("series")

    @property
    def profiles(self):
        """profiles.csv (md), else profiles/index.csv (pd, dbm: one profile file per row)."""
        return self.table("profiles" if (self.folder / "profiles.csv").is_file() else "profiles/index")

    def frames(self, array="", kind=None):
        """Iterates over the run's frames in time order, of ``kind`` (default: the first the run
        has): "dumps" (LAMMPS dumps: md's, macroparticle's, and pd's and granular's with [output]
        dump = true; structured arrays of their columns), "fields" (the grid
        fields of its .pvd of .vti or .pvti files: mpm, dbm, phasefield; ``array`` names the data
        array, default the first), "profiles" (pd, dbm: profiles/profile_<k>.csv as structured arrays
        at the times of profiles/index.csv) or "particles" (the .pvd of .vtp or .pvtp files: mpm's
        particles, pd's points, granular's grains; structured arrays, ``read_points``).
        InputError naming its tables when it has none."""
        for frames_of_file in self._frame_files(array, kind):
            yield from frames_of_file()

    def last_frame(self, array="", kind=None):
        """The last frame ``frames(array, kind)`` would yield, reading only its file."""
        return list(self._frame_files(array, kind)[-1]())[-1]

    def _frame_files(self, array, kind):
        """One callable per file of the frames of ``kind``, in time order, each returning the
        file's frames (a dump file can hold several)."""
        dumps = sorted(self.folder.glob("dumps/*.lammpstrj"), key=_step_of) or sorted(
            self.folder.glob("*.lammpstrj"), key=_step_of)
        collections = sorted(self.folder.glob("*.pvd")) + sorted(self.folder.glob("profiles/*.pvd"))
        series = [p for p in collections if re.search(r'\.p?vti"', p.read_text())]  # .pvti: in pieces
        particles = [p for p in collections if re.search(r'\.p?vtp"', p.read_text())]
        index = self.folder / "profiles" / "index.csv"
        available = [k for k, present in (("dumps", dumps), ("fields", series), ("profiles", index.is_file()),
                                          ("particles", particles)) if present]
        if kind is None and available:
            kind = available[0]
        if kind not in available:
            raise InputError(f"{self.folder}: this {self.method} run has no {kind or 'frames'} (it has: "
                             f"{', '.join(available) or 'no frames'}); its tables: {', '.join(self.tables()) or 'none'}")
        if kind == "dumps":
            # Steps to time: the method's [<method>] timestep (md: ps), when it has a fixed one.
            timestep = self.config.get(self.method, {}).get("timestep")

            def dump_frames(path):
                return [Frame(time=step * timestep if time is None and timestep is not None else time, data=atoms,
                              file=str(path), step=step, box=box) for step, time, box, atoms in read_lammps_dump(path)]
            return [lambda path=path: dump_frames(path) for path in dumps]
        if kind == "profiles":
            table = read_csv(index)
            time_column = "time_s" if "time_s" in table.dtype.names else "time"
            files = [(float(row[time_column]), int(row["step"]), self.folder / "profiles" / f"profile_{int(row['profile'])}.csv")
                     for row in table]
            return [lambda t=t, step=step, file=file: [Frame(time=t, data=read_csv(file), file=str(file), step=step)]
                    for t, step, file in files]
        if kind == "particles":
            return [lambda t=t, file=file: [Frame(time=t, data=read_points(file), file=file)]
                    for t, file in read_pvd(particles[0])]
        from . import analysis
        core = analysis._require_core()

        def field_frame(time, file):
            values, _, spacing, origin = core.read_field(file, array)
            return [Frame(time=time, data=values, file=file, extra={"spacing": spacing, "origin": origin})]
        return [lambda t=t, file=file: field_frame(t, file) for t, file in core.read_series(str(series[0]))]

    def __repr__(self):
        status = self.summary.get("status") if self.summary else "no summary"
        return f"Run({str(self.folder)!r}, method={self.method!r}, {status})"


def _first_number(table, key):
    items = table.items() if isinstance(table, dict) else enumerate(table)
    for name, value in items:
        if name == key and isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value)
        if isinstance(value, (dict, list)):
            found = _first_number(value, key)
            if found is not None:
                return found
    return None


def _step_of(path):
    numbers = re.findall(r"\d+", path.name)
    return int(numbers[-1]) if numbers else 0
