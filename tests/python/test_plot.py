"""shockfield.plot (python -m shockfield.plot, shockfield plot): every kind draws a PNG of a tiny run
of its method with the expected panels, a kind of another method is refused naming the run's
kinds (exit 2 from both commands), and the shared reader (shockfield.run) gives what an
independent parse of each file kind gives (ctest python.test_plot; about 10 s)."""

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import tomllib
import unittest
from unittest import mock

import matplotlib

matplotlib.use("Agg")
import matplotlib.figure  # noqa: E402
import numpy as np  # noqa: E402

import shockfield  # noqa: E402
import shockfield.plot  # noqa: E402
from shockfield.run import read_csv, read_json, read_lammps_dump, read_points, read_pvd, read_toml  # noqa: E402
from shockfield.vtk_arrays import read_vtk_arrays  # noqa: E402

SOURCE = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"])
CASES = SOURCE / "tests" / "cli" / "cases"

def cavity_case():
    """mpm_tiny.toml with one 60 µm cavity in place of the pores (series.csv: collapsibility)."""
    with open(CASES / "mpm_tiny.toml", "rb") as f:
        table = tomllib.load(f)
    body = table["body"][0]
    for key in ("porosity", "void_radius", "seed"):
        del body[key]
    body.update(cavity_radius=60e-6, cavity_depth=250e-6)
    return shockfield.Case.from_dict(table, directory=CASES)


# A 16 x 16 GLS quench, 20 steps (tests/cli/dbm_gls_run.sh's case): series, summary.csv, 3 frames.
# A Taylor compression of 4 crystal grains ([homogeneous], the pd_ofhc_compression example in small).
TAYLOR = {"method": "pd", "material": {"model": "crystal", "density": 8960.0, "orientation": "random",
                                      "taylor_grains": 4, "seed": 3},
          "homogeneous": {"strain_rate": -0.01, "end_strain": -0.02, "strain_increment": 1e-3,
                          "output_increment": 0.01}}
GLS = {"method": "dbm", "grid": {"nx": 16, "ny": 16, "dx": 0.0625},
       "model": {"kind": "gls", "K": 1e-3, "tau": 1e-3, "q": -0.019},
       "initial": {"type": "quench", "rho0": 1.0, "T": 0.85, "noise": 0.05},
       "run": {"end_time": 0.02, "dt": 1e-3},
       "output": {"series_interval": 0.005, "field_interval": 0.01}}


def is_png(path):
    data = pathlib.Path(path).read_bytes()
    return len(data) > 500 and data[:8] == b"\x89PNG\r\n\x1a\n"


def drawn_axes(kind, folder, **options):
    """Draws `kind` of `folder`; returns (PNG path, axes of the figure saved). The PNG is written
    at 30 dpi (the helpers' own 90-130 dpi cost 0.5 s a figure more)."""
    saved = []
    original = matplotlib.figure.Figure.savefig

    def record(fig, *args, **kwargs):
        saved.append(fig)
        return original(fig, *args, **dict(kwargs, dpi=30))
    with mock.patch.object(matplotlib.figure.Figure, "savefig", record):
        out = shockfield.plot.plot(kind, folder, **options)
    return out, [ax for ax in saved[-1].axes if ax.get_label() != "<colorbar>"]


