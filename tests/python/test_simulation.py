"""shockfield.Simulation: a case run in-process and stepped from Python (ctest python.test_simulation).

- The arrays are views: zeroing the velocities of the 256-atom Cu crystal between two NVE steps
  makes the next step start from rest, so velocity Verlet gives v = dt/(2m) (f0 + f1) ftm2v
  from the forces before (f0) and after (f1) the step, and the thermo row's KinEng is
  ½ mvv2e m Σv² of it (to 1e-12 relative: the same formula evaluated in another order).
- The views stay valid: over 120 steps at 600 K (neighbour rebuilds in the log) the arrays keep
  their address and an old view reads what a fresh one does.
- A view that went stale raises: a 4×4×2 cell compressed along z at 5/ps (deform) falls below the
  interaction range (cutoff + skin, 5.95 Å) at step 20, so ghosts need a second image layer and
  positions, forces and types (owned + ghost storage) move; step() raises StaleViewError naming
  those three and not the owned-only arrays, and arrays() then gives views that stay put.
- Granular views: zeroing the velocities of the 200-grain column gives the velocity Verlet step
  from rest, checked through (w1 − w0)(f0 + f1) = dt f0 v1, which needs no masses.
- Macroparticle views are the rod's engine arrays in its reduced units (the unit text gives one
  unit in SI): the centres span the cylinder, and zeroed velocities give the step from rest.
- The phase-field view is the grid, shaped (ny, nx): a random field written into it gives the
  forward-Euler step of the Ginzburg–Landau equation that numpy computes (two steps, 1e-14).
- The DBM view is f (16 velocities × the lattice with its ghosts): Σ f_k is the density of each
  side of the Sod tube, and the left state's f^eq written into every cell stays put for two steps.
- Per-atom energies (computed for a `pe` dump column) sum to the thermo PotEng at a dump step.
- The run is the command line's: the in-process run's thermo.csv, series.csv and dumps are
  bytewise those of `shockfield run` with the same values and thread count (views taken), and so
  are the CSV files of mpm, pd, granular, phasefield, dbm and macroparticle runs.
- Mistakes raise: a wrong dtype or shape on assignment, stepping a run with no step left or one
  closed by finish(), finishing early, a bad key (the command line's message).
"""

import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import shockfield

SF = os.environ["SHOCKFIELD_BIN"]
CASES = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "cli" / "cases"
MVV2E = 1.0364269e-4  # amu·Å²/ps² -> eV (core/units.hpp, LAMMPS metal units)
FTM2V = 1.0 / MVV2E


def small_cu(steps_warm, steps_run):
    case = shockfield.Case.load(CASES / "tiny_cu.toml")
    return case.set("stage[0].steps", steps_warm).set("stage[1].steps", steps_run)


