"""shockfield.analysis on numpy arrays against `shockfield analyze` on the same fields written
to files, and its refusals of bad arrays (ctest python.test_analysis; a few seconds).

Equality: the CLI writes minkowski.csv / stats.csv with 10 significant digits ({:.10g}), so a
value from Python must equal the CLI's to 1e-9 relative (integers, χ, exactly; similarity.csv
has 6 digits, so 1e-6 there); both call the same C++ functions on the same doubles, so anything
beyond that rounding is a real difference.
"""

import csv
import os
import pathlib
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import shockfield

SF = os.environ["SHOCKFIELD_BIN"]


def write_csv_field(path, field):
    """The CSV grid format of docs/analysis-minkowski.md: rows y = 0 first, slices separated by a
    blank line; repr() keeps every double exactly."""
    slices = field if field.ndim == 3 else field[np.newaxis]
    with open(path, "w") as f:
        f.write("\n\n".join("\n".join(",".join(repr(float(v)) for v in row) for row in s) for s in slices) + "\n")


def cli_table(*args):
    """The CLI's table, its columns under the Python API's names: a CSV grid that names no unit
    gives columns ending in `_unknown` (docs/conventions.md), the numpy results carry no unit."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([SF, "analyze", *args, "--no-plot", "-o", out], check=True, capture_output=True)
        name = {"minkowski": "minkowski.csv", "stats": "stats.csv", "similarity": "similarity.csv"}[args[0]]
        with open(pathlib.Path(out) / name) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        return [{key.removesuffix("_unknown"): value for key, value in row.items()} for row in rows]


def close(a, b, rel=1e-9):
    if np.isnan(a) or np.isnan(b):  # χ/N of a field without black cells: NaN on both sides
        return np.isnan(a) and np.isnan(b)
    return abs(a - b) <= rel * max(1.0, abs(a), abs(b))


class AgainstTheCommandLine(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)
        rng = np.random.default_rng(7)
        self.field2 = rng.normal(size=(24, 32)).cumsum(axis=1)  # ny = 24, nx = 32: x fastest
        self.field3 = rng.normal(size=(6, 8, 10))

    def tearDown(self):
        self.tmp.cleanup()

    def compare_minkowski(self, field, options, py_options):
        path = self.dir / "field.csv"
        write_csv_field(path, field)
        rows = cli_table("minkowski", str(path), *options)
        mine = shockfield.analysis.minkowski(field, **py_options)
        self.assertEqual(len(rows), len(mine))
        for row, m in zip(rows, mine):
            for name in mine.dtype.names:
                if name == "chi":
                    self.assertEqual(int(row[name]), int(m[name]))
                else:
                    self.assertTrue(close(float(row[name]), float(m[name])), (name, row[name], m[name]))
        return mine

    def test_2d_every_option(self):
        for boundary in ("periodic", "open"):
            for connectivity in (4, 8):
                m = self.compare_minkowski(
                    self.field2, ["-n", "9", "--boundary", boundary, "--connectivity", str(connectivity)],
                    dict(count=9, boundary=boundary, connectivity=connectivity))
                self.assertEqual(m.dtype.names, ("threshold", "A", "L", "chi", "chi_per_black"))

    def test_3d_and_single_layer(self):
        for adjacency in (6, 26):
            m = self.compare_minkowski(self.field3, ["-t", "-0.5,0,0.7", "--adjacency", str(adjacency)],
                                       dict(thresholds=[-0.5, 0.0, 0.7], adjacency=adjacency))
            self.assertEqual(m.dtype.names, ("threshold", "V", "S", "b", "M", "chi", "chi_per_black"))
        self.compare_minkowski(self.field2, ["-n", "5", "--dimension", "3"], dict(count=5, dimension=3))

    def test_statistics(self):
        path = self.dir / "field.csv"
        write_csv_field(path, self.field2)
        row = cli_table("stats", str(path), "--bins", "16")[0]
        s = shockfield.analysis.statistics(self.field2, bins=16, threads=2)
        for key in ("mean", "std", "skewness", "kurtosis", "domain_size_R"):
            self.assertTrue(close(float(row[key]), s[key]), (key, row[key], s[key]))
        self.assertEqual(int(row["cells"]), s["cells"])
        self.assertEqual(int(s["histogram_counts"].sum()), self.field2.size)

    def test_similarity(self):
        times = [0.0, 1.0, 2.0]
        ref = [self.field2 * (1 + 0.1 * k) for k in range(3)]
        cand = [self.field2 + 0.2 * k for k in range(3)]
        for k in range(3):
            write_csv_field(self.dir / f"r{k}.csv", ref[k])
            write_csv_field(self.dir / f"c{k}.csv", cand[k])
        rows = cli_table("similarity", *[str(self.dir / f"c{k}.csv") for k in range(3)], "-r",
                         *[str(self.dir / f"r{k}.csv") for k in range(3)], "--reference-threshold", "1.0",
                         "-n", "7", "--times", "0,1,2")
        s = shockfield.analysis.similarity(ref, 1.0, cand, times, count=7)
        self.assertEqual(len(rows), 7)
        for row, d in zip(rows, s["d_P"]):
            # similarity.csv prints d_P with the stream's 6 significant digits
            self.assertTrue(close(float(row["d_P"]), d, rel=1e-6), (row["d_P"], d))
        self.assertEqual(s["best_threshold"], s["thresholds"][int(np.argmin(s["d_P"]))])

    def test_read_field_round_trip(self):
        path = self.dir / "field.csv"
        write_csv_field(path, self.field3)
        values, void, spacing, origin = shockfield.analysis._core.read_field(str(path))
        self.assertTrue(np.array_equal(values, self.field3))
        self.assertIsNone(void)


class Threads(unittest.TestCase):
    def test_gil_released_and_threads_honoured(self):
        f = shockfield.analysis.gaussian_random_field((1024, 1024), 4.0, seed=3)
        one = shockfield.analysis.minkowski(f, count=64, threads=1)
        two = shockfield.analysis.minkowski(f, count=64, threads=2)
        for name in one.dtype.names:  # sums of integer block counts: independent of threads
            self.assertTrue(np.array_equal(one[name], two[name], equal_nan=True), name)
        # While a worker thread is inside minkowski, this thread keeps running (the GIL is
        # released): it wakes from 1 ms sleeps many times. Holding the GIL would leave it asleep
        # until the call returned (a few ticks at most).
        done, ticks, spent = threading.Event(), 0, []

        def work():
            t0 = time.perf_counter()
            shockfield.analysis.minkowski(f, count=256, threads=1)
            spent.append(time.perf_counter() - t0)
            done.set()

        worker = threading.Thread(target=work)
        worker.start()
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)
        worker.join()
        self.assertGreater(ticks, 10, f"{ticks} ticks during a {spent[0]:.3f} s call")
        print(f"ok: {ticks} ticks of this thread during a {spent[0]:.3f} s minkowski call in another")


class BadArrays(unittest.TestCase):
    def test_refusals(self):
        good = np.zeros((8, 8))
        cases = [
            (TypeError, "expected dtype float64", dict(field=good.astype(np.float32))),
            (TypeError, "expected dtype float64", dict(field=good.astype(np.int64))),
            (ValueError, "expected a 2D (ny, nx) or 3D (nz, ny, nx) array, got 1", dict(field=np.zeros(8))),
            (ValueError, "got 4 dimension", dict(field=np.zeros((2, 2, 2, 2)))),
            (ValueError, "not C-contiguous", dict(field=np.zeros((8, 16))[:, ::2])),
            (ValueError, "not C-contiguous", dict(field=np.zeros((8, 9)).T)),
            (ValueError, "the array is empty", dict(field=np.zeros((0, 8)))),
            (ValueError, "boundary: expected 'periodic' or 'open'", dict(field=good, boundary="wrap")),
            (ValueError, "connectivity: expected 4 or 8", dict(field=good, connectivity=6)),
            (ValueError, "void mask's shape", dict(field=good, void=np.zeros((4, 4), bool))),
            (shockfield.InputError, "give either thresholds or count", dict(field=good, thresholds=[0.5], count=3)),
        ]
        for error, message, kwargs in cases:
            with self.assertRaises(error, msg=message) as caught:
                shockfield.analysis.minkowski(**kwargs)
            self.assertIn(message, str(caught.exception))
        nan = good.copy()
        nan[2, 3] = np.nan
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.analysis.minkowski(nan, thresholds=[0.5])
        self.assertIsInstance(caught.exception, ValueError)
        self.assertIn("field", str(caught.exception))
        with self.assertRaises(shockfield.InputError):
            shockfield.analysis.minkowski(good, thresholds=[0.5, 0.2])
        print("ok: bad arrays refused; NaN ->", caught.exception)

    def test_void_mask(self):
        f = np.ones((8, 8))
        void = np.zeros((8, 8), bool)
        void[:, :4] = True
        m = shockfield.analysis.minkowski(f, thresholds=[0.5], void=void)
        self.assertEqual(m["A"][0], 0.5)
        # The next call reuses this thread's grid: nothing of the mask or the size may stay.
        self.assertEqual(shockfield.analysis.minkowski(f, thresholds=[0.5])["A"][0], 1.0)
        self.assertEqual(shockfield.analysis.minkowski(np.ones((4, 4)), thresholds=[0.5])["A"][0], 1.0)
        self.assertEqual(shockfield.analysis.minkowski(f, thresholds=[0.5], spacing=2.0)["L"][0], 0.0)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
