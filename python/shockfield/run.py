"""Run folders: what a run of any method wrote, as numpy arrays.

    run = shockfield.Run.open("runs/al_800")
    run.method, run.config["mpm"], run.derived, run.summary["results"]
    run.series["time_s"]              # series.csv as a numpy structured array
    for frame in run.frames():        # fields (.pvd of .vti) or atom dumps, in time order
        frame.time, frame.data

Tables are numpy structured arrays, one field per CSV column (numbers as float64, text as str);
``Run.table(name, pandas=True)`` gives a pandas DataFrame instead when pandas is installed.
"""

import csv
import json
import pathlib
import re
import tomllib
from dataclasses import dataclass, field

import numpy as np

from .errors import InputError


def read_csv(path):
    """A CSV file with a header line (lines starting with '#' skipped) as a structured array."""
    with open(path, newline="") as f:
        rows = [row for row in csv.reader(line for line in f if not line.startswith("#")) if row]
    if not rows:
        raise InputError(f"{path}: no header line")
    header, body = rows[0], rows[1:]
    for number, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise InputError(f"{path}: row {number} has {len(row)} values for {len(header)} columns")
    columns = []
    for k, name in enumerate(header):
        values = [row[k] for row in body]
        try:
            columns.append(np.array([float(v) for v in values], dtype=np.float64))
        except ValueError:
            columns.append(np.array(values, dtype=str))
    out = np.empty(len(body), dtype=[(name, c.dtype) for name, c in zip(header, columns)])
    for name, c in zip(header, columns):
        out[name] = c
    return out


@dataclass
class Frame:
    """One output frame: ``time`` (the method's unit), ``step`` (None for fields), ``data`` (a
    field as an array shaped (ny, nx) or (nz, ny, nx), void cells NaN; atoms or a pd profile as a
    structured array of the file's columns), ``file``, and for dumps ``box`` ((3, 2) bounds)."""
    time: float
    data: np.ndarray
    file: str
    step: int = None
    box: np.ndarray = None
    extra: dict = field(default_factory=dict)


def read_lammps_dump(path):
    """The frames of a LAMMPS text dump ([ITEM: UNITS] / [ITEM: TIME] / ITEM: TIMESTEP / [TIME] /
    NUMBER OF ATOMS / BOX BOUNDS / ATOMS ...) as (step, time or None, box, atoms structured array)
    tuples; a column of names (``element``) is a string field, every other column float."""
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
            box = np.array([[float(v) for v in lines[i + 3 + k].split()[:2]] for k in range(3)])
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


class Run:
    """A run folder written by ``shockfield run`` (any method). Open with ``Run.open(folder)``."""

    def __init__(self, folder):
        self.folder = pathlib.Path(folder)
        resolved = self.folder / "config.resolved.toml"
        if not resolved.is_file():
            raise InputError(f"{self.folder}: not a run folder (no config.resolved.toml)")
        with open(resolved, "rb") as f:
            self.config = tomllib.load(f)
        self.method = self.config.get("method")
        self.derived = self.config.get("derived", {})
        summary = self.folder / "summary.json"
        self.summary = json.loads(summary.read_text()) if summary.is_file() else None

    @classmethod
    def open(cls, folder):
        """The run in ``folder``; InputError when it holds no config.resolved.toml."""
        return cls(folder)

    def tables(self):
        """The CSV files of the folder (relative names), sorted."""
        return sorted(str(p.relative_to(self.folder)) for p in self.folder.rglob("*.csv"))

    def table(self, name, pandas=False):
        """The CSV file ``name`` (relative to the folder, ".csv" optional) as a structured array,
        or a pandas DataFrame with ``pandas=True``. InputError naming the tables the run holds
        when it has no such file."""
        path = self.folder / (name if name.endswith(".csv") else name + ".csv")
        if not path.is_file():
            raise InputError(f"{self.folder}: this {self.method} run has no {path.name}; its tables: "
                             f"{', '.join(self.tables()) or 'none'}")
        if pandas:
            import pandas as pd  # optional
            return pd.read_csv(path, comment="#")
        return read_csv(path)

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
        fields of its .pvd of .vti files: mpm, dbm, phasefield; ``array`` names the data array,
        default the first) or "profiles" (pd, dbm: profiles/profile_<k>.csv as structured arrays
        at the times of profiles/index.csv). InputError naming its tables when it has none."""
        dumps = sorted(self.folder.glob("dumps/*.lammpstrj"), key=_step_of) or sorted(
            self.folder.glob("*.lammpstrj"), key=_step_of)
        series = [p for p in sorted(self.folder.glob("*.pvd")) if ".vti" in p.read_text()]
        index = self.folder / "profiles" / "index.csv"
        available = [k for k, present in (("dumps", dumps), ("fields", series), ("profiles", index.is_file()))
                     if present]
        if kind is None and available:
            kind = available[0]
        if kind not in available:
            raise InputError(f"{self.folder}: this {self.method} run has no {kind or 'frames'} (it has: "
                             f"{', '.join(available) or 'no frames'}); its tables: {', '.join(self.tables()) or 'none'}")
        if kind == "dumps":
            # Steps to time: the method's [<method>] timestep (md: ps), when it has a fixed one.
            timestep = self.config.get(self.method, {}).get("timestep")
            for path in dumps:
                for step, time, box, atoms in read_lammps_dump(path):
                    if time is None and timestep is not None:
                        time = step * timestep
                    yield Frame(time=time, data=atoms, file=str(path), step=step, box=box)
        elif kind == "profiles":
            table = read_csv(index)
            time_column = "time_s" if "time_s" in table.dtype.names else "time"
            for row in table:
                file = self.folder / "profiles" / f"profile_{int(row['profile'])}.csv"
                yield Frame(time=float(row[time_column]), data=read_csv(file), file=str(file), step=int(row["step"]))
        else:
            from . import analysis
            core = analysis._require_core()
            for time, file in core.read_series(str(series[0])):
                values, _, spacing, origin = core.read_field(file, array)
                yield Frame(time=time, data=values, file=file, extra={"spacing": spacing, "origin": origin})

    def __repr__(self):
        status = self.summary.get("status") if self.summary else "no summary"
        return f"Run({str(self.folder)!r}, method={self.method!r}, {status})"


def _step_of(path):
    numbers = re.findall(r"\d+", path.name)
    return int(numbers[-1]) if numbers else 0
