"""shockfield.analysis.voids and structure()'s diamond, clusters and domains against `shockfield
analyze atoms` on the same dump (ctest python.test_atom_analyses).

Frames (written at full precision, so the CLI reads the same doubles):
- voids: a periodic 6×6×6 fcc Cu crystal (a = 3.615 Å) less the atoms within 6 Å of the centre
  (tests/cli/analyze_voids.sh's void, smaller box); `--voids 2.17 --voids-margin 6`;
- domains: an 8×8×8 fcc crystal with a bcc inclusion of radius 7 Å at the centre (the same
  atomic volume; tests/cli/analyze_domains.sh's construction); `--clusters 3 --cluster-select
  acna:bcc --domains 3 --profile z:5 --voxel 2 --voxel-smooth 1 --voxel-select acna:bcc` (the
  voxel field equals voxels_0.vti's arrays exactly);
- diamond: 3×3×3 cells of cubic diamond Si (a = 5.431 Å) with 0.25 Å Gaussian displacements, so
  that some atoms leave the cubic-diamond class (measured: 104 cubic, 89 first and 23 second
  neighbours, 22 clusters; 0.15 Å leaves all 216 cubic); `--diamond --clusters 2.6
  --cluster-select dia:!cubic`.
- excess energy: test_structure's jittered 256-atom Cu crystal with a made-up pe column
  (−3.54 + 0.5 u², u uniform); `--adaptive-cna --excess-energy auto --profile z:3.6 --clusters 3
  --cluster-select excess>0.2`; a given e0 gives pe − e0.
- Burgers circuits: the unrelaxed Volterra edge dislocation a/2[1-10] of
  examples/md_dislocation_burgers (cylinder radius 22 Å, box ff ff pp) with a circuit about the
  line (b = [1 -1 0]/2, perfect) and one in good crystal (0); burgers.csv's rows as printed.
- tracks: the bcc inclusion of radius 5.5, 6.5, 7.5 Å at timesteps 1000-3000 through a
  ClusterTracker and through `--track --timestep-size 0.001`: tracks.csv, growth.csv and the
  track column equal.
Every per-atom column (acna, dia, cluster, excess, burgers_circuit, track) equals the CLI's dump column exactly, the counts and
fractions equal structures.csv as printed, and every row of voids.csv, domains.csv, clusters.csv and
profiles.csv equals the Python row
printed as the CLI prints it ({:.10g}); the surfaces' triangles equal the .vtp's (after the same
renumbering). The void must be one closed manifold (χ = 2) at the box centre, the domain one
(χ = 2): a check that the frames show what they should. 1 and 2 threads give the same result.
"""

import csv
import importlib.util
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import shockfield
from shockfield import _core, analysis
from test_structure import fcc_cu, read_dump_columns, write_dump
from vtk_files import read_cells

SF = os.environ["SHOCKFIELD_BIN"]
SOURCE = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"])
FCC = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])


def lattice(basis, a, n):
    cells = np.stack(np.meshgrid(*[np.arange(n)] * 3, indexing="ij"), -1).reshape(-1, 3)
    return (cells[:, None, :] + basis[None]).reshape(-1, 3) * a


def void_frame(a=3.615, n=6, radius=6.0):
    x, length = lattice(FCC, a, n), n * a
    x = x[np.linalg.norm(x - length / 2, axis=1) > radius]
    return np.ascontiguousarray(x), (np.zeros(3), np.full(3, length))


def inclusion_frame(a=3.615, n=8, radius=7.0):
    length, ab = n * a, a / 2 ** (1 / 3)  # bcc of fcc's atomic volume: 2 ab³ = a³/2
    x, centre = lattice(FCC, a, n), np.full(3, n * a / 2)
    m = int(np.ceil(radius / ab)) + 1
    g = np.stack(np.meshgrid(*[np.arange(-m, m + 1)] * 3, indexing="ij"), -1).reshape(-1, 3).astype(float)
    b = np.concatenate([g, g + 0.5]) * ab
    b = b[np.linalg.norm(b, axis=1) <= radius] + centre
    x = np.concatenate([x[np.linalg.norm(x - centre, axis=1) > radius], b])
    return np.ascontiguousarray(x), (np.zeros(3), np.full(3, length))


