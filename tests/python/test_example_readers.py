"""Example scripts read run folders through shockfield.run (issue 23: one shared reader for every
run-folder file instead of per-script copies). A grep-level check over examples/*/*.py: a script
that parses a file itself (csv, numpy.loadtxt/genfromtxt, json.load, tomllib.load, pandas.read_csv,
or open() on a run-folder file name) while naming a run-folder file fails, unless ALLOWED lists it
with the reason. An allowed script that no longer parses a run-folder file fails too, so the list
cannot go stale. The check is shown to fail on a planted offender (ctest python.test_example_readers;
well under 1 s)."""

import os
import pathlib
import re
import tempfile
import unittest

SOURCE = pathlib.Path(os.environ.get("SHOCKFIELD_SOURCE", pathlib.Path(__file__).resolve().parents[2]))

# What a shockfield run or analysis folder holds (docs/python.md, docs/cli.md).
RUN_FILES = (r"summary\.json|config\.resolved\.toml|thermo\.csv|series\.csv|profiles|index\.csv|"
             r"tracks\.csv|growth\.csv|voids\.csv|domains\.csv|burgers\.csv|structures\.csv|clusters\.csv|"
             r"hugoniot_\w*\.(?:toml|csv)|shock_front\w*\.csv|hugoniot_sweep\.csv|\.lammpstrj|final\.data|\.p?vt[ipu]|\.pvd")
PARSERS = (r"csv\.DictReader|csv\.reader|\bloadtxt\(|\bgenfromtxt\(|json\.loads?\(|tomllib\.loads?\(|"
           r"pd\.read_csv|pandas\.read_csv")
OPEN_OF_RUN_FILE = rf"open\([^)]*(?:{RUN_FILES})"

# Scripts that parse files that are not run-folder outputs, or whose run-folder files the
# example cannot reproduce cheaply enough to prove a conversion; each with its reason.
ALLOWED = {
    "bridge_cu_atoms_to_plate/plot.py": "mpm_states.txt, pd_speeds.txt and timings.txt are the example's own "
                                        "tables (written by run.sh, mpm_hugoniot.py, pd_front_speed.py), no run-folder "
                                        "files; its run folders go through shockfield.run",
}


def offending_lines(script):
    """The lines of `script` that parse a file itself, when the script names a run-folder file."""
    text = script.read_text(encoding="utf-8")
    if not re.search(RUN_FILES, text):
        return []
    return [f"{script.name}:{number}: {line.strip()}" for number, line in enumerate(text.splitlines(), 1)
            if re.search(PARSERS, line) or re.search(OPEN_OF_RUN_FILE, line)]


def offenders(examples):
    """{script relative to examples: its offending lines} over examples/*/*.py."""
    found = {}
    for script in sorted(examples.glob("*/*.py")):
        lines = offending_lines(script)
        if lines:
            found[str(script.relative_to(examples))] = lines
    return found


class ExampleReaders(unittest.TestCase):
    def test_examples_use_the_shared_reader(self):
        found = offenders(SOURCE / "examples")
        unexpected = {name: lines for name, lines in found.items() if name not in ALLOWED}
        self.assertEqual(unexpected, {}, "example scripts parsing run-folder files themselves; read them "
                         "through shockfield.run.Run (or add the script to ALLOWED with the reason)")
        stale = sorted(set(ALLOWED) - set(found))
        self.assertEqual(stale, [], "ALLOWED lists scripts that no longer parse run-folder files")

    def test_planted_offender_is_caught(self):
        with tempfile.TemporaryDirectory() as tmp:
            examples = pathlib.Path(tmp)
            (examples / "planted").mkdir()
            (examples / "planted" / "ok.py").write_text(
                "from shockfield.run import Run\nrows = Run.open(folder).table('thermo')\n")
            (examples / "planted" / "bad.py").write_text(
                "import csv\nrows = list(csv.DictReader(open(f'{run}/thermo.csv')))\n")
            (examples / "planted" / "raw.py").write_text(
                "text = open(folder + '/config.resolved.toml').read()\n")
            (examples / "planted" / "own_data.py").write_text(
                "import numpy as np\ndata = np.loadtxt('literature.txt')\n")
            found = offenders(examples)
            self.assertEqual(sorted(found), ["planted/bad.py", "planted/raw.py"])
            self.assertIn("csv.DictReader", found["planted/bad.py"][0])


if __name__ == "__main__":
    unittest.main()
