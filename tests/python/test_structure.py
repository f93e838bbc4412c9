"""shockfield.analysis.structure and .delaunay against the command line (ctest python.test_structure).

- structure(): a 4×4×4 fcc Cu crystal (256 atoms) with random displacements of 0.12 Å (so that
  some atoms are no longer fcc) written as a LAMMPS dump at full precision; `shockfield analyze
  atoms` with coordination, CNA, adaptive CNA, centro-symmetry and bond pairs writes the dump
  back with its per-atom columns at full precision: every column equals the Python result
  exactly (the same code on the same doubles), and the counts match structures.csv.
- delaunay(): 300 random points in the unit cube (and 200 in the unit square) as a CSV point
  file; `shockfield analyze geometry` writes the simplices (delaunay.vtu, ASCII connectivity)
  and both cluster labellings (clusters.csv): equal exactly; the total volume to its 12 printed
  digits.
- Bad arrays raise TypeError / ValueError, bad values InputError.
"""

import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import shockfield
from shockfield import analysis
from vtk_files import read_cells

SF = os.environ["SHOCKFIELD_BIN"]


def fcc_cu(repeat=4, a0=3.615, jitter=0.12, seed=3):
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    cells = np.array([[i, j, k] for i in range(repeat) for j in range(repeat) for k in range(repeat)])
    x = (cells[:, None, :] + basis[None, :, :]).reshape(-1, 3) * a0
    x += np.random.default_rng(seed).normal(scale=jitter, size=x.shape)
    return np.ascontiguousarray(x), (np.zeros(3), np.full(3, repeat * a0))


def write_dump(path, x, box, columns=None, bounds="pp pp pp", timestep=0):
    """One frame at full precision; `columns`: extra per-atom columns by name (e.g. pe)."""
    columns = columns or {}
    lines = ["ITEM: TIMESTEP", str(timestep), "ITEM: NUMBER OF ATOMS", str(len(x)), f"ITEM: BOX BOUNDS {bounds}"]
    lines += [f"{lo!r} {hi!r}" for lo, hi in zip(*box)]
    lines.append(" ".join(["ITEM: ATOMS id type x y z", *columns]))
    lines += [" ".join([f"{i + 1} 1 {p[0]!r} {p[1]!r} {p[2]!r}", *(repr(float(c[i])) for c in columns.values())])
              for i, p in enumerate(x)]
    path.write_text("\n".join(lines) + "\n")


def read_dump_columns(path):
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    rows = [line.split() for line in lines[start + 1:]]
    return {name: [row[k] for row in rows] for k, name in enumerate(names)}


