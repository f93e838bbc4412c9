"""shockfield.Simulation stopped and resumed, and DBM's fields (ctest python.test_simulation_resume).

- Resume: the 256-atom Cu case (10 + 10 steps, a thermo row every step) and the 100-cell DBM Sod
  tube (50 steps), each stepped in-process for 7 (md) or 23 (dbm) steps, stopped with stop() (a
  checkpoint, summary.json "stopped", the command line's message naming --resume), then resumed
  by Simulation(case, output, resume=True) and stepped to the end: thermo.csv (and dbm's
  series.csv) are byte-identical to an uninterrupted `shockfield run` with the same thread count.
  A stopped Simulation refuses more steps.
- DBM fields: Simulation.fields() gives ρ, (vx, vy) and T as copies; at every step that writes a
  profile (profiles/profile_<k>.csv: the whole row of the one-cell-high tube) they equal its
  columns as printed, and at every field frame (fields/*.vti, Float32) ρ and T rounded to
  float32 equal the frame's arrays exactly (as doubles they differ by 5.6e-8 relative: float32). Writing into the copies changes nothing. md's fields are its box (test_triclinic.py).
"""

import csv
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import shockfield
from shockfield import _core

SF = os.environ["SHOCKFIELD_BIN"]
CASES = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "cli" / "cases"


def small_cu():
    case = shockfield.Case.load(CASES / "tiny_cu.toml")
    return case.set("stage[0].steps", 10).set("stage[1].steps", 10).set("output.thermo_every", 1)


class Resume(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def cli(self, case_file, folder, *args):
        process = subprocess.run([SF, "run", str(case_file), "-o", str(folder), "-q", "-j", "1", *args],
                                 capture_output=True, text=True)
        self.assertEqual(process.returncode, 0, process.stderr)

    def test_stop_and_resume_equal_an_uninterrupted_run(self):
        cu = small_cu()
        for name, case, stop_at, files, sets in (
                ("md", cu, 7, ("thermo.csv",), ["stage[0].steps=10", "stage[1].steps=10", "output.thermo_every=1"]),
                ("dbm", shockfield.Case.load(CASES / "dbm_sod.toml"), 23, ("thermo.csv", "series.csv"), [])):
            with self.subTest(method=name):
                folder = self.dir / name / "py"
                sim = shockfield.Simulation(case, folder, threads=1)
                sim.step(stop_at)
                message = sim.stop()
                self.assertIn("--resume", message)
                self.assertTrue(sim.closed)
                self.assertEqual(json.loads((folder / "summary.json").read_text())["status"], "stopped")
                with self.assertRaisesRegex(ValueError, "closed by finish\\(\\) or stop\\(\\)"):
                    sim.step(1)
                resumed = shockfield.Simulation(case, folder, threads=1, resume=True)
                self.assertEqual(resumed.step_number, stop_at)
                while not resumed.finished:
                    resumed.step(10)
                resumed.finish()
                case_file = CASES / ("tiny_cu.toml" if name == "md" else "dbm_sod.toml")
                self.cli(case_file, self.dir / name / "cli", *sum((["--set", s] for s in sets), []))
                for file in files:
                    self.assertEqual((folder / file).read_bytes(), (self.dir / name / "cli" / file).read_bytes(), file)

    def test_dbm_fields_are_the_written_ones(self):
        sim = shockfield.Simulation(CASES / "dbm_sod.toml", self.dir / "run", threads=1)
        profiles, frames, checked_profiles, checked_frames = self.dir / "run" / "profiles", self.dir / "run" / "fields", 0, 0
        seen_profiles, seen_frames = len(list(profiles.glob("profile_*.csv"))), len(list(frames.glob("*.vti")))
        while not sim.finished:
            sim.step(1)
            fields = sim.fields()
            self.assertEqual((fields["rho"].shape, fields["velocity"].shape, fields["T"].shape),
                             ((1, 100), (1, 100, 2), (1, 100)))
            written = sorted(profiles.glob("profile_*.csv"), key=lambda p: int(p.stem.split("_")[1]))
            if len(written) > seen_profiles:
                seen_profiles = len(written)
                with open(written[-1]) as f:
                    rows = list(csv.DictReader(f))
                for column, values in (("rho", fields["rho"][0]), ("vx", fields["velocity"][0, :, 0]),
                                       ("vy", fields["velocity"][0, :, 1]), ("T", fields["T"][0])):
                    # the CSV as printed: the same formatting of the same double
                    self.assertEqual([f"{float(r[column]):.10g}" for r in rows], [f"{v:.10g}" for v in values], column)
                checked_profiles += 1
            vti = sorted(frames.glob("*.vti"))
            if len(vti) > seen_frames:
                seen_frames = len(vti)
                for name in ("rho", "T"):  # the frames store Float32: the same double rounded once
                    np.testing.assert_array_equal(_core.read_field(str(vti[-1]), name)[0],
                                                  fields[name].astype(np.float32).astype(np.float64))
                checked_frames += 1
        self.assertGreaterEqual(checked_profiles, 1)
        self.assertGreaterEqual(checked_frames, 1)
        before = sim.fields()
        before["rho"][...] = 0.0  # a copy: the simulation is unchanged
        np.testing.assert_array_equal(sim.fields()["T"], before["T"])
        self.assertGreater(sim.fields()["rho"].min(), 0.1)
        sim.finish()
        md = shockfield.Simulation(small_cu(), self.dir / "md", threads=1)
        self.assertEqual(sorted(md.fields()), ["box_hi", "box_lo", "box_tilt", "cell"])  # md's: its box


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
