"""shockfield.Case and shockfield.Run against the command line (ctest python.test_case; ~10 s).

A case run from Python and the same case run by `shockfield run` with the same --set values
and thread count write byte-identical thermo tables, series and dumps (both are the same
binary; this checks that Case passes the case, its values and the thread count through
unchanged). Mistakes raise the command line's message: the test compares the two texts.
"""

import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import tomllib
import unittest

import numpy as np

import shockfield

SF = os.environ["SHOCKFIELD_BIN"]
CASES = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "cli" / "cases"


class Cases(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def cli(self, *args):
        return subprocess.run([SF, *args], capture_output=True, text=True)

    def test_md_run_is_the_command_lines(self):
        case = shockfield.Case.load(CASES / "tiny_cu.toml")
        case.set("stage[0].steps", 20).set("stage[1].steps", 20).set("output.dump_every", 20)
        seen = []
        run = case.run(output=self.dir / "py", threads=2, quiet=True, progress=lambda s, f: seen.append((s, f)))
        cli = self.cli("run", str(CASES / "tiny_cu.toml"), "-o", str(self.dir / "cli"), "-j", "2", "-q",
                       "--set", "stage[0].steps=20", "--set", "stage[1].steps=20", "--set", "output.dump_every=20")
        self.assertEqual(cli.returncode, 0, cli.stderr)
        names = sorted(str(p.relative_to(self.dir / "cli")) for p in (self.dir / "cli").rglob("*")
                       if p.suffix in (".csv", ".lammpstrj"))
        self.assertIn("thermo.csv", names)
        self.assertTrue(any(n.endswith(".lammpstrj") for n in names), names)
        for name in names:
            self.assertEqual((self.dir / "py" / name).read_bytes(), (self.dir / "cli" / name).read_bytes(), name)
        self.assertEqual(run.method, "md")
        self.assertEqual(run.summary["status"], "finished")
        self.assertEqual(run.summary["steps"], 40)
        self.assertEqual(run.thermo.dtype.names[0], run.thermo.dtype.names[0])
        self.assertGreater(len(run.thermo), 2)
        frames = list(run.frames())
        self.assertGreaterEqual(len(frames), 2)
        self.assertEqual(len(frames[-1].data), 256)
        self.assertEqual(frames[-1].step, 40)
        self.assertAlmostEqual(frames[-1].time, 40 * 0.002, places=12)
        self.assertTrue({"x", "y", "z", "vx"} <= set(frames[-1].data.dtype.names))
        print(f"ok: md case from Python byte-identical to the CLI's ({len(names)} files), "
              f"{len(seen)} progress callbacks, {len(frames)} frames")

    def test_set_unknown_key_has_the_cli_message(self):
        case = shockfield.Case.load(CASES / "mpm_tiny.toml")
        with self.assertRaises(shockfield.InputError) as caught:
            case.set("loading.sped", 200.0)
        cli = self.cli("run", str(CASES / "mpm_tiny.toml"), "--check", "--set", "loading.sped=200.0")
        self.assertEqual(cli.returncode, 2)
        self.assertEqual(str(caught.exception), cli.stderr.strip().removeprefix("error: "))
        self.assertIn("loading.sped", str(caught.exception))
        self.assertEqual(case.overrides, [])  # a refused value is not kept
        with self.assertRaises(shockfield.InputError) as caught:
            case.set("loading.speed", "fast")
        self.assertIn("loading.speed", str(caught.exception))
        print("ok:", str(caught.exception).splitlines()[0])

    def test_check_from_dict_and_mpm_run(self):
        with open(CASES / "mpm_tiny.toml", "rb") as f:
            table = tomllib.load(f)
        case = shockfield.Case.from_dict(table, directory=self.dir)
        case.set("loading.speed", 200)
        resolved = case.check()
        self.assertEqual(resolved["loading"]["speed"], 200)
        self.assertIn("derived", resolved)
        self.assertEqual(resolved["derived"], shockfield.Case.load(CASES / "mpm_tiny.toml").set(
            "loading.speed", 200).check()["derived"])
        run = case.run(output=self.dir / "mpm", threads=1, quiet=True)
        self.assertEqual(list(self.dir.glob(".case-*")), [])  # the temporary case file is removed
        self.assertEqual(run.config["loading"]["speed"], 200)
        self.assertGreater(len(run.series), 5)
        self.assertIn("time_s", run.series.dtype.names)
        frames = list(run.frames())
        self.assertGreaterEqual(len(frames), 2)
        self.assertEqual(frames[0].data.ndim, 2)
        self.assertTrue(np.all(np.diff([fr.time for fr in frames]) > 0))
        with self.assertRaises(shockfield.InputError) as caught:
            run.table("profiles")
        self.assertIn("its tables: ", str(caught.exception))
        self.assertIn("series.csv", str(caught.exception))
        print("ok: from_dict + set + check + run (mpm),", len(frames), "field frames;", caught.exception)

    def test_every_method_opens(self):
        expected = {"pd_tiny": "profiles", "dbm_sod": "profiles", "phasefield_tiny": "fields", "granular_tiny": "dumps"}
        for name, frames in expected.items():
            run = shockfield.Case.load(CASES / f"{name}.toml").run(output=self.dir / name, threads=1, quiet=True)
            self.assertEqual(run.summary["status"], "finished", name)
            self.assertGreater(len(run.thermo), 1, name)
            self.assertGreater(len(run.series), 1, name)
            got = list(run.frames(kind=frames))
            self.assertGreaterEqual(len(got), 2, name)
            self.assertTrue(all(a.time < b.time for a, b in zip(got, got[1:])), name)
            if name == "pd_tiny":
                self.assertIn("sxx_Pa", got[-1].data.dtype.names)
                # pd with dump = true: its dumps first, one per profile, at the profiles' steps and times
                dumps = list(run.frames())
                self.assertEqual([f.step for f in dumps], [f.step for f in got])
                self.assertTrue(np.allclose([f.time for f in dumps], [f.time for f in got], rtol=1e-9))  # CSV: 10 digits
            elif name == "granular_tiny":  # the grain frames' dumps, ITEM: TIME in s
                self.assertEqual([f.step for f in got], [0, 309, 617])
                self.assertEqual(got[0].data["vz"][0], -0.05)  # grain 0 struck downward, z up
                self.assertAlmostEqual(got[-1].time, 1e-4, delta=2e-7)  # due at 1e-4 s, the step at or past
                with self.assertRaises(shockfield.InputError) as caught:
                    next(run.frames(kind="fields"))
                self.assertIn("has no fields (it has: dumps, particles); its tables: ", str(caught.exception))
                # The same frames as .vtp (profiles/grains.pvd): z = -depth and velocity up, as the dumps'.
                grains = list(run.frames(kind="particles"))
                self.assertTrue(np.allclose([f.time for f in grains], [f.time for f in got], rtol=1e-6))
                self.assertTrue(np.allclose(grains[-1].data["velocity"][:, 2], got[-1].data["vz"], rtol=1e-6, atol=0))
            elif name == "dbm_sod":
                self.assertEqual(next(run.frames()).data.dtype, np.float64)  # dbm: fields first
            else:
                self.assertEqual(got[-1].data.dtype, np.float64)
        print("ok: pd, dbm, phasefield, granular run folders open with their tables and frames")

    def test_run_errors(self):
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.Run.open(self.dir)
        self.assertIn("not a run folder", str(caught.exception))
        (self.dir / "out").mkdir()
        (self.dir / "out" / "x").write_text("")
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.Case.load(CASES / "mpm_tiny.toml").run(output=self.dir / "out", quiet=True)
        cli = self.cli("run", str(CASES / "mpm_tiny.toml"), "-o", str(self.dir / "out"), "-q")
        self.assertEqual(str(caught.exception), cli.stderr.strip().removeprefix("error: "))
        with self.assertRaises(shockfield.InputError):
            shockfield.Case.from_dict({"method": "mpm", "grid": {"dim": 7}}).check()


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