class InProcess(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def cli(self, case, folder, *args):
        command = [SF, "run", str(case), "-o", str(folder), "-q", *args]
        process = subprocess.run(command, capture_output=True, text=True)
        self.assertEqual(process.returncode, 0, process.stderr)

    def assert_same_files(self, a, b, suffixes):
        names = sorted(str(p.relative_to(b)) for p in b.rglob("*") if p.suffix in suffixes)
        self.assertTrue(names)
        for name in names:
            self.assertEqual((a / name).read_bytes(), (b / name).read_bytes(), name)
        return names

    def test_zeroed_velocities_give_the_predicted_next_step(self):
        case = small_cu(10, 10).set("output.thermo_every", 1)
        sim = shockfield.Simulation(case, self.dir / "run", threads=2)
        self.assertEqual(sim.method, "md")
        sim.step(11)  # into the NVE stage
        v, f = sim["velocities"], sim["forces"]
        self.assertEqual((v.shape, v.dtype, f.shape), ((256, 3), np.float64, (256, 3)))
        mass = 2.0 * sim.thermo()["KinEng"] / (MVV2E * np.sum(v * v))  # one element: Cu
        f0 = f.copy()
        v[:] = 0.0
        self.assertEqual(sim.step(1), 1)
        predicted = 0.5 * 0.002 * FTM2V * (f0 + f) / mass
        np.testing.assert_allclose(v, predicted, rtol=1e-12, atol=1e-14)
        ke = 0.5 * MVV2E * mass * np.sum(predicted * predicted)
        self.assertAlmostEqual(sim.thermo()["KinEng"] / ke, 1.0, delta=1e-12)
        last = np.genfromtxt(self.dir / "run" / "thermo.csv", delimiter=",", names=True)[-1]
        self.assertEqual(int(last["step"]), 12)
        self.assertAlmostEqual(last["ke_eV"] / ke, 1.0, delta=1e-9)  # 10 printed digits
        sim.step(sim.steps_left)
        sim.finish()
        self.assertTrue((self.dir / "run" / "summary.json").is_file())

    def test_views_stay_valid_across_neighbour_rebuilds(self):
        with shockfield.Simulation(small_cu(60, 60), self.dir / "run", threads=2) as sim:
            old = sim.arrays()
            address = {name: a.__array_interface__["data"][0] for name, a in old.items()}
            while not sim.finished:
                sim.step(15)
                fresh = sim.arrays()
                for name in ("positions", "velocities", "forces", "types", "ids", "images"):
                    self.assertEqual(fresh[name].__array_interface__["data"][0], address[name], name)
                    np.testing.assert_array_equal(old[name], fresh[name])
            self.assertEqual(sim.step_number, 120)
        log = (self.dir / "run" / "log.txt").read_text()
        rebuilds = [int(line.split("(")[1].split(",")[1].split()[0]) for line in log.splitlines()
                    if "neighbour rebuilds)" in line]
        self.assertGreater(sum(rebuilds), 0, log)

    def test_a_moved_array_raises_stale_view_error(self):
        case = small_cu(2, 40).set("system.lattice.repeat", [4, 4, 2]).set("stage[1].deform_rate", [0.0, 0.0, -5.0])
        sim = shockfield.Simulation(case, self.dir / "run", threads=1)
        sim.step(2)
        sim.arrays()
        with self.assertRaises(shockfield.errors.StaleViewError) as caught:
            while not sim.finished:
                sim.step(1)
        self.assertEqual(sim.step_number, 20)  # 7.23 Å (1 - 5/ps · 0.036 ps) < 5.95 Å
        message = str(caught.exception)
        self.assertIn("positions (128 rows, now 128), forces (128 rows, now 128), types (128 rows, now 128) moved",
                      message)
        self.assertNotIn("velocities", message)
        fresh = sim.arrays()
        address = {name: a.__array_interface__["data"][0] for name, a in fresh.items()}
        sim.step(5)  # no error: the storage was reserved for the two layers
        for name, a in sim.arrays().items():
            self.assertEqual(a.__array_interface__["data"][0], address[name], name)
            np.testing.assert_array_equal(fresh[name], a)
        self.assertLess(np.ptp(fresh["positions"][:, 2]), 5.95)  # the view shows the compressed cell

    def test_per_atom_energies_sum_to_the_potential_energy(self):
        case = small_cu(5, 5).set("output.dump_fields", ["id", "type", "x", "y", "z", "pe"])
        sim = case.set("output.dump_every", 5).simulation(self.dir / "run", threads=1)
        sim.step(5)  # a dump step: per-atom energies computed
        e = sim["energies"]
        self.assertEqual(e.shape, (256,))
        self.assertAlmostEqual(e.sum() / sim.thermo()["PotEng"], 1.0, delta=1e-13)  # summed in another order

    def test_md_is_the_command_lines(self):
        sets = ["stage[0].steps=20", "stage[1].steps=20", "output.dump_every=20"]
        case = shockfield.Case.load(CASES / "tiny_cu.toml")
        for s in sets:
            key, value = s.split("=")
            case.set(key, int(value))
        sim = case.simulation(self.dir / "py", threads=2)
        sim.arrays()  # views taken: they must not change the run
        sim.step(7)
        sim.step(100)
        sim.finish()
        self.cli(CASES / "tiny_cu.toml", self.dir / "cli", "-j", "2", *sum((["--set", s] for s in sets), []))
        names = self.assert_same_files(self.dir / "py", self.dir / "cli", (".csv", ".lammpstrj"))
        self.assertIn("thermo.csv", names)

    def test_other_methods_are_the_command_lines(self):
        for case in ("mpm_tiny.toml", "pd_tiny.toml", "granular_tiny.toml", "phasefield_tiny.toml", "dbm_sod.toml",
                     "macroparticle_tiny.toml"):
            with self.subTest(case=case):
                sim = shockfield.Simulation(CASES / case, self.dir / case / "py", threads=2)
                sim.arrays()  # views taken (mpm recomputes its fastest wave speed, dbm copies f: same values)
                while not sim.finished:
                    sim.step(25)
                sim.finish()
                self.cli(CASES / case, self.dir / case / "cli", "-j", "2")
                names = self.assert_same_files(self.dir / case / "py", self.dir / case / "cli", (".csv",))
                self.assertTrue({"series.csv", "thermo.csv"} & set(names), names)

    def test_mpm_and_pd_views(self):
        for case in ("mpm_tiny.toml", "pd_tiny.toml"):
            with self.subTest(case=case):
                sim = shockfield.Simulation(CASES / case, self.dir / case, threads=1)
                x, v = sim["positions"], sim["velocities"]
                self.assertEqual((x.ndim, x.shape[1], x.dtype), (2, 3, np.float64))
                self.assertEqual(v.shape, x.shape)
                self.assertEqual(sim.units()["velocities"], "m/s")
                before = x.copy()
                sim.step(3)
                self.assertFalse(np.array_equal(before, x))  # the view follows the particles

    def test_granular_views(self):
        sim = shockfield.Simulation(CASES / "granular_tiny.toml", self.dir / "run", threads=1)
        self.assertEqual(sim.units(), {"displacements": "m", "velocities": "m/s", "forces": "N"})
        sim.step(20)
        w, v, f = sim["displacements"], sim["velocities"], sim["forces"]
        self.assertEqual((w.shape, v.shape, f.shape, w.dtype), ((200,), (200,), (200,), np.float64))
        w0, f0 = w.copy(), f.copy()
        v[:] = 0.0
        sim.step(1)
        # velocity Verlet from rest: w1 - w0 = dt (dt/2m) f0 and v1 = (dt/2m)(f0 + f1), so
        # (w1 - w0)(f0 + f1) = dt f0 v1 whatever the masses; w1 - w0 is ~1e-4 of w, so rounding
        # leaves ~1e-12 of the largest term (measured 2.9e-13)
        dt = sim.time / sim.step_number
        lhs, rhs = (w - w0) * (f0 + f), dt * f0 * v
        np.testing.assert_allclose(lhs, rhs, rtol=0, atol=1e-10 * np.max(np.abs(rhs)))
        self.assertGreater(np.max(np.abs(rhs)), 0.0)

    def test_macroparticle_views(self):
        # The rod's engine works in reduced units; each unit text is one engine unit in SI. Its
        # centres span the 14 mm cylinder less one spacing r0 (0.0119 m) and the 8 layers.
        sim = shockfield.Simulation(CASES / "macroparticle_tiny.toml", self.dir / "run", threads=1)
        unit = {name: float(text.split()[0]) for name, text in sim.units().items() if text}
        x, v, f = sim["positions"], sim["velocities"], sim["forces"]
        self.assertEqual(x.shape, (417, 3))
        np.testing.assert_allclose(np.ptp(x, axis=0) * unit["positions"], [0.0119, 0.0119, 0.0238], rtol=1e-3)
        sim.step(10)
        # zeroed velocities, as for the granular chain: (x1 − x0)(f0 + f1) = dt f0 v1 (Langevin's
        # forces included) on every particle but the two end layers the loading moves; x1 − x0 is
        # far smaller than x, so rounding leaves ~1e-9 of the largest term (measured 2e-9)
        inner = (x[:, 2] > x[:, 2].min() + 0.1) & (x[:, 2] < x[:, 2].max() - 0.1)
        x0, f0 = x.copy(), f.copy()
        v[:] = 0.0
        sim.step(1)
        dt = sim.time / sim.step_number / (unit["positions"] / unit["velocities"])  # engine time
        lhs, rhs = ((x - x0) * (f0 + f))[inner], (dt * f0 * v)[inner]
        np.testing.assert_allclose(lhs, rhs, rtol=0, atol=1e-7 * np.max(np.abs(rhs)))

    def test_phasefield_view_is_the_grid(self):
        # forward Euler on the 48 × 40 periodic grid: ξ1 = ξ0 + dt (D ∇²ξ0 − ξ0(ξ0 − a)(ξ0 − 1)) with
        # the 5-point Laplacian, x along the last axis; twice, so the second step reads the view's
        # storage after the first (the explicit step would otherwise swap buffers)
        case = shockfield.Case.load(CASES / "phasefield_tiny.toml")
        case.set("time.dt", 0.05).set("time.scheme", "explicit")
        sim = shockfield.Simulation(case, self.dir / "run", threads=1)
        xi = sim["xi"]
        self.assertEqual((xi.shape, xi.dtype, sim.units()["xi"]), ((40, 48), np.float64, ""))
        xi[...] = np.random.default_rng(23).uniform(0.0, 1.0, xi.shape)
        dx, a, dt = 0.5, 0.4, 0.05
        for _ in range(2):
            before = xi.copy()
            laplacian = (sum(np.roll(before, s, axis) for s in (1, -1) for axis in (0, 1)) - 4 * before) / dx**2
            predicted = before + dt * (laplacian - before * (before - a) * (before - 1.0))
            sim.step(1)
            np.testing.assert_allclose(xi, predicted, rtol=0, atol=1e-14)  # the same sums, another order

    def test_dbm_view_is_f(self):
        # f_k of the 100-cell Sod tube, ghosts included; Σ_k f_k = ρ (Xu et al. (2015), eq. 20).
        # Writing the left state's f^eq into every cell makes the tube uniform: the step leaves
        # it as it is (no gradient, no departure from equilibrium) instead of launching Sod's waves.
        sim = shockfield.Simulation(CASES / "dbm_sod.toml", self.dir / "run", threads=1)
        f = sim["f"]
        self.assertEqual((f.shape, f.dtype), ((16, 5, 104), np.float64))
        self.assertAlmostEqual(f[:, 2, 2].sum(), 1.0, delta=1e-14)  # left ρ
        self.assertAlmostEqual(f[:, 2, -3].sum(), 0.125, delta=1e-14)  # right ρ
        f[...] = f[:, 2:3, 2:3].copy()
        uniform = f.copy()
        for _ in range(2):  # one at a time: the view must show f after each step (buffers not swapped)
            sim.step(1)
            np.testing.assert_allclose(f, uniform, rtol=1e-13, atol=0)  # rounding: 1.5e-14 measured

    def test_mistakes_raise(self):
        sim = shockfield.Simulation(small_cu(2, 2), self.dir / "run", threads=1)
        with self.assertRaisesRegex(TypeError, "velocities: expected dtype float64, got float32"):
            sim["velocities"] = np.zeros((256, 3), dtype=np.float32)
        with self.assertRaisesRegex(ValueError, r"velocities: expected shape \(256, 3\), got \(3, 256\)"):
            sim["velocities"] = np.zeros((3, 256))
        with self.assertRaisesRegex(KeyError, "md simulation has no array 'temperature'; it has: positions"):
            sim["temperature"]
        with self.assertRaisesRegex(ValueError, "finish\\(\\): 4 step\\(s\\) left"):
            sim.finish()
        with self.assertRaisesRegex(ValueError, "expected a number of steps >= 0"):
            sim.step(-1)
        self.assertEqual(sim.step(10), 4)
        with self.assertRaisesRegex(ValueError, r"step\(1\): the run has no step left \(at step 4\)"):
            sim.step(1)
        sim.finish()
        with self.assertRaisesRegex(ValueError, "the run was closed by finish"):
            sim.step(1)
        sim["velocities"][:] = 0.0  # a view outlives the run's end: the memory is the Simulation's
        bad = shockfield.Case.load(CASES / "tiny_cu.toml")
        bad.overrides.append("md.timestepp=0.001")
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.Simulation(bad, self.dir / "bad")
        process = subprocess.run([SF, "run", str(CASES / "tiny_cu.toml"), "-o", str(self.dir / "bad2"),
                                  "--set", "md.timestepp=0.001"], capture_output=True, text=True)
        self.assertEqual(process.returncode, 2)
        self.assertEqual(str(caught.exception), process.stderr.strip().removeprefix("error: "))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
