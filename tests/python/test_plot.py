"""shockfield.plot (python -m shockfield.plot): the generic kinds draw any run with titles from
the run, a kind of another method is refused naming the run's kinds (ctest python.test_plot)."""

import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

import shockfield
import shockfield.plot

CASES = pathlib.Path(os.environ["SHOCKFIELD_SOURCE"]) / "tests" / "cli" / "cases"


def is_png(path):
    return pathlib.Path(path).read_bytes()[1:4] == b"PNG"


class Plot(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.mpm = shockfield.Case.load(CASES / "mpm_tiny.toml").run(
            output=pathlib.Path(cls.tmp.name) / "mpm", threads=1, quiet=True)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_generic_kinds(self):
        self.assertTrue(is_png(shockfield.plot.plot("thermo", self.mpm.folder)))
        out = shockfield.plot.plot("series", self.mpm.folder, columns=["bottom_h200um_pressure_mean"])
        self.assertTrue(is_png(out))
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.plot.plot("series", self.mpm.folder, columns=["pressure"])
        self.assertIn("has no column pressure; its columns: ", str(caught.exception))

    def test_wrong_kind_is_refused(self):
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.plot.plot("bar", self.mpm.folder)
        self.assertIn("a mpm run; 'bar' draws pd runs. Kinds for this run: thermo, series, porous, cavity",
                      str(caught.exception))
        with self.assertRaises(shockfield.InputError) as caught:
            shockfield.plot.plot("spectra", self.mpm.folder)
        self.assertIn("unknown kind 'spectra'", str(caught.exception))

    def test_module_command(self):
        p = subprocess.run([sys.executable, "-m", "shockfield.plot", "profiles", str(self.mpm.folder)],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 2)
        self.assertIn("Kinds for this run", p.stderr)
        out = pathlib.Path(self.tmp.name) / "t.png"
        p = subprocess.run([sys.executable, "-m", "shockfield.plot", "thermo", str(self.mpm.folder), "--out", str(out),
                            "--columns", "MaxTemp,TotEng"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertTrue(is_png(out))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