def diamond_frame(a=5.431, n=3, jitter=0.25, seed=4):
    basis = np.concatenate([FCC, FCC + 0.25])
    x = lattice(basis, a, n) + np.random.default_rng(seed).normal(scale=jitter, size=(8 * n ** 3, 3))
    return np.ascontiguousarray(x), (np.zeros(3), np.full(3, n * a))


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def renumbered(triangles):
    """The triangles on the points they use, numbered in order of first use (as the .vtp)."""
    index = {}
    return np.array([[index.setdefault(v, len(index)) for v in t] for t in triangles.tolist()], dtype=np.int32)


class AtomAnalyses(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def analyze(self, x, box, name, *options, columns=None, bounds="pp pp pp"):
        write_dump(self.dir / f"{name}.lammpstrj", x, box, columns, bounds)
        out = self.dir / name
        process = subprocess.run([SF, "analyze", "atoms", str(self.dir / f"{name}.lammpstrj"), "--no-plot", "-o",
                                  str(out), "-j", "2", *options], capture_output=True, text=True)
        self.assertEqual(process.returncode, 0, process.stderr)
        return out, read_dump_columns(out / f"{name}.lammpstrj")

    def assert_rows_printed_equal(self, table, rows, digits, fraction_digits=None):
        self.assertEqual(len(table), len(rows))
        for mine, theirs in zip(table, rows):
            for column in table.dtype.names:
                if table.dtype[column].kind == "i":
                    self.assertEqual(int(mine[column]), int(theirs[column]), column)
                else:
                    d = fraction_digits if fraction_digits and column.endswith("_fraction") else digits
                    self.assertEqual(f"{float(mine[column]):.{d}g}", theirs[column], column)

    def test_voids(self):
        x, box = void_frame()
        out, _ = self.analyze(x, box, "void", "--voids", "2.17", "--voids-margin", "6")
        r = analysis.voids(x, box, 2.17, margin=6.0)
        v = r["voids"]
        self.assertEqual(len(v), 1)
        self.assertEqual((v["euler_characteristic"][0], v["manifold"][0]), (2, 1))
        np.testing.assert_allclose([v["x_A"][0], v["y_A"][0], v["z_A"][0]], box[1] / 2, atol=1e-6)
        self.assert_rows_printed_equal(v, read_csv(out / "voids.csv"), 10)
        points, triangles = read_cells(out / "voids_0.vtp", 3)
        np.testing.assert_array_equal(renumbered(r["surfaces"]["triangles"]), triangles)
        used = list(dict.fromkeys(r["surfaces"]["triangles"].ravel().tolist()))
        np.testing.assert_array_equal(r["surfaces"]["points"][used], points)

    def test_domains_and_clusters(self):
        x, box = inclusion_frame()
        out, cli = self.analyze(x, box, "inclusion", "--clusters", "3.0", "--cluster-select", "acna:bcc",
                                "--domains", "3.0", "--profile", "z:5", "--voxel", "2.0", "--voxel-smooth", "1.0",
                                "--voxel-select", "acna:bcc")
        results = [analysis.structure(x, box, clusters=3.0, cluster_select="acna:bcc", domains=3.0, profile=("z", 5.0),
                                      voxel=2.0, voxel_smooth=1.0, voxel_select="acna:bcc", threads=t) for t in (1, 2)]
        r = results[1]
        np.testing.assert_array_equal(r["acna"], np.array(cli["acna"], dtype=int))
        np.testing.assert_array_equal(r["cluster"], np.array(cli["cluster"], dtype=int))
        self.assertEqual(len(r["domains"]), 1)
        self.assertEqual((r["domains"]["euler_characteristic"][0], r["domains"]["manifold"][0]), (2, 1))
        self.assert_rows_printed_equal(r["domains"], read_csv(out / "domains.csv"), 10)
        self.assert_rows_printed_equal(r["clusters"], read_csv(out / "clusters.csv"), 10)
        _, triangles = read_cells(out / "domains_0.vtp", 3)
        np.testing.assert_array_equal(renumbered(r["domain_surfaces"]["triangles"]), triangles)
        summary = read_csv(out / "structures.csv")[0]
        for column, value in r["counts"].items():
            self.assertEqual(f"{value:.10g}", summary[column], column)
        for name in ("acna", "cluster"):
            np.testing.assert_array_equal(results[0][name], r[name])
        np.testing.assert_array_equal(results[0]["domains"], r["domains"])
        bcc = r["profile"]["acna_bcc_fraction"]  # 0.047 measured in the bins through the inclusion, 0 in the end bins
        self.assertGreater(bcc.max(), 0.02)
        self.assertEqual((bcc[0], bcc[-1]), (0.0, 0.0))
        self.assert_rows_printed_equal(r["profile"], read_csv(out / "profiles.csv"), 10, fraction_digits=6)
        voxels = r["voxels"]
        self.assertEqual(voxels["fraction"].shape, (14, 14, 14))  # round(8 a / 2 Å) nodes per periodic axis
        self.assertGreater(voxels["fraction"].max(), 0.5)  # the inclusion's centre
        for name in ("fraction", "density"):
            np.testing.assert_array_equal(_core.read_field(str(out / "voxels_0.vti"), name)[0], voxels[name], name)
        np.testing.assert_array_equal(results[0]["voxels"]["fraction"], voxels["fraction"])

    def test_diamond(self):
        x, box = diamond_frame()
        out, cli = self.analyze(x, box, "si", "--diamond", "--clusters", "2.6", "--cluster-select", "dia:!cubic")
        one, two = (analysis.structure(x, box, diamond=True, clusters=2.6, cluster_select="dia:!cubic", threads=t)
                    for t in (1, 2))
        np.testing.assert_array_equal(two["dia"], np.array(cli["dia"], dtype=int))
        np.testing.assert_array_equal(two["cluster"], np.array(cli["cluster"], dtype=int))
        self.assertGreater(two["counts"]["dia_cubic_count"], 0)
        self.assertGreater(len(two["clusters"]), 0)  # the displacements made some atoms leave cubic diamond
        summary = read_csv(out / "structures.csv")[0]
        for column, value in two["counts"].items():
            self.assertEqual(f"{value:.10g}", summary[column], column)
        self.assert_rows_printed_equal(two["clusters"], read_csv(out / "clusters.csv"), 10)
        np.testing.assert_array_equal(one["dia"], two["dia"])
        np.testing.assert_array_equal(one["cluster"], two["cluster"])

    def test_excess_energy(self):
        x, box = fcc_cu()  # 256 Cu atoms jittered by 0.12 Å: some are not fcc
        pe = -3.54 + 0.5 * np.random.default_rng(8).random(len(x)) ** 2
        out, cli = self.analyze(x, box, "cu", "--adaptive-cna", "--excess-energy", "auto", "--profile", "z:3.6",
                                "--clusters", "3.0", "--cluster-select", "excess>0.2", columns={"pe": pe})
        r = analysis.structure(x, box, adaptive_cna=True, pe=pe, excess_energy="auto", profile=("z", 3.6), clusters=3.0,
                               cluster_select="excess>0.2", threads=2)
        np.testing.assert_array_equal(r["excess"], np.array(cli["excess"], dtype=float))
        np.testing.assert_array_equal(r["cluster"], np.array(cli["cluster"], dtype=int))
        self.assertGreater(len(r["clusters"]), 0)
        summary = read_csv(out / "structures.csv")[0]
        for column in ("excess_reference_eV", "excess_mean_eV", "acna_fcc_count"):
            self.assertEqual(f"{r['counts'][column]:.10g}", summary[column], column)
        self.assert_rows_printed_equal(r["profile"], read_csv(out / "profiles.csv"), 10, fraction_digits=6)
        fixed = analysis.structure(x, box, coordination=3.0, pe=pe, excess_energy=-3.54)
        np.testing.assert_allclose(fixed["excess"], pe + 3.54, rtol=0, atol=1e-15)  # pe − e0, e0 given

    def test_burgers_circuits(self):
        # The Volterra edge dislocation a/2[1-10] of examples/md_dislocation_burgers (unrelaxed, a
        # cylinder of radius 22 Å, two repeats along the line): a circuit of radius 12 Å about the
        # line gives the perfect vector, one about an axis 12 Å away in good crystal gives 0.
        spec = importlib.util.spec_from_file_location("make_dislocation", SOURCE / "examples" / "md_dislocation_burgers"
                                                      / "make_dislocation.py")
        make = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(make)
        x, lz = make.crystal(22.0, 2)
        x = np.ascontiguousarray(make.add_edge(x, 0.37, make.A / np.sqrt(3) / 2, make.A / np.sqrt(2)))
        box = (np.array([x[:, 0].min() - 1, x[:, 1].min() - 1, 0.0]), np.array([x[:, 0].max() + 1, x[:, 1].max() + 1, lz]))
        orient = "1 -1 0,1 1 1,-1 -1 2"
        out, cli = self.analyze(x, box, "edge", "--burgers-orient", orient, "--burgers-lattice", "3.615",
                                "--burgers-line", f"0.37,1.04,{lz / 2!r}:0,0,1:12", "--burgers-line",
                                f"0,-13,{lz / 2!r}:0,0,1:5", bounds="ff ff pp")
        r = analysis.structure(x, box, boundary="ffp", adaptive_cna=True, burgers_orient=((1, -1, 0), (1, 1, 1), (-1, -1, 2)),
                               burgers_lattice=3.615, burgers_lines=[((0.37, 1.04, lz / 2), (0, 0, 1), 12.0),
                                                                     ((0.0, -13.0, lz / 2), (0, 0, 1), 5.0)])
        b = r["burgers"]
        self.assertEqual(list(b["b"]), ["[1 -1 0]/2", "0"])
        self.assertEqual(b["kind"][0], "perfect a/2<110>")
        rows = read_csv(out / "burgers.csv")
        for column in ("source", "b", "kind"):
            self.assertEqual(list(b[column]), [row[column] for row in rows], column)
        numeric = b[[n for n in b.dtype.names if n not in ("source", "b", "kind", "max_step_error")]]
        self.assert_rows_printed_equal(numeric, rows, 10)
        self.assertEqual([f"{v:.4g}" for v in b["max_step_error"]], [row["max_step_error"] for row in rows])
        np.testing.assert_array_equal(r["burgers_circuit"], np.array(cli["burgers_circuit"], dtype=int))

    def test_tracks(self):
        # The bcc inclusion growing, radius 5.5, 6.5, 7.5 Å at timesteps 1000, 2000, 3000: one track,
        # the domain's growth laws from three points.
        tracker, files, cli_tracks = analysis.ClusterTracker(), [], []
        for k, radius in enumerate((5.5, 6.5, 7.5)):
            x, box = inclusion_frame(radius=radius)
            files.append(self.dir / f"grow{k}.lammpstrj")
            write_dump(files[-1], x, box, timestep=1000 * (k + 1))
            r = analysis.structure(x, box, clusters=3.0, cluster_select="acna:bcc", tracker=tracker,
                                   timestep=1000 * (k + 1), threads=2)
            cli_tracks.append(r["track"])
        out = self.dir / "grow"
        process = subprocess.run([SF, "analyze", "atoms", *map(str, files), "--no-plot", "-o", str(out), "--clusters",
                                  "3.0", "--cluster-select", "acna:bcc", "--track", "--timestep-size", "0.001"],
                                 capture_output=True, text=True)
        self.assertEqual(process.returncode, 0, process.stderr)
        for k, track in enumerate(cli_tracks):
            np.testing.assert_array_equal(track, np.array(read_dump_columns(out / f"grow{k}.lammpstrj")["track"], dtype=int))
        tracks, growth = tracker.tracks(dt=0.001), tracker.growth(dt=0.001)
        self.assertEqual(tracker.frames, 3)
        self.assertEqual(list(tracks["track"][tracks["cluster"] == 1]), [1, 1, 1])  # the domain keeps its track
        self.assert_rows_printed_equal(tracks, read_csv(out / "tracks.csv"), 10)
        rows = read_csv(out / "growth.csv")
        self.assertEqual(list(growth["quantity"]), [row["quantity"] for row in rows])
        for mine, theirs in zip(growth, rows):
            for column, digits in (("exponent", 6), ("exponent_stderr", 3), ("prefactor", 6)):
                self.assertEqual(f"{mine[column]:.{digits}g}", theirs[column], column)
        self.assertGreater(growth["exponent"][list(growth["quantity"]).index("ellipsoid_volume_A3")], 1.0)  # grows: V ~ t^1.58 here
        with self.assertRaisesRegex(shockfield.InputError, "tracker needs clusters"):
            analysis.structure(x, box, adaptive_cna=True, tracker=tracker)

    def test_bad_input_raises(self):
        x, box = void_frame(n=3, radius=2.0)
        with self.assertRaisesRegex(TypeError, "positions: expected dtype float64"):
            analysis.voids(x.astype(np.float32), box, 2.17)
        with self.assertRaisesRegex(ValueError, "not C-contiguous"):
            analysis.voids(np.asfortranarray(x), box, 2.17)
        with self.assertRaisesRegex(shockfield.InputError, "positive"):
            analysis.voids(x, box, 0.0)
        with self.assertRaisesRegex(shockfield.InputError, "go together"):
            analysis.structure(x, box, adaptive_cna=True, clusters=3.0)
        with self.assertRaisesRegex(shockfield.InputError, "cluster_select 'csp>1': selecting by csp needs csp=N"):
            analysis.structure(x, box, adaptive_cna=True, clusters=3.0, cluster_select="csp>1")
        with self.assertRaisesRegex(shockfield.InputError, "domains needs the clusters"):
            analysis.structure(x, box, adaptive_cna=True, domains=3.0)
        with self.assertRaisesRegex(ValueError, "profile: expected \\(AXIS, WIDTH\\)"):
            analysis.structure(x, box, adaptive_cna=True, profile=("w", 5.0))
        with self.assertRaisesRegex(shockfield.InputError, "width"):
            analysis.structure(x, box, adaptive_cna=True, profile=("z", 0.0))
        with self.assertRaisesRegex(shockfield.InputError, "excess_energy needs the per-atom potential energies"):
            analysis.structure(x, box, adaptive_cna=True, excess_energy="auto")
        with self.assertRaisesRegex(ValueError, "pe: expected"):
            analysis.structure(x, box, adaptive_cna=True, excess_energy="auto", pe=np.zeros(3))
        with self.assertRaisesRegex(shockfield.InputError, "needs a structure method"):
            analysis.structure(x, box, coordination=3.0, excess_energy="auto", pe=np.zeros(len(x)))
        with self.assertRaisesRegex(shockfield.InputError, "selecting by excess needs excess_energy and pe"):
            analysis.structure(x, box, adaptive_cna=True, clusters=3.0, cluster_select="excess>0.1")
        with self.assertRaisesRegex(shockfield.InputError, "burgers_clusters needs clusters"):
            analysis.structure(x, box, adaptive_cna=True, burgers_clusters=True)
        with self.assertRaisesRegex(shockfield.InputError, "burgers_orient"):
            analysis.structure(x, box, adaptive_cna=True, burgers_ids=[[1, 2, 3]],
                               burgers_orient=((1, 0, 0), (1, 1, 0), (0, 0, 1)))
        with self.assertRaisesRegex(shockfield.InputError, "radius must be > 0"):
            analysis.structure(x, box, adaptive_cna=True, burgers_lines=[((0, 0, 0), (0, 0, 1), 0.0)])
        with self.assertRaisesRegex(shockfield.InputError, "voxel_select 'csp>1': selecting by csp needs csp=N"):
            analysis.structure(x, box, adaptive_cna=True, voxel=2.0, voxel_select="csp>1")
        with self.assertRaisesRegex(shockfield.InputError, "spacing"):
            analysis.structure(x, box, adaptive_cna=True, voxel=-1.0)
        with self.assertRaisesRegex(ValueError, "domains_surface"):
            analysis.structure(x, box, adaptive_cna=True, domains=3.0, domains_surface="alpha")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
