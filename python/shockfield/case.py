"""Cases: load, change, check and run a case file through the ``shockfield`` command.

``Case`` keeps the case file and the ``--set`` values given to it; ``check()`` and ``run()``
call the same ``shockfield run`` the command line does, so a run from Python is the command
line's run, byte for byte, and every mistake raises the command line's message.
"""

import contextlib
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import tomllib

from .errors import InputError, RunError, StopRequested


def shockfield_command():
    """The ``shockfield`` executable: $SHOCKFIELD_BIN, else the one installed beside this package
    (PREFIX/bin for PREFIX/lib/pythonX.Y/...-packages/shockfield), else the build tree's (BUILD for
    BUILD/python/shockfield), else ``shockfield`` on PATH."""
    chosen = os.environ.get("SHOCKFIELD_BIN")
    if chosen:
        return chosen
    here = pathlib.Path(__file__).resolve().parent
    for candidate in (here.parents[3] / "bin" / "shockfield", here.parents[1] / "shockfield"):
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    found = shutil.which("shockfield")
    if found:
        return found
    raise InputError("the shockfield command was not found beside this package nor on PATH; set SHOCKFIELD_BIN")


def toml_value(value):
    """``value`` in TOML syntax, as ``--set KEY=VALUE`` takes it."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value) or math.isinf(value):
            return ("-inf" if value < 0 else "inf") if math.isinf(value) else "nan"
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if hasattr(value, "item"):  # numpy scalars
        return toml_value(value.item())
    raise InputError(f"cannot write {value!r} ({type(value).__name__}) as a TOML value")


def _toml_key(key):
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else toml_value(str(key))


def toml_text(table, prefix=""):
    """A TOML document of nested dicts: sub-dicts as [tables], lists of dicts as [[arrays]]."""
    lines, nested = [], []
    for key, value in table.items():
        if isinstance(value, dict):
            nested.append((key, value, False))
        elif isinstance(value, (list, tuple)) and value and all(isinstance(v, dict) for v in value):
            nested.append((key, value, True))
        else:
            lines.append(f"{_toml_key(key)} = {toml_value(value)}")
    for key, value, is_array in nested:
        name = prefix + _toml_key(key)
        for item in value if is_array else [value]:
            lines.append("")
            lines.append(f"[[{name}]]" if is_array else f"[{name}]")
            lines.append(toml_text(item, name + "."))
    return "\n".join(lines)


def _error_from(process, what):
    message = process.stderr.strip()
    for prefix in ("error: ", "run stopped: "):
        message = "\n".join(line[len(prefix):] if line.startswith(prefix) else line for line in message.splitlines())
    if process.returncode == 2:
        return InputError(message)
    if process.returncode == 130:
        return StopRequested(message)
    return RunError(f"{what} failed (exit code {process.returncode}): {message}")


_PROGRESS = re.compile(r"^\S+ step (\d+)(?:/(\d+))? \((\d+)%\)")


class Case:
    """A case file and the values set on it. Make one with ``Case.load(path)`` or
    ``Case.from_dict(d)``."""

    def __init__(self, path=None, text=None, overrides=(), directory="."):
        self._path = None if path is None else pathlib.Path(path)
        self._text = text
        self._directory = pathlib.Path(directory)
        self.overrides = list(overrides)

    @classmethod
    def load(cls, path):
        """The case file at ``path`` (relative files it names are found beside it)."""
        path = pathlib.Path(path)
        if not path.is_file():
            raise InputError(f"{path}: no such case file")
        return cls(path=path)

    @classmethod
    def from_dict(cls, table, directory="."):
        """A case from nested dicts (as ``tomllib`` reads a case file); relative file names in it
        are found from ``directory``."""
        if not isinstance(table, dict):
            raise InputError(f"Case.from_dict: expected a dict, got {type(table).__name__}")
        return cls(text=toml_text(table) + "\n", directory=directory)

    def set(self, key, value):
        """Sets ``key`` (dotted, ``stage[1].steps`` for arrays of tables) to ``value``, as
        ``--set key=value`` does, and checks the case: an unknown key or a wrong value raises
        ``InputError`` with the command line's message (and leaves the case unchanged)."""
        override = f"{key}={toml_value(value)}"
        self.overrides.append(override)
        try:
            self.check()
        except InputError:
            self.overrides.pop()
            raise
        return self

    @contextlib.contextmanager
    def _case_file(self):
        """The case file's path for the time of a with block (a dict case written to a file
        beside the relative files it names, removed afterwards)."""
        if self._path is not None:
            yield self._path
            return
        handle = tempfile.NamedTemporaryFile("w", suffix=".toml", prefix=".case-", dir=self._directory, delete=False)
        with handle:
            handle.write(self._text)
        try:
            yield pathlib.Path(handle.name)
        finally:
            pathlib.Path(handle.name).unlink(missing_ok=True)

    @contextlib.contextmanager
    def _command(self):
        """``shockfield run CASE --set ...`` and a scratch folder, for the time of a with block."""
        with tempfile.TemporaryDirectory(prefix="shockfield-case-") as scratch, self._case_file() as case_file:
            command = [shockfield_command(), "run", str(case_file)]
            for override in self.overrides:
                command += ["--set", override]
            yield command, pathlib.Path(scratch)

    def check(self):
        """Validates the case as ``shockfield run --check`` does and returns its resolved values:
        a dict of every value read (defaults included) with the derived ones under "derived"."""
        with self._command() as (command, scratch):
            resolved = scratch / "config.resolved.toml"
            process = subprocess.run(command + ["--check", "--write-resolved", str(resolved)],
                                     capture_output=True, text=True)
            if process.returncode != 0:
                raise _error_from(process, "shockfield run --check")
            with open(resolved, "rb") as f:
                return tomllib.load(f)

    def run(self, output, threads=0, progress=None, overwrite=False, quiet=False):
        """Runs the case into the folder ``output`` and returns its ``Run``.

        ``threads``: OpenMP threads (0: OMP_NUM_THREADS, else all cores). ``progress``: called
        as ``progress(step, fraction)`` at each progress line (fraction in [0, 1]). The run's
        log lines go to this process's stdout unless ``quiet``. Raises ``InputError`` (bad case),
        ``RunError`` (the run failed; its folder is kept), ``StopRequested``.
        """
        from .run import Run

        with self._command() as (command, _):
            command += ["--output", str(output), "--threads", str(int(threads))]
            if overwrite:
                command.append("--overwrite")
            with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                  bufsize=1) as process:
                for line in process.stdout:
                    match = _PROGRESS.match(line)
                    if match and progress is not None:
                        progress(int(match.group(1)), int(match.group(3)) / 100.0)
                    if not quiet:
                        sys.stdout.write(line)
                stderr = process.stderr.read()
            if process.returncode != 0:
                raise _error_from(subprocess.CompletedProcess(command, process.returncode, "", stderr),
                                  "shockfield run")
            return Run.open(output)

    def simulation(self, output, threads=0, overwrite=False, quiet=True):
        """The case run in-process, stepped from Python: a ``shockfield.Simulation``."""
        from .simulation import Simulation

        return Simulation(self, output, threads=threads, overwrite=overwrite, quiet=quiet)

    def __repr__(self):
        source = str(self._path) if self._path is not None else "<dict>"
        return f"Case({source!r}, overrides={self.overrides!r})"