class Structure(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_equals_analyze_atoms(self):
        x, box = fcc_cu()
        write_dump(self.dir / "cu.lammpstrj", x, box)
        process = subprocess.run([SF, "analyze", "atoms", str(self.dir / "cu.lammpstrj"), "-o", str(self.dir / "out"),
                                  "--coordination", "3.0", "--cna", "3.08", "--adaptive-cna", "--csp", "fcc",
                                  "--bond-pairs", "3.08", "-j", "2"], capture_output=True, text=True)
        self.assertEqual(process.returncode, 0, process.stderr)
        cli = read_dump_columns(next((self.dir / "out").glob("*.lammpstrj")))
        r = analysis.structure(x, box, coordination=3.0, cna=3.08, adaptive_cna=True, csp="fcc", bond_pairs=3.08,
                               threads=2)
        np.testing.assert_array_equal(r["coord"], np.array(cli["coord"], dtype=int))
        for name in ("cna", "acna", "bpa"):
            np.testing.assert_array_equal(r[name], np.array(cli[name], dtype=int), name)
        np.testing.assert_array_equal(r["csp"], np.array(cli["csp"], dtype=float))
        self.assertGreater(r["acna_counts"]["fcc"], 0)
        self.assertGreater(r["acna_counts"]["other"], 0)  # the jitter made some atoms non-fcc
        counts = np.genfromtxt(self.dir / "out" / "structures.csv", delimiter=",", names=True)
        for name in ("cna", "acna", "bpa"):
            for kind, n in r[f"{name}_counts"].items():
                self.assertEqual(int(counts[f"{name}_{kind}_count"]), n, f"{name}_{kind}_count")
        offset = r["bond_offset"]
        self.assertEqual((len(offset), offset[-1]), (len(x) + 1, len(r["bond_partner"])))
        one = analysis.structure(x, box, adaptive_cna=True, threads=1)
        np.testing.assert_array_equal(one["acna"], r["acna"])  # threads change nothing

    def test_equals_analyze_geometry(self):
        rng = np.random.default_rng(5)
        for dim, n, distance in ((3, 300, 0.12), (2, 200, 0.06)):
            with self.subTest(dim=dim):
                points = rng.random((n, dim))
                names = "xyz"[:dim]
                csv = self.dir / f"points{dim}.csv"
                csv.write_text(",".join(names) + "\n" + "".join(",".join(repr(v) for v in p) + "\n" for p in points))
                out = self.dir / f"geo{dim}"
                process = subprocess.run([SF, "analyze", "geometry", str(csv), "--dimension", str(dim), "-d",
                                          str(distance), "-o", str(out)], capture_output=True, text=True)
                self.assertEqual(process.returncode, 0, process.stderr)
                r = analysis.delaunay(points, cluster_distance=distance)
                _, cells = read_cells(out / "delaunay.vtu", dim + 1)
                np.testing.assert_array_equal(r["simplices"], cells)
                labels = np.genfromtxt(out / "clusters.csv", delimiter=",", names=True)
                np.testing.assert_array_equal(r["seed_rule"]["label"], labels["seed_rule"].astype(int))
                np.testing.assert_array_equal(r["single_linkage"]["label"], labels["single_linkage"].astype(int))
                summary = dict(line.split() for line in (out / "summary.txt").read_text().splitlines())
                total = r["total_volume" if dim == 3 else "total_area"]
                # a CSV names no unit: summary.txt says so (docs/conventions.md)
                self.assertEqual(f"{total:.12g}", summary["total_volume_unknown" if dim == 3 else "total_area_unknown"])
                self.assertEqual(int(summary["seed_rule_clusters"]), r["seed_rule"]["count"])
                self.assertGreater(r["single_linkage"]["count"], 1)

    def test_bad_arrays_raise(self):
        x, box = fcc_cu(repeat=2)
        with self.assertRaisesRegex(TypeError, "positions: expected dtype float64, got float32"):
            analysis.structure(x.astype(np.float32), box, adaptive_cna=True)
        with self.assertRaisesRegex(ValueError, r"positions: expected an \(n, 3\) array"):
            analysis.structure(np.ascontiguousarray(x[:, :2]), box, adaptive_cna=True)
        with self.assertRaisesRegex(ValueError, "not C-contiguous"):
            analysis.structure(np.asfortranarray(x), box, adaptive_cna=True)
        with self.assertRaises(shockfield.InputError):
            analysis.structure(x, box)  # no analysis asked for
        with self.assertRaises(shockfield.InputError):
            analysis.structure(x, box, adaptive_cna=True, ids=np.ones(len(x), dtype=int))  # duplicate ids
        with self.assertRaisesRegex(TypeError, "points: expected dtype float64"):
            analysis.delaunay(np.zeros((10, 3), dtype=np.int64))
        with self.assertRaisesRegex(ValueError, "points: expected an \\(n, 2\\) or \\(n, 3\\) array"):
            analysis.delaunay(np.zeros((10, 4)))
        with self.assertRaisesRegex(ValueError, "rule: expected"):
            analysis.delaunay(np.random.default_rng(1).random((10, 3)), 0.1, rule="nearest")
        with self.assertRaises(shockfield.InputError):
            analysis.delaunay(np.zeros((10, 3)))  # all points equal


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
