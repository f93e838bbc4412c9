"""Every analysis entry point refuses every kind of bad array with a Python exception naming the
argument, never a crash (ctest python.test_bad_input).

The entry points: minkowski, statistics, similarity (its reference and its candidate fields),
structure, voids, delaunay, surface. The bad arrays: float32, int64 and complex dtypes, a list or
None instead of an array, one and four dimensions, a wrong number of columns, a strided slice, a
Fortran-ordered copy, an empty array, a NaN and an infinity in one entry. Dtype and type give
TypeError; layout, shape and emptiness ValueError; bad values InputError (a ValueError) naming the
value (NaN in a field: the cell, as the command line names the file's line). An empty atom list is
an empty frame, not an error: structure returns no counts (and no per-atom arrays). A crash would end this process, failing
the test. Case.set of a bad key or value (NaN, a string, a list, a negative size, a misspelt key)
raises InputError carrying the command line's message for the same --set, word for word.
Simulation's arrays: test_simulation.py.
"""

import os
import pathlib
import subprocess
import sys
import unittest

import numpy as np

import shockfield

A = shockfield.analysis
RNG = np.random.default_rng(23)
FIELD = RNG.normal(size=(16, 16))
LATTICE = np.ascontiguousarray(np.array(np.meshgrid(*[np.arange(3)] * 3, indexing="ij")).reshape(3, -1).T * 2.0 + 0.5)
BOX = ((0.0, 0.0, 0.0), (6.0, 6.0, 6.0))
SPHERE = RNG.normal(size=(300, 3))
SPHERE /= np.linalg.norm(SPHERE, axis=1)[:, None]

# name: (call on the array, a good array, the argument's name in messages, layout words)
ENTRIES = {
    "minkowski": (lambda a: A.minkowski(a, count=4), FIELD, "field", "expected a 2D"),
    "statistics": (lambda a: A.statistics(a), FIELD, "field", "expected a 2D"),
    "similarity reference": (lambda a: A.similarity([a, a], 0.0, [FIELD, FIELD], [0.0, 1.0], count=3), FIELD,
                             "reference field 0", "expected a 2D"),
    "similarity candidate": (lambda a: A.similarity([FIELD, FIELD], 0.0, [a, a], [0.0, 1.0], count=3), FIELD,
                             "candidate field 0", "expected a 2D"),
    "structure": (lambda a: A.structure(a, BOX, coordination=2.5), LATTICE, "positions", "expected an (n, 3)"),
    "voids": (lambda a: A.voids(a, BOX, 1.0), LATTICE, "positions", "expected an (n, 3)"),
    "delaunay": (lambda a: A.delaunay(a), SPHERE, "points", "expected an (n, 2) or (n, 3)"),
    "surface": (lambda a: A.surface(a, radius=0.5), SPHERE, "points", "expected an (n, 3)"),
}


def with_value(a, value):
    b = a.copy()
    b.flat[3] = value
    return b


def bad_arrays(good):
    """(what, array, exception, words in the message or None for pybind11's own argument error)."""
    columns = np.zeros((good.shape[0], 4)) if good.shape[1] == 3 else np.zeros((2, 2, 2, 2))
    return [
        ("float32", good.astype(np.float32), TypeError, "expected dtype float64, got float32"),
        ("int64", good.astype(np.int64), TypeError, "expected dtype float64, got int64"),
        ("complex", good.astype(complex), TypeError, "expected dtype float64, got complex128"),
        ("a list", good.tolist(), TypeError, None),
        ("None", None, TypeError, None),
        ("1 dimension", good.reshape(-1), ValueError, "layout"),
        ("4 dimensions", good.reshape((1, 1) + good.shape), ValueError, "layout"),
        ("4 columns", columns, ValueError, "layout"),
        ("strided", np.repeat(good, 2, axis=0)[::2], ValueError, "not C-contiguous"),
        ("Fortran order", np.asfortranarray(good), ValueError, "not C-contiguous"),
        ("empty", good[:0], ValueError, None),
        ("NaN", with_value(good, np.nan), shockfield.InputError, "nan"),
        ("inf", with_value(good, np.inf), shockfield.InputError, "inf"),
    ]


class BadArrays(unittest.TestCase):
    def test_every_entry_point_refuses_every_bad_array(self):
        for name, (call, good, argument, layout) in ENTRIES.items():
            call(good)  # the good array passes
            for what, array, error, words in bad_arrays(good):
                with self.subTest(entry=name, array=what):
                    if what == "empty" and name == "structure":
                        result = call(array)  # an empty frame: no atoms, no counts
                        self.assertEqual(result["counts"], {})
                        self.assertEqual(result.get("coord", np.zeros(0)).shape, (0,))
                        continue
                    with self.assertRaises(error) as caught:
                        call(array)
                    message = str(caught.exception)
                    if words is None:
                        continue
                    words = layout if words == "layout" else words
                    self.assertTrue(message.startswith(argument) or f"{argument}:" in message, message)
                    if what in ("NaN", "inf"):
                        self.assertRegex(message, f"non-finite|value {words}", message)
                    else:
                        self.assertIn(words, message)


class BadCaseValues(unittest.TestCase):
    def test_case_set_raises_the_command_lines_message(self):
        case_file = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests/cli/cases/mpm_tiny.toml"
        for key, value, text in (("loading.speed", float("nan"), "nan"), ("loading.speed", "fast", '"fast"'),
                                 ("loading.speed", [1, 2], "[1, 2]"), ("grid.cell_size", -1.0, "-1.0"),
                                 ("loading.sped", 1.0, "1.0")):
            with self.subTest(key=key, value=text):
                case = shockfield.Case.load(case_file)
                with self.assertRaises(shockfield.InputError) as caught:
                    case.set(key, value)
                self.assertEqual(case.overrides, [])  # the bad value is not kept
                cli = subprocess.run([os.environ["SHOCKFIELD_BIN"], "run", str(case_file), "--check", "--set",
                                      f"{key}={text}"], capture_output=True, text=True)
                self.assertEqual(cli.returncode, 2)
                self.assertEqual(str(caught.exception), cli.stderr.strip().removeprefix("error: "))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
