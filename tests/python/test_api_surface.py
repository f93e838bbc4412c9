"""The package's public surface is typed and documented (ctest python.test_api_surface).

- Stubs: every module of the package with a ``.pyi`` beside it (the compiled ``_core`` included)
  has in that stub every public name it defines, every public member of its classes, and the same
  parameter names in the same order as the running code (``inspect.signature`` for Python, the
  signature line pybind11 writes into a docstring for the compiled module); the stub names nothing
  the module lacks (besides its own type aliases). A stub beside a .py hides the .py from type
  checkers, so a stub missing a name would make that name an error for a user's checker.
- Docstrings: every public function, class, method and property of every module has one.
- pandas: ``Run.table(name, pandas=True)`` hands the CSV to ``pandas.read_csv`` (pandas is not
  installed here: a stand-in module records the call; without it the table is a numpy array).
"""

import ast
import importlib
import inspect
import pathlib
import re
import sys
import tempfile
import types
import unittest
from unittest import mock

import numpy as np

import shockfield

PACKAGE = pathlib.Path(shockfield.__file__).parent
MODULES = ["shockfield", "shockfield._core", "shockfield.analysis", "shockfield.box", "shockfield.case",
           "shockfield.errors", "shockfield.run", "shockfield.simulation", "shockfield.sweep",
           "shockfield.vtk_arrays", "shockfield.plot"]


def defined_here(module, name):
    """A public name the module defines (not a module, not a re-export of another shockfield module
    but _core, whose classes the Python modules hand out)."""
    if name.startswith("_"):
        return False
    value = getattr(module, name)
    if inspect.ismodule(value):
        return False
    origin = getattr(value, "__module__", module.__name__)
    if not isinstance(origin, str) or origin in (module.__name__, "shockfield._core"):
        return True
    if origin.startswith("shockfield"):
        return False
    return not (callable(value) or inspect.isclass(value))  # constants count; imported functions do not


def stub_signatures(tree):
    """{name: parameter names (None for a variable) or {member: parameter names}} of a stub."""
    def params(f):
        a = f.args
        return [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs if p.arg not in ("self", "cls")]

    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = params(node)
        elif isinstance(node, ast.ClassDef):
            members = out[node.name] = {}
            for m in node.body:
                if isinstance(m, ast.FunctionDef):
                    members[m.name] = params(m)
                elif isinstance(m, ast.AnnAssign) and isinstance(m.target, ast.Name):
                    members[m.target.id] = None
        elif isinstance(node, ast.AnnAssign):
            out[node.target.id] = None
        elif isinstance(node, ast.Assign):
            out.update({t.id: None for t in node.targets if isinstance(t, ast.Name)})
    return out


def runtime_params(f):
    """Parameter names of a function or method, self and cls left out; None when it has no
    readable signature. pybind11's are read from its docstring's first line: name(a: T, b: U = v)."""
    if isinstance(f, (classmethod, staticmethod)):
        f = f.__func__
    try:
        return [p for p in inspect.signature(f).parameters if p not in ("self", "cls")]
    except (TypeError, ValueError):
        first = (f.__doc__ or "").split("\n", 1)[0]
        inside = first[first.find("(") + 1:first.rfind(")")] if "(" in first else ""
        depth, names, token = 0, [], ""
        for c in inside + ",":
            depth += c in "([{" and 1 or (c in ")]}" and -1 or 0)
            if c == "," and depth == 0:
                names.append(re.match(r"\s*\*{0,2}(\w+)", token).group(1)) if token.strip() else None
                token = ""
            else:
                token += c
        return [n for n in names if n != "self"] if "(" in first else None


class Stubs(unittest.TestCase):
    def test_every_stub_matches_its_module(self):
        stubs = sorted(PACKAGE.glob("*.pyi"))
        self.assertGreaterEqual(len(stubs), 8, stubs)
        for stub in stubs:
            name = "shockfield." + stub.stem
            module = importlib.import_module(name)
            declared = stub_signatures(ast.parse(stub.read_text()))
            with self.subTest(stub=stub.name):
                public = [n for n in dir(module) if defined_here(module, n)]
                self.assertEqual([n for n in public if n not in declared], [], f"{stub.name} lacks these")
                aliases = {n for n, v in declared.items() if v is None and not hasattr(module, n)}
                self.assertEqual([n for n in declared if not hasattr(module, n) and n not in aliases], [])
                for item, signature in declared.items():
                    if not hasattr(module, item):
                        continue
                    value = getattr(module, item)
                    if isinstance(signature, list):
                        self.assertEqual(signature, runtime_params(value), f"{stub.name}: {item}")
                    elif isinstance(signature, dict):
                        self.check_class(stub.name, value, signature)

    def check_class(self, stub, cls, members):
        public = [m for m in dir(cls) if not m.startswith("_") and not (inspect.isclass(cls) and
                  issubclass(cls, (BaseException, tuple)) and hasattr(BaseException if issubclass(cls, BaseException)
                                                                       else tuple, m))]
        self.assertEqual([m for m in public if m not in members], [], f"{stub}: class {cls.__name__} lacks these")
        for member, signature in members.items():
            if signature is None:  # an attribute: a class or an instance one
                continue
            self.assertTrue(hasattr(cls, member), f"{stub}: {cls.__name__}.{member} is not in the module")
            raw = inspect.getattr_static(cls, member)
            if isinstance(raw, property):
                continue
            expected = runtime_params(raw)
            if member == "__init__" and expected is None:  # pybind11: the signature is the class's
                expected = runtime_params(cls.__init__)
            self.assertEqual(signature, expected, f"{stub}: {cls.__name__}.{member}")


class Docstrings(unittest.TestCase):
    def test_every_public_callable_has_a_docstring(self):
        missing = []
        for name in MODULES:
            module = importlib.import_module(name)
            self.assertTrue((module.__doc__ or "").strip(), name)
            for item in (n for n in dir(module) if defined_here(module, n)):
                value = getattr(module, item)
                if not (callable(value) or inspect.isclass(value)):
                    continue
                if not (value.__doc__ or "").strip():
                    missing.append(f"{name}.{item}")
                if not inspect.isclass(value) or issubclass(value, BaseException):
                    continue
                for member, raw in vars(value).items():
                    if member.startswith("_") or not (callable(raw) or isinstance(raw, (property, classmethod,
                                                                                         staticmethod))):
                        continue
                    if not (getattr(raw, "__doc__", None) or "").strip():
                        missing.append(f"{name}.{item}.{member}")
        self.assertEqual(missing, [])


class Pandas(unittest.TestCase):
    def test_table_goes_through_pandas_read_csv(self):
        with tempfile.TemporaryDirectory() as folder:
            folder = pathlib.Path(folder)
            (folder / "config.resolved.toml").write_text('method = "md"\n')
            (folder / "thermo.csv").write_text("# a comment\nstep,ke_eV\n0,1.5\n10,2.5\n")
            run = shockfield.Run.open(folder)
            np.testing.assert_array_equal(run.table("thermo")["ke_eV"], [1.5, 2.5])
            calls = []
            stand_in = types.ModuleType("pandas")
            stand_in.read_csv = lambda path, **options: calls.append((pathlib.Path(path), options)) or "frame"
            with mock.patch.dict(sys.modules, {"pandas": stand_in}):
                self.assertEqual(run.table("thermo", pandas=True), "frame")
                run.table("thermo", pandas=True, text=("step",))
            self.assertEqual(calls, [(folder / "thermo.csv", {"comment": "#"}),
                                     (folder / "thermo.csv", {"comment": "#", "dtype": {"step": str}})])


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
