"""The exceptions of shockfield, the command line's error classes in Python.

Each carries the message the ``shockfield`` command prints for the same mistake (its stderr line
without the ``error:`` / ``run stopped:`` prefix).
"""


class InputError(ValueError):
    """Bad input: a case file, a key given to ``Case.set``, an array, a run folder (exit code 2)."""


class RunError(RuntimeError):
    """A run that could not go on: NaN, lost atoms, a full disk (exit code 3; outputs kept)."""


class StopRequested(RuntimeError):
    """A run stopped on request (``--stop-after``, Ctrl-C) after writing its checkpoint (exit 130)."""


class StaleViewError(RuntimeError):
    """A ``Simulation``'s array storage moved or changed length during ``step()`` (docs/python.md):
    arrays taken before no longer show the simulation; take them again."""
