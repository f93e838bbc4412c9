"""Writing into MPM's and PD's views changes their next step (ctest python.test_simulation_views);
md, granular, macroparticle, phasefield and dbm have theirs in test_simulation.py.

- PD: bond forces depend on relative positions only (Galilean invariance), so adding a uniform
  velocity c along the bar to every point of one of two identical runs leaves its forces as they
  were and, after one step, its velocities c higher and its points c dt further than the other
  run's. The 400-point bar of pd_tiny.toml has free ends (its impact is the two halves' initial
  velocities), so nothing breaks the invariance.
- MPM: a uniform velocity field does not deform a body, so a strip given v = (0, -u, 0) on every
  particle (u = 250 m/s, the case's own loading is 1000 m/s) keeps that velocity for one step and
  moves by -u dt, away from the wall's and the grid sides' cells (two cells, 50 µm, around them);
  without the write the same particles move at 1000 m/s.
- MPM's material state (pressure, energy, ..., deviator, F) is a strided view into the particles'
  array of structs: energy raised by Δe raises the next pressure by ρ0 Γ0 Δe, and the views equal
  the particle frames (float32) at the end of the run.
- PD's damage (computed from its bonds) comes from Simulation.fields() as a copy equal to the
  profiles' damage column and, averaged, to the thermo's MeanDamage; a correspondence model's
  stress and plastic strain equal the profiles' columns too.
- Both keep their arrays' addresses for the whole run (they never resize them).
"""

import os
import pathlib
import sys
import tempfile
import unittest

import numpy as np

import shockfield

CASES = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "cli" / "cases"


def addresses(sim):
    return {name: a.__array_interface__["data"][0] for name, a in sim.arrays().items()}


