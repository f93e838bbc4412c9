"""Tilted (LAMMPS restricted triclinic) boxes in the Python package (ctest python.test_triclinic).

- read_lammps_dump on a dump LAMMPS wrote (tests/fixtures/lammps_triclinic/cu_u3_sheared_void.dump:
  `ITEM: BOX BOUNDS xy xz yz`, the bounding box and the tilts 4.515 2.915 4.115 Å): the Box's cell
  (lo, hi, tilt) is LAMMPS's region prism 0 18.075 0 14.46 0 14.46 (fcc 5x4x4 at 3.615 Å, tilted
  one lattice unit and sheared by 0.9, -0.7, 0.5 Å), its volume LAMMPS's (the .totals file) to
  1e-13, and its bounds give back the file's lines exactly.
- read_lammps_data on a data file LAMMPS wrote (tests/fixtures/io/data_triclinic.data, tilts
  3.615 -3.615 1.8075 Å): the box, types, masses, positions and velocities as the file gives them
  (an independent parse of its sections), every atom inside the tilted cell (fractional
  coordinates in [0, 1)); a malformed file raises InputError naming the line.
- structure() on that tilted dump with its Box equals `shockfield analyze atoms` on the file (which
  reads the tilt itself) column for column; given only (lo, hi) — the tilt dropped — the
  coordination differs, so the test sees a lost tilt. Profiles along x and y bin the fractional
  coordinate (numpy's count per slab parallel to the b-c or a-c face; the Cartesian axis gives
  other counts); a profile along z runs. voids(), the voxel field and domains on the tilted cell
  raise InputError saying they need an orthogonal box.
- Simulation.box of an in-process md run in a tilted cell (tests/cli/cases/tilted_fcc.toml, tilts
  2.1 -3.3 1.7 Å) sheared by deform_tilt_rate: the tilt equals thermo.csv's xy_A xz_A yz_A (to
  its 10 digits) and the final.data header, cell's rows are the edges a = (lx, 0, 0), b = (xy, ly, 0), c = (xz, yz, lz),
  det(cell) the volume; it moves with the shear (a copy: the next step's box is new).
"""

import csv
import os
import pathlib
import subprocess
import tempfile
import unittest

import numpy as np

import shockfield
from shockfield import analysis
from shockfield.box import Box
from shockfield.run import read_lammps_data, read_lammps_dump

SF = os.environ["SHOCKFIELD_BIN"]
FIXTURES = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "fixtures"
DUMP = FIXTURES / "lammps_triclinic" / "cu_u3_sheared_void.dump"
DATA = FIXTURES / "io" / "data_triclinic.data"


def file_sections(path):
    """The data file's header values and its Masses / Atoms / Velocities rows, parsed here."""
    header, sections, current = {}, {}, None
    for line in path.read_text().splitlines()[1:]:
        line = line.split("#")[0].strip()
        if not line:
            continue
        words = line.split()
        if words[0] in ("Masses", "Atoms", "Velocities"):
            current = sections.setdefault(words[0], [])
        elif current is None:
            header[" ".join(w for w in words if not w[0].isdigit() and w[0] != "-")] = [float(w) for w in words[:3]
                                                                                       if w[0].isdigit() or w[0] == "-"]
        else:
            current.append([float(w) for w in words])
    return header, {k: np.array(v) for k, v in sections.items()}