class Plot(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        root = pathlib.Path(cls.tmp.name)

        def run(case, name):
            return case.run(output=root / name, threads=1, quiet=True)
        md = shockfield.Case.load(CASES / "tiny_cu.toml")
        md.set("output.profile_every", 50)
        cls.runs = {
            "mpm": run(cavity_case(), "mpm"),
            "porous": run(shockfield.Case.load(CASES / "mpm_tiny.toml"), "porous"),
            "pd": run(shockfield.Case.load(CASES / "pd_tiny.toml"), "pd"),
            "dbm": run(shockfield.Case.load(CASES / "dbm_sod.toml"), "dbm"),
            "gls": run(shockfield.Case.from_dict(GLS), "gls"),
            "granular": run(shockfield.Case.load(CASES / "granular_tiny.toml"), "granular"),
            "macroparticle": run(shockfield.Case.load(CASES / "macroparticle_tiny.toml"), "macroparticle"),
            "phasefield": run(shockfield.Case.load(CASES / "phasefield_tiny.toml"), "phasefield"),
            "md": run(md, "md"),
            "plate": run(shockfield.Case.load(CASES / "pd_plate_loading.toml"), "plate"),
            "taylor": run(shockfield.Case.from_dict(TAYLOR), "taylor"),
        }

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def folder(self, name):
        return self.runs[name].folder

    def test_every_kind_draws_its_panels(self):
        # (kind, run, panels): the figure's axes besides colour bars, as each helper lays them out.
        expected = [("thermo", "mpm", 7), ("series", "pd", 7), ("profiles", "md", 4), ("porous", "porous", 5),
                    ("cavity", "mpm", 2), ("bar", "pd", 2), ("crystal", "pd", 2), ("profiles", "pd", 7),
                    ("profiles", "dbm", 4), ("tne", "dbm", 3), ("profiles", "gls", 5), ("tne", "gls", 3),
                    ("phase-separation", "gls", 7), ("chain", "granular", 3),
                    ("stress-strain", "macroparticle", 1), ("phasefield", "phasefield", 3), ("damage", "plate", 1),
                    ("compression", "taylor", 2), ("orientations", "taylor", 2)]
        # structures and slice: tests/cli/plot_atoms.sh; hugoniot: test_hugoniot_folder; voids and
        # domains: test_voids_and_domains_folders.
        self.assertEqual({k for k, _, _ in expected} | {"hugoniot", "structures", "slice", "voids", "domains"},
                         set(shockfield.plot.KINDS), "a kind without a test here")
        for kind, name, panels in expected:
            with self.subTest(kind=kind, run=name):
                out, axes = drawn_axes(kind, self.folder(name), out=self.folder(name) / f"{kind}_test.png")
                self.assertTrue(is_png(out))
                self.assertEqual(len(axes), panels, [ax.get_ylabel() or ax.get_title() for ax in axes])
        # The title names the run and its case file; the Sod profiles carry the exact star state.
        _, axes = drawn_axes("profiles", self.folder("dbm"))
        self.assertIn("dbm run dbm (dbm_sod.toml): profiles", axes[0].figure._suptitle.get_text())
        levels = [t.get_text() for t in axes[2].texts]  # rho, u_x, p, T
        self.assertTrue(any(t.startswith("exact p* ") for t in levels), levels)
        # No reference curve of one material is drawn on another run's compression (only its own
        # grains, their band and the Taylor average), and the title names the run.
        _, axes = drawn_axes("compression", self.folder("taylor"))
        self.assertIn("pd run taylor", axes[0].get_title())
        self.assertEqual([t.get_text() for t in axes[0].get_legend().get_texts()][-1], "Taylor average (eq. 43), 4 grains")

    def test_hugoniot_folder(self):
        """The folder of `shockfield hugoniot`: its sweep (here LAMMPS's fixture sweep) and the
        experimental line its hugoniot_fit.toml names, not one hard-coded in the helper."""
        folder = pathlib.Path(self.tmp.name) / "hugoniot"
        folder.mkdir()
        (folder / "hugoniot_sweep.csv").write_bytes((SOURCE / "tests/fixtures/lammps_shock/lammps_sweep.csv").read_bytes())
        (folder / "hugoniot_fit.toml").write_text("[experiment_nickel]\nc0_km_s = 4.6\ns = 1.44\n")
        out, axes = drawn_axes("hugoniot", folder)
        self.assertTrue(is_png(out))
        labels = [t.get_text() for t in axes[0].get_legend().get_texts()]
        self.assertIn("experiment, nickel: 4.6 + 1.44 Up", labels)
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.plot.plot("hugoniot", self.folder("md"))
        self.assertIn("no hugoniot_sweep.csv", str(caught.exception))

    def test_voids_and_domains_folders(self):
        """The folders of `analyze atoms --voids` (here on the void fixture, by the command line)
        and `--domains` (a two-frame domains.csv in the command's columns): the lines drawn are
        the CSV's total and largest volume and area per timestep; a folder without the table and
        a run folder are refused naming the table."""
        folder = pathlib.Path(self.tmp.name) / "voids"
        dump = SOURCE / "tests/fixtures/lammps_structure/cu_void_300K.dump"
        subprocess.run([os.environ["SHOCKFIELD_BIN"], "analyze", "atoms", str(dump), "--voids", "2.17", "--no-plot",
                        "-o", str(folder)], check=True, capture_output=True)
        domains = pathlib.Path(self.tmp.name) / "domains"
        domains.mkdir()
        (domains / "domains.csv").write_text(
            "frame,timestep,domain,atoms,volume_A3,area_A2,equivalent_radius_A,atoms_volume_A3,atoms_radius_A,"
            "x_A,y_A,z_A,euler_characteristic,manifold\n"
            "0,0,1,300,3000,1000,8.9,3000,8.9,1,2,3,2,1\n0,0,2,50,500,300,4.9,500,4.9,5,6,7,2,1\n"
            "1,1000,1,400,4000,1200,9.8,4000,9.8,1,2,3,2,1\n")
        for kind, target in (("voids", folder), ("domains", domains)):
            with self.subTest(kind=kind):
                table = read_csv(target / f"{kind}.csv")
                out, axes = drawn_axes(kind, target)
                self.assertEqual(out, str(target / f"{kind}.png"))
                self.assertTrue(is_png(out))
                steps = np.unique(table["timestep"])
                for ax, column in zip(axes, ("volume_A3", "area_A2")):
                    total, largest = ax.get_lines()[:2]
                    np.testing.assert_array_equal(total.get_xdata(), steps)
                    np.testing.assert_allclose(total.get_ydata(),
                                               [table[column][table["timestep"] == t].sum() for t in steps])
                    np.testing.assert_allclose(largest.get_ydata(),
                                               [table[column][table["timestep"] == t].max() for t in steps])
                self.assertGreater(np.sum(axes[0].get_lines()[0].get_ydata()), 0.0)
                with self.assertRaises(shockfield.InputError) as caught:
                    shockfield.plot.plot(kind, self.folder("md"))
                self.assertIn(f"no {kind}.csv (the folder of `shockfield analyze atoms --{kind}`)", str(caught.exception))

    def test_wrong_kind_is_refused(self):
        cases = [("bar", "mpm", "a mpm run; 'bar' draws pd runs. Kinds for this run: thermo, series, porous, cavity"),
                 ("phase-separation", "dbm", "a dbm run; 'phase-separation' draws dbm runs of [model] kind = \"gls\". "
                                             "Kinds for this run: thermo, series, profiles, tne"),
                 ("porous", "granular", "a granular run; 'porous' draws mpm runs. Kinds for this run: thermo, series, "
                                        "chain"),
                 ("cavity", "porous", "a mpm run; 'cavity' draws mpm runs with a cavity ([[body]] cavity_radius). "
                                      "Kinds for this run: thermo, series, porous"),
                 ("tne", "pd", "Kinds for this run: thermo, series, profiles, bar, crystal, damage"),
                 ("compression", "pd", "'compression' draws pd runs with a [homogeneous] block")]
        for kind, name, message in cases:
            with self.subTest(kind=kind, run=name), self.assertRaises(shockfield.InputError) as caught:
                shockfield.plot.plot(kind, self.folder(name))
            self.assertIn(message, str(caught.exception))
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.plot.plot("spectra", self.folder("mpm"))
        self.assertIn("unknown kind 'spectra'", str(caught.exception))
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.plot.plot("series", self.folder("mpm"), columns=["pressure"])
        self.assertIn("has no column pressure; its columns: ", str(caught.exception))

    def test_commands(self):
        """python -m shockfield.plot and shockfield plot: one path, the same refusals and help."""
        commands = {"module": [sys.executable, "-m", "shockfield.plot"],
                    "cli": [os.environ["SHOCKFIELD_BIN"], "plot"]}
        for name, command in commands.items():
            with self.subTest(command=name):
                p = subprocess.run(command + ["chain", str(self.folder("dbm"))], capture_output=True, text=True)
                self.assertEqual(p.returncode, 2, p.stderr)
                self.assertIn("'chain' draws granular runs. Kinds for this run: thermo, series, profiles, tne",
                              p.stderr)
                p = subprocess.run(command + ["--help"], capture_output=True, text=True)
                self.assertEqual(p.returncode, 0, p.stderr)
                listed = [line.split()[0] for line in p.stdout.split("kinds:\n")[1].splitlines() if line.strip()]
                self.assertEqual(listed, list(shockfield.plot.KINDS))
        # A figure through the command line (the module it runs draws the same in-process above).
        out = self.folder("gls") / "cli.png"
        p = subprocess.run(commands["cli"] + ["thermo", str(self.folder("gls")), "-o", str(out), "--columns",
                                              "Mass,TotEng"], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertTrue(is_png(out))

    def test_reader_against_independent_parses(self):
        """Each file kind through shockfield.run against numpy.genfromtxt, tomllib, json, the
        pure-Python VTK reader and the LAMMPS dump of the same frame."""
        for name in ("mpm", "pd", "dbm", "granular"):
            run = shockfield.Run.open(self.folder(name))
            with open(run.folder / "config.resolved.toml", "rb") as f:
                self.assertEqual(run.config, tomllib.load(f))
            self.assertEqual(run.summary, json.loads((run.folder / "summary.json").read_text()))
            for table in ("thermo", "series") + (("spacetime_force", "probes") if name == "granular" else ()):
                ours = run.table(table)
                raw = np.genfromtxt(run.folder / f"{table}.csv", delimiter=",", names=True, deletechars="")
                self.assertEqual(ours.dtype.names, raw.dtype.names)
                for column in raw.dtype.names:
                    np.testing.assert_array_equal(ours[column], raw[column], err_msg=f"{name} {table} {column}")
        profiles = list(shockfield.Run.open(self.folder("dbm")).frames(kind="profiles"))
        index = np.genfromtxt(self.folder("dbm") / "profiles" / "index.csv", delimiter=",", names=True)
        np.testing.assert_array_equal([f.time for f in profiles], index["time"])
        last = np.genfromtxt(self.folder("dbm") / "profiles" / f"profile_{int(index['profile'][-1])}.csv",
                             delimiter=",", names=True)
        for column in last.dtype.names:
            np.testing.assert_array_equal(profiles[-1].data[column], last[column])
        # md's profiles.csv (text-free) and its dumps against genfromtxt.
        md = shockfield.Run.open(self.folder("md"))
        raw = np.genfromtxt(md.folder / "profiles.csv", delimiter=",", names=True)
        for column in raw.dtype.names:
            np.testing.assert_array_equal(md.profiles[column], raw[column])
        frame = md.last_frame(kind="dumps")
        atoms = np.genfromtxt(frame.file, skip_header=9)
        np.testing.assert_array_equal(frame.data["x"], atoms[:, 2])
        # Grid fields: the compiled reader (Run.frames "fields") against the pure-Python one.
        gls = shockfield.Run.open(self.folder("gls"))
        field = gls.last_frame(array="rho", kind="fields")
        np.testing.assert_array_equal(field.data.ravel(), read_vtk_arrays(field.file)["rho"].astype(float))
        # Particles: pd's points.vtp (deformed positions, float32 by default) against the LAMMPS
        # dump written with the same profile; the float32 rounding bounds the difference.
        pd = shockfield.Run.open(self.folder("pd"))
        points = pd.last_frame(kind="particles")
        self.assertEqual(points.file, read_pvd(pd.folder / "profiles" / "points.pvd")[-1][1])
        dump = pd.last_frame(kind="dumps").data
        np.testing.assert_allclose(points.data["points"][:, 0], dump["x"], rtol=1e-6, atol=0)
        self.assertEqual(set(read_points(points.file).dtype.names), set(points.data.dtype.names))
        self.assertNotIn("points", read_csv(pd.folder / "series.csv").dtype.names)

    def test_toml_accessor(self):
        """Run.toml (the examples' hugoniot_*.toml) against tomllib on every TOML file of a run; a
        missing one is refused naming the TOML files the run holds."""
        for name in ("md", "pd"):
            run = shockfield.Run.open(self.folder(name))
            held = sorted(run.folder.rglob("*.toml"))
            self.assertIn(run.folder / "config.resolved.toml", held)
            for path in held:
                with open(path, "rb") as f:
                    self.assertEqual(run.toml(str(path.relative_to(run.folder))), tomllib.load(f), path)
            self.assertEqual(run.toml("config.resolved"), run.config)
            with self.assertRaisesRegex(shockfield.InputError, "no hugoniot_nothing.toml; its TOML files: .*config.resolved.toml"):
                run.toml("hugoniot_nothing")

    def test_text_columns(self):
        """read_csv / Run.table(text=...): a text column whose rows all read as numbers (burgers.csv's
        b = "0" for a closed circuit) stays the file's text; without it the column is float64."""
        folder = pathlib.Path(self.tmp.name) / "text_columns"
        folder.mkdir()
        (folder / "config.resolved.toml").write_bytes((self.folder("md") / "config.resolved.toml").read_bytes())
        (folder / "burgers.csv").write_text("circuit,b,kind,max_step_error\n1,0,none,0.4569\n2,0,none,1e-05\n")
        run = shockfield.Run.open(folder)
        inferred, kept = run.table("burgers"), run.table("burgers", text=("b", "max_step_error"))
        self.assertEqual(inferred["b"].dtype, np.float64)
        self.assertEqual(list(kept["b"]), ["0", "0"])
        self.assertEqual(list(kept["max_step_error"]), ["0.4569", "1e-05"])
        np.testing.assert_array_equal(kept["circuit"], [1.0, 2.0])
        self.assertEqual(list(kept["kind"]), list(inferred["kind"]))
        self.assertEqual(read_csv(folder / "burgers.csv", text=("b",))["b"].dtype.kind, "U")

    def test_readers_refuse_mutated_files(self):
        """Mutation fuzzing of the shared reader: every kind of file with random bytes replaced,
        inserted, deleted or cut off (seeded) is read or refused with InputError naming it, never
        another exception. 150 mutants of each of 7 files."""
        rng = np.random.default_rng(2026)
        pd, gls = self.folder("pd"), self.folder("gls")
        files = [(read_csv, pd / "series.csv"), (read_toml, pd / "config.resolved.toml"),
                 (read_json, pd / "summary.json"), (read_pvd, pd / "profiles" / "points.pvd"),
                 (read_points, pd / "profiles" / "points_4.vtp"), (read_lammps_dump, self.runs["md"].last_frame().file),
                 (read_csv, gls / "summary.csv")]
        mutant = pathlib.Path(self.tmp.name) / "mutant"
        for reader, original in files:
            data = bytearray(pathlib.Path(original).read_bytes())
            refused = 0
            for _ in range(150):
                m = bytearray(data)
                for _ in range(rng.integers(1, 4)):
                    k = int(rng.integers(0, len(m)))
                    choice = rng.integers(0, 4)
                    if choice == 0:
                        m[k] = int(rng.integers(0, 256))
                    elif choice == 1:
                        m.insert(k, int(rng.choice(list(b',."=<>\n0-e'))))
                    elif choice == 2:
                        del m[k:k + int(rng.integers(1, 40))]
                    else:
                        m = m[:k]
                mutant.write_bytes(bytes(m))
                try:
                    reader(mutant)
                except shockfield.InputError as error:
                    self.assertIn(str(mutant), str(error))
                    refused += 1
            self.assertGreater(refused, 0, f"no mutant of {original} was refused")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