class WritesChangeTheNextStep(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_pd_uniform_velocity_added(self):
        plain = shockfield.Simulation(CASES / "pd_tiny.toml", self.dir / "plain", threads=1)
        moved = shockfield.Simulation(CASES / "pd_tiny.toml", self.dir / "moved", threads=1)
        where = addresses(moved)
        plain.step(10)
        moved.step(10)
        x0 = moved["positions"].copy()
        np.testing.assert_array_equal(x0, plain["positions"])
        c = 50.0  # m/s along the bar
        moved["velocities"][:, 0] += c
        dt = plain.time / plain.step_number  # fixed step
        plain.step(1)
        moved.step(1)
        # velocities: c more, to the rounding of |v| ≈ 300 m/s and of the forces of positions
        # shifted by c dt (measured 1.3e-11 m/s; the forces 2.2e-12 of the largest, the shift
        # 3.3e-12 of c dt ≈ 7e-8 m)
        np.testing.assert_allclose(moved["velocities"][:, 0] - plain["velocities"][:, 0], c, rtol=0, atol=1e-9)
        np.testing.assert_array_equal(moved["velocities"][:, 1:], plain["velocities"][:, 1:])
        shift = (moved["positions"][:, 0] - x0[:, 0]) - (plain["positions"][:, 0] - x0[:, 0])
        np.testing.assert_allclose(shift, c * dt, rtol=1e-9)
        force = plain["force_densities"]
        np.testing.assert_allclose(moved["force_densities"], force, rtol=0, atol=1e-9 * np.max(np.abs(force)))
        while not moved.finished:
            moved.step(50)
        self.assertEqual(addresses(moved), where)

    def test_mpm_uniform_velocity_written(self):
        sim = shockfield.Simulation(CASES / "mpm_tiny.toml", self.dir / "run", threads=1)
        where = addresses(sim)
        x, v = sim["positions"], sim["velocities"]
        x0 = x.copy()
        np.testing.assert_allclose(v[:, 1], -1000.0)  # the case's loading: towards the wall at y = 0
        u = 250.0
        v[:] = (0.0, -u, 0.0)
        sim.step(1)
        dt = sim.time
        margin = 50e-6  # two cells from the wall (y = 0) and the grid's sides (x = 0, 0.4 mm)
        inner = (x0[:, 1] > margin) & (x0[:, 0] > margin) & (x0[:, 0] < 0.4e-3 - margin)
        self.assertGreater(inner.sum(), 500)
        # a uniform field stays uniform: v to the rounding of u (measured 9e-13 m/s), the step -u dt
        # to 1.4e-13 of it, no sideways motion at all (835 of the 1217 particles inside)
        np.testing.assert_allclose(v[inner], np.tile([0.0, -u, 0.0], (inner.sum(), 1)), rtol=0, atol=1e-9)
        np.testing.assert_allclose((x - x0)[inner][:, 1], -u * dt, rtol=1e-9)
        np.testing.assert_allclose((x - x0)[inner][:, 0], 0.0, rtol=0, atol=1e-9 * u * dt)
        while not sim.finished:
            sim.step(50)
        self.assertEqual(addresses(sim), where)

    def test_mpm_material_state_views(self):
        # Each particle's material state (pressure, energy, ..., deviator and F) is a strided view
        # into the particles' array of structs: the values the particle frames write, and writing
        # into them changes the next step. Mie–Grüneisen is linear in e, P = P_H(ρ) + ρ0 Γ0 (e − e_H)
        # (Xu et al. (2015), eq. 5), so energy raised by Δe on every particle raises the pressure of
        # the undeformed inner particles after one step by ρ0 Γ0 Δe exactly (a uniform velocity does
        # no work: their energy stays Δe above the other run's).
        plain = shockfield.Simulation(CASES / "mpm_tiny.toml", self.dir / "plain", threads=1)
        hot = shockfield.Simulation(CASES / "mpm_tiny.toml", self.dir / "hot", threads=1)
        n = len(hot["positions"])
        state = hot.arrays()
        self.assertEqual((state["pressures"].shape, state["deviators"].shape, state["deformations"].shape),
                         ((n,), (n, 3, 3), (n, 3, 3)))
        np.testing.assert_array_equal(state["deformations"], np.broadcast_to(np.eye(3), (n, 3, 3)))
        self.assertEqual(hot.units()["energies"], "J/kg")
        x0 = hot["positions"].copy()
        de = 2.0e4  # J/kg
        state["energies"] += de
        plain.step(1)
        hot.step(1)
        config = shockfield.Run.open(hot.folder).config
        material = next(m for m in config["material"] if m["name"] == "al")
        rho0_gamma0 = material["rho0"] * material["gamma0"]  # 2700 kg/m³ × 1.96
        margin = 50e-6
        inner = (x0[:, 1] > margin) & (x0[:, 0] > margin) & (x0[:, 0] < 0.4e-3 - margin)
        np.testing.assert_allclose((hot["energies"] - plain["energies"])[inner], de, rtol=1e-12)
        # both measured equal to 4e-16 (relative)
        np.testing.assert_allclose((hot["pressures"] - plain["pressures"])[inner], rho0_gamma0 * de, rtol=1e-12)
        # the views are the frames' values: run to the end, whose state the last particle frame holds
        while not plain.finished:
            plain.step(50)
        plain.finish()
        frame = shockfield.Run.open(plain.folder).last_frame(kind="particles")
        self.assertAlmostEqual(frame.time, plain.time, delta=1e-12 * plain.time)
        views, data = plain.arrays(), frame.data  # the frames store float32: the views rounded to it
        for view, column in (("temperatures", "temperature"), ("energies", "energy"), ("plastic_works", "plastic_work"),
                             ("plastic_strains", "plastic_strain"), ("damages", "damage")):
            np.testing.assert_array_equal(views[view].astype(np.float32), data[column], view)
        np.testing.assert_array_equal(views["deviators"].reshape(-1, 9).astype(np.float32), data["deviator"].reshape(-1, 9))
        # the frame's pressure is −tr σ / 3 = P + q − tr s / 3 (tr s ≈ 0), rounded to float32
        np.testing.assert_allclose(views["pressures"] + views["viscous_pressures"], data["pressure"], rtol=1e-7,
                                   atol=1e-7 * np.max(np.abs(data["pressure"])))
        self.assertGreater(np.max(data["plastic_strain"]), 0.0)

    def test_pd_damage_field(self):
        # PD's damage is computed from the bonds, not stored: Simulation.fields() gives it as a copy.
        # The 40 × 20 plate's pre-crack leaves points with broken bonds from the start; at the end
        # the field equals the last profile's damage column (printed to 10 digits) and its mean the
        # thermo row's MeanDamage.
        sim = shockfield.Simulation(CASES / "pd_plate_loading.toml", self.dir / "plate", threads=1)
        first = sim.fields()["damage"]
        self.assertEqual(first.shape, (len(sim["positions"]),))
        self.assertGreater(np.count_nonzero(first), 0)
        first[:] = 1.0  # a copy: the simulation does not see it
        self.assertLess(sim.fields()["damage"].max(), 1.0)
        while not sim.finished:
            sim.step(50)
        damage = sim.fields()["damage"]
        self.assertAlmostEqual(damage.mean(), sim.thermo()["MeanDamage"], delta=1e-15)
        sim.finish()
        profile = shockfield.Run.open(sim.folder).last_frame(kind="profiles")
        self.assertAlmostEqual(profile.time, sim.time, delta=1e-12 * sim.time)
        np.testing.assert_allclose(damage, profile.data["damage"], rtol=1e-9, atol=1e-12)
        self.assertEqual(np.count_nonzero(damage), 64)  # the thermo's Broken column (measured)
        with self.assertRaisesRegex(ValueError, "the mpm method computes no fields"):
            shockfield.Simulation(CASES / "mpm_tiny.toml", self.dir / "mpm", threads=1).fields()

    def test_pd_stress_and_plastic_fields(self):
        # A correspondence (J2) model's Cauchy stress and plastic strain per point, from fields(): at
        # the end of the 300 m/s bar impact they are the last profile's columns (10 printed digits).
        sim = shockfield.Simulation(CASES / "pd_tiny.toml", self.dir / "bar", threads=1)
        while not sim.finished:
            sim.step(50)
        fields = sim.fields()
        sim.finish()
        n = len(sim["positions"])
        self.assertEqual((fields["stress"].shape, fields["plastic"].shape), ((n, 3, 3), (n,)))
        np.testing.assert_array_equal(fields["damage"], np.zeros(n))  # no bonds to break
        profile = shockfield.Run.open(sim.folder).last_frame(kind="profiles")
        self.assertAlmostEqual(profile.time, sim.time, delta=1e-12 * sim.time)
        scale = np.max(np.abs(fields["stress"]))
        self.assertGreater(scale, 1e8)  # the impact stress, ~1 GPa
        for column, (row, col) in (("sxx_Pa", (0, 0)), ("syy_Pa", (1, 1)), ("szz_Pa", (2, 2)), ("sxy_Pa", (0, 1)),
                                   ("sxz_Pa", (0, 2)), ("syz_Pa", (1, 2))):
            np.testing.assert_allclose(fields["stress"][:, row, col], profile.data[column], rtol=1e-9,
                                       atol=1e-12 * scale, err_msg=column)
        np.testing.assert_allclose(fields["plastic"], profile.data["plastic"], rtol=1e-9, atol=1e-15)
        self.assertGreater(fields["plastic"].max(), 0.0)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