class Triclinic(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_dump_reader_gives_the_cell(self):
        [(step, _, box, atoms)] = read_lammps_dump(DUMP)
        self.assertEqual((step, len(atoms)), (0, 301))
        self.assertIsInstance(box, Box)
        self.assertTrue(box.triclinic)
        np.testing.assert_allclose(box.lo, [0, 0, 0], atol=1e-14)
        np.testing.assert_allclose(box.hi, [18.075, 14.46, 14.46], rtol=1e-15)
        np.testing.assert_allclose(box.tilt, [4.515, 2.915, 4.115], rtol=1e-15)
        lammps_volume = next(float(line.split()[1]) for line in (DUMP.with_suffix(".totals")).read_text().splitlines()
                             if line.startswith("volume"))
        self.assertAlmostEqual(box.volume / lammps_volume, 1.0, delta=1e-13)
        self.assertAlmostEqual(abs(np.linalg.det(box.cell)) / lammps_volume, 1.0, delta=1e-13)
        file_bounds = np.array([[float(v) for v in line.split()[:2]] for line in DUMP.read_text().splitlines()[5:8]])
        np.testing.assert_array_equal(box.bounds, file_bounds)
        s = box.fractional(np.column_stack([atoms["x"], atoms["y"], atoms["z"]]))
        self.assertTrue(np.all((s > -1e-12) & (s < 1 + 1e-12)), "atoms outside the cell: the tilt was misread")

    def test_data_reader_gives_the_tilt(self):
        d = read_lammps_data(DATA)
        header, sections = file_sections(DATA)
        box = d["box"]
        np.testing.assert_array_equal(box.tilt, header["xy xz yz"])
        np.testing.assert_array_equal(box.lo, [header[f"{a}lo {a}hi"][0] for a in "xyz"])
        np.testing.assert_array_equal(box.hi, [header[f"{a}lo {a}hi"][1] for a in "xyz"])
        self.assertEqual(d["boundary"], "ppp")
        atoms = sections["Atoms"][np.argsort(sections["Atoms"][:, 0])]
        order = np.argsort(d["ids"])
        np.testing.assert_array_equal(d["ids"][order], atoms[:, 0].astype(np.int64))
        np.testing.assert_array_equal(d["types"][order], atoms[:, 1].astype(np.int32))
        np.testing.assert_array_equal(d["positions"][order], atoms[:, 2:5])
        np.testing.assert_array_equal(d["images"][order], atoms[:, 5:8].astype(np.int32))
        velocities = sections["Velocities"][np.argsort(sections["Velocities"][:, 0])]
        np.testing.assert_array_equal(d["velocities"][order], velocities[:, 1:4])
        np.testing.assert_array_equal(d["masses"], sections["Masses"][:, 1])
        s = box.fractional(d["positions"])
        self.assertTrue(np.all((s >= 0) & (s < 1)))
        bad = self.dir / "bad.data"
        bad.write_text(DATA.read_text().replace("xy xz yz", "xy xz"))
        with self.assertRaises(shockfield.InputError) as caught:
            read_lammps_data(bad)
        self.assertIn(str(bad), str(caught.exception))

    def test_structure_on_the_tilted_cell_equals_analyze_atoms(self):
        [(_, _, box, atoms)] = read_lammps_dump(DUMP)
        x = np.ascontiguousarray(np.column_stack([atoms["x"], atoms["y"], atoms["z"]]))
        ids = atoms["id"].astype(np.int64)
        process = subprocess.run([SF, "analyze", "atoms", str(DUMP), "-o", str(self.dir / "out"), "--coordination",
                                  "3.0", "--cna", "3.08", "--adaptive-cna", "-j", "1"], capture_output=True, text=True)
        self.assertEqual(process.returncode, 0, process.stderr)
        [(_, _, _, cli)] = read_lammps_dump(self.dir / "out" / DUMP.name)
        cli = cli[np.argsort(cli["id"])]
        r = analysis.structure(x, box, ids=ids, coordination=3.0, cna=3.08, adaptive_cna=True, threads=1)
        order = np.argsort(ids)
        for name in ("coord", "cna", "acna"):
            np.testing.assert_array_equal(r[name][order], cli[name].astype(int), name)
        self.assertGreater(r["acna_counts"]["fcc"], 200)  # the sheared crystal around the void
        untilted = analysis.structure(x, (box.lo, box.hi), ids=ids, coordination=3.0, threads=1)
        self.assertFalse(np.array_equal(untilted["coord"], r["coord"]), "dropping the tilt changed nothing")
        profile = analysis.structure(x, box, adaptive_cna=True, profile=("z", 3.615))["profile"]
        self.assertEqual(int(profile["atoms"].sum()), len(x))

    def test_profiles_along_x_and_y_bin_the_fractional_coordinate(self):
        # the slabs are parallel to the cell face the other two edges span: per bin the atoms
        # numpy counts on s·L (L = lx, ly; the positions are LAMMPS's lattice jittered by 0.05 Å,
        # off the bin faces); on the Cartesian axis the counts differ (a tilt ignored is seen)
        [(_, _, box, atoms)] = read_lammps_dump(DUMP)
        x = np.ascontiguousarray(np.column_stack([atoms["x"], atoms["y"], atoms["z"]]))
        s = box.fractional(x) % 1.0
        for d, axis in enumerate("xy"):
            length, width = box.lengths[d], 3.615
            profile = analysis.structure(x, box, adaptive_cna=True, profile=(axis, width))["profile"]
            nbins = len(profile)
            expected = np.bincount(np.minimum(np.floor(s[:, d] * length / width).astype(int), nbins - 1), minlength=nbins)
            np.testing.assert_array_equal(profile["atoms"].astype(int), expected, axis)
            np.testing.assert_allclose(profile["lo_A"], box.lo[d] + width * np.arange(nbins), rtol=1e-15)
            cartesian = np.bincount(np.clip(np.floor((x[:, d] - box.lo[d]) / width).astype(int), 0, nbins - 1),
                                    minlength=nbins)
            self.assertFalse(np.array_equal(expected, cartesian), axis)

    def test_axis_grids_refuse_a_tilted_cell(self):
        [(_, _, box, atoms)] = read_lammps_dump(DUMP)
        x = np.ascontiguousarray(np.column_stack([atoms["x"], atoms["y"], atoms["z"]]))
        for call in (lambda: analysis.voids(x, box, 2.0),
                     lambda: analysis.structure(x, box, adaptive_cna=True, voxel=2.0),
                     lambda: analysis.structure(x, box, adaptive_cna=True, clusters=3.0, cluster_select="acna:!fcc",
                                                domains=3.0)):
            with self.assertRaises(shockfield.InputError) as caught:
                call()
            self.assertIn("needs an orthogonal box", str(caught.exception))
        with self.assertRaises(shockfield.InputError):  # beyond LAMMPS's tilt limit |xy| <= lx/2
            analysis.structure(x, (box.lo, box.hi, (12.0, 0.0, 0.0)), coordination=3.0)
        with self.assertRaises(ValueError):
            analysis.structure(x, (box.lo,), coordination=3.0)


    def test_simulation_box_gives_the_tilt_and_cell(self):
        case = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "cli" / "cases" / "tilted_fcc.toml"
        sheared = shockfield.Case.load(case).set("stage[0].deform_tilt_rate", [0.05, -0.03, 0.02])
        sim = shockfield.Simulation(sheared, pathlib.Path(self.tmp.name) / "box", threads=1)
        start = sim.box
        np.testing.assert_array_equal(start.tilt, [2.1, -3.3, 1.7])
        sim.step(sim.steps_left)
        box = sim.box
        self.assertGreater(box.tilt[0], start.tilt[0])  # sheared at +0.05/ps: a new copy
        (lx, ly, lz), (xy, xz, yz) = box.lengths, box.tilt
        np.testing.assert_array_equal(box.cell, [[lx, 0, 0], [xy, ly, 0], [xz, yz, lz]])
        self.assertAlmostEqual(abs(np.linalg.det(box.cell)), box.volume, delta=1e-9 * box.volume)
        sim.finish()
        with open(sim.folder / "thermo.csv") as table:
            last = list(csv.DictReader(table))[-1]  # the final step's row, 10 significant digits
        np.testing.assert_allclose(box.tilt, [float(last[k]) for k in ("xy_A", "xz_A", "yz_A")], rtol=1e-9)
        header = next(line for line in open(sim.folder / "final.data") if line.rstrip().endswith("xy xz yz"))
        np.testing.assert_allclose([float(w) for w in header.split()[:3]], box.tilt, rtol=1e-15, atol=0)

if __name__ == "__main__":
    unittest.main()
