#!/usr/bin/python3
"""Stale-docs check: what the docs quote of the command line and the case files still exists.

    docs_current.py SHOCKFIELD SOURCE_ROOT [FILE ...]
    docs_current.py SHOCKFIELD SOURCE_ROOT --printed DIR [FILE ...]

FILEs default to every docs/**/*.md, README.md, examples/*/README.md and examples/*/run.sh of
SOURCE_ROOT. Five checks, each catching a sentence that went stale when the code changed under it
(the first four cheap, the fifth on what examples printed):

- Flags: every command line a file quotes, `shockfield SUB [SUB2] ... --flag` (in a code block
  or inline code, continuation lines joined; `"$sf"`/`"$SF"`/`"$SHOCKFIELD"` stand for
  shockfield in scripts), names only flags that `shockfield SUB [SUB2] --help` lists (or
  shockfield's own). The subcommands and their help come from the binary itself.
- Case keys, per section: every key in the first column of a key table (a table whose header's
  first column is `key`, under a heading that names a `[section]` or `[[section]]`) is read in that
  section. On the page of a method (docs/<method>*.md, and PAGE_METHOD) "read" means: the resolved
  case (`shockfield run --check --write-resolved`) of some case file of that method under
  examples/ or tests/cli/cases/ holds the key in a table of that name ([grid], or [x.grid]); a key
  no case file sets nor defaults (one read only with another key: a `data_file` system's
  `boundary`, an msst stage's `q`) must be a string literal, "key", in a source file of the
  method's folder (src/shockfield/<method>/) that also names the section, "section", or one of the
  reviewed CONDITIONAL_KEYS, each naming the file that reads it (an entry a case now reads is
  reported, so the list only shrinks). $DOCS_CURRENT_KEYS_CACHE names a file that keeps the
  resolved keys for a second run on the same tree. So a key documented under [md] that only [mpm] reads, or
  under [output] that only [grid] reads, is reported. Pages of no method (material files, run
  inputs) keep the weaker test: "key" is a literal somewhere in src/shockfield.
- Paths: every repository path a Markdown file quotes (`src/…`, `tests/…`, `examples/…`, `docs/…`,
  `python/…`, `bench/…`, `scripts/…`) exists, as written or as a module name with its source
  ending (`io/vtk_xml` for vtk_xml.hpp/.cpp) or a prefix ending in `_` (`crystal_*`); paths with
  a pattern ({ } * < >) and the peers' own paths (FOREIGN_PATHS) are left out.
- Python names: every `shockfield.x.y` / `shockfield_plot.x` a Markdown file quotes in inline code
  is a package, a module (.py, .pyi: the compiled _core) or a name its module defines (def, class,
  assignment, import) under python/.
- Examples: every folder of examples/ has a README.md, a run.sh and a picture (.png), as the
  repository's README says.
- Quoted values (docs_values.py): a number followed by a marker `<!-- value: EXAMPLE LABEL ... -->`
  is what examples/EXAMPLE/run.sh prints after LABEL. Without --printed only the markers' form is
  checked (the example exists, the marker follows a number); with --printed DIR (a folder holding
  EXAMPLE.txt, the stdout of run.sh, for the examples a test ran) only this check runs, on every
  marker of those examples, and an example with a file there but no marker is reported.

Prints each stale quote with its file and line; exits 1 if there is any.
"""
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import tomllib

from docs_values import markers, stale_values, unchecked_examples

COMMAND = re.compile(r'(?:(?<![\w/.$-])shockfield|"\$(?:sf|SF|SHOCKFIELD)")((?: [a-z][a-z0-9-]*){1,3})([^`|;&)]*)')
FLAG = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")
KEY_ROW = re.compile(r"\| ((?:`[A-Za-z_]\w*`(?:, | or |/)?)+) \|")
SECTION_HEADING = re.compile(r"#+ .*?`\[\[?([\w.]+)\]?\]`")
SECTION_PARAGRAPH = re.compile(r"`\[\[?([\w.]+)\]?\]`")
REPO_PATH = re.compile(r"(?<![\w./-])((?:src|tests|examples|docs|python|bench|scripts)/[\w./{}*<>-]*\w)")
MODULE_ENDINGS = ("", ".hpp", ".cpp", ".py", ".sh")
# Paths in other projects' trees that the docs cite: LAMMPS's sources and benchmark input, CabanaPD's
# examples.
FOREIGN_PATHS = ("src/SHOCK/", "src/fix_", "bench/in.", "examples/mechanics/")
PYTHON_NAME = re.compile(r"`(shockfield(?:_plot)?(?:\.\w+)+)")
NOT_PYTHON = {"shockfield.pc"}  # the pkg-config file (docs/install.md)


# Pages named for no method whose key tables are a method's case keys.
PAGE_METHOD = {"analysis-atoms": "md"}
# Keys read only with another key present, which no case file under examples/ or tests/cli/cases/
# sets, and read in a file outside the method's folder or without the section's name: (page, section,
# key) -> the file that reads it (checked to exist and name the key as a word). Each was tried with
# `run --check --set` on a case of the method: refused as a wrong value, not as an unknown key.
REGION = "src/shockfield/geometry/region.cpp"  # the shapes of MD's [[system.delete]] and PD's [[region]]
CONDITIONAL_KEYS = {
    ("md-system", "system", "data_file"): "src/shockfield/md/system_builder.cpp",  # instead of [system.lattice]
    ("md-system", "system", "elements"): "src/shockfield/md/system_builder.cpp",  # with data_file
    ("md-system", "system", "boundary"): "src/shockfield/md/system_builder.cpp",  # with data_file
    ("granular", "impurity", "poisson_ratio"): "src/shockfield/granular/case_file.cpp",  # read when given (no default)
    **{("md-system", "system.delete", k): REGION for k in ("axis", "lo", "hi")},  # shape = "cylinder"
    **{("pd", "region", k): REGION for k in ("axis", "lo", "hi")},  # shape = "cylinder"
    ("pd", "region", "velocity_file"): "src/shockfield/pd/regions.cpp",
    ("pd", "region", "components"): "src/shockfield/pd/regions.cpp",  # with prescribed_*
    ("pd", "material", "euler_angles_deg"): "src/shockfield/pd/crystal_case.cpp",  # orientation = "euler"
    # read as "xyz"[d] for each of the grid's dimensions
    **{("phasefield", "grid.boundary", k): "src/shockfield/phasefield/case_file.cpp" for k in "xyz"},
}


class CaseKeys:
    """Where the case readers read each key: the resolved case of every case file under examples/
    and tests/cli/cases/ (`run --check --write-resolved`: every key read, defaults included), per
    method and section; the string literals of the sources per file."""

    def __init__(self, binary, root, cache=None):
        self.root = root
        self.read = {}  # (method, section path) -> keys
        if cache and pathlib.Path(cache).exists():  # a second run on the same tree (docs_current.sh)
            self.read = {tuple(k.split("|")): set(v) for k, v in json.loads(pathlib.Path(cache).read_text()).items()}
        else:
            self._read_cases(binary, root)
            if cache:
                pathlib.Path(cache).write_text(json.dumps({"|".join(k): sorted(v) for k, v in self.read.items()}))
        self.methods = sorted({m for m, _ in self.read})
        self.sources = {f: set(re.findall(r'"([A-Za-z_]\w*)"', f.read_text()))
                        for f in (root / "src/shockfield").rglob("*.[ch]pp")}
        self.literals = set().union(*self.sources.values())

    def _read_cases(self, binary, root):
        with tempfile.TemporaryDirectory() as work:
            for n, case in enumerate(sorted([*root.glob("examples/*/*.toml"), *root.glob("tests/cli/cases/*.toml")])):
                if not re.search(r'^method\s*=', case.read_text(), re.M):
                    continue  # a material file or a peer's input
                resolved = pathlib.Path(work) / f"{n}.toml"
                # A case whose input files a script makes first (a prepare.sh, another run) is refused; its
                # keys then rest on the source test below.
                subprocess.run([binary, "run", str(case), "--check", "--write-resolved", str(resolved)],
                               capture_output=True, cwd=root)
                if resolved.exists():
                    table = tomllib.loads(resolved.read_text())
                    self._add(table.get("method"), (), {k: v for k, v in table.items()
                                                       if k not in ("derived", "provenance")})

    def _add(self, method, path, table):
        for key, value in table.items():
            if isinstance(value, dict):
                self._add(method, path + (key,), value)
            elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
                for v in value:
                    self._add(method, path + (key,), v)
            else:
                self.read.setdefault((method, ".".join(path)), set()).add(key)

    def read_in(self, method, section, key):
        if any(key in keys for (m, s), keys in self.read.items()
               if m == method and (s == section or s.endswith("." + section))):
            return True
        if any(key in keys for (m, _), keys in self.read.items() if m == method):
            return False  # a case reads it, in another section
        folder = self.root / "src/shockfield" / method
        last = section.split(".")[-1]
        return any(key in lits and last in lits for f, lits in self.sources.items() if folder in f.parents)


def help_tree(binary):
    """{subcommand path: flags its --help lists}, for every subcommand the binary has."""
    flags, todo = {}, [()]
    while todo:
        path = todo.pop()
        text = subprocess.run([binary, *path, "--help"], capture_output=True, text=True).stdout
        flags[path] = set(FLAG.findall(text))
        listed = re.search(r"\nSubcommands:\n(.*)", text, re.S)
        todo += [path + (s,) for s in re.findall(r"^  ([a-z][a-z0-9-]*)\s{2,}", listed.group(1), re.M)] if listed else []
    return flags


def logical_lines(text):
    """(first line number, line) with backslash-continued lines joined."""
    start, parts = None, []
    for number, line in enumerate(text.splitlines(), 1):
        start = start or number
        if line.endswith("\\"):
            parts.append(line[:-1])
            continue
        yield start, " ".join(parts + [line])
        start, parts = None, []


def stale_flags(path, text, flags):
    for number, line in logical_lines(text):
        for m in COMMAND.finditer(line):
            command = ()
            for word in m.group(1).split():
                if command + (word,) not in flags:
                    break
                command += (word,)
            if not command:
                continue
            for flag in FLAG.findall(m.group(2)):
                if flag not in flags[command] | flags[()]:
                    yield f"{path}:{number}: `shockfield {' '.join(command)}` has no {flag} (not in its --help)"


def key_rows(text):
    """(line number, section path as the heading names it, key) of every key-table row: a table whose
    header's first column is `key`, under a heading naming `[section]` or `[[section]]`, or under a
    paragraph that starts with one (a sub-table's keys: `[stage.msst]`)."""
    section, key_table, previous = None, False, ""
    for number, line in enumerate(text.splitlines(), 1):
        if line.startswith("#"):
            heading = SECTION_HEADING.match(line)
            section = heading.group(1) if heading else None
        elif SECTION_PARAGRAPH.match(line):  # "`[stage.msst]` (required with ...):" opens a sub-table's keys
            section = SECTION_PARAGRAPH.match(line).group(1)
        if line.startswith("|") and not previous.startswith("|"):
            key_table = line.split("|")[1].strip() == "key"
        row = KEY_ROW.match(line)
        if section and key_table and row:
            for key in re.findall(r"`([A-Za-z_]\w*)`", row.group(1)):
                yield number, section, key
        previous = line


def page_method(path, methods):
    """The method whose case keys a docs page documents (docs/md.md, docs/md-system.md: md), or None."""
    stem = pathlib.Path(path).stem
    return PAGE_METHOD.get(stem) or next((m for m in methods if stem == m or stem.startswith(m + "-")), None)


def stale_conditional_keys(keys):
    """CONDITIONAL_KEYS entries that no longer hold: the file does not name the key, or a case reads it now
    (nothing for a tree without sources, the test's own)."""
    if not keys.sources:
        return
    for (page, section, key), source in CONDITIONAL_KEYS.items():
        file = keys.root / source
        if not file.exists() or not re.search(rf"\b{key}\b", file.read_text()):
            yield f"docs_current.py: CONDITIONAL_KEYS {(page, section, key)}: {source} does not name `{key}`"
        elif keys.read_in(page_method(page, keys.methods), section, key):
            yield f"docs_current.py: CONDITIONAL_KEYS {(page, section, key)}: a case reads it now; remove the entry"


def stale_keys(path, text, keys):
    method = page_method(path, keys.methods)
    for number, section, key in key_rows(text):
        if (pathlib.Path(path).stem, section, key) in CONDITIONAL_KEYS:
            continue
        if method is None:
            if key not in keys.literals:
                yield f"{path}:{number}: key `{key}` of a key table is read nowhere in src/shockfield (no \"{key}\")"
        elif not keys.read_in(method, section, key):
            yield (f"{path}:{number}: key `{key}` is not read in [{section}] of a {method} case (no case file's "
                   f"resolved [{section}] holds it; a case reads it elsewhere, or no src/shockfield/{method}/ file "
                   f"names both \"{key}\" and \"{section.split('.')[-1]}\")")


def stale_paths(path, text, root):
    for number, line in enumerate(text.splitlines(), 1):
        for quoted in REPO_PATH.findall(line):
            if any(c in quoted for c in "{}*<>") or quoted.startswith(FOREIGN_PATHS):
                continue
            if quoted.endswith("_") and any((root / quoted).parent.glob((root / quoted).name + "*")):
                continue
            if not any((root / (quoted + ending)).exists() for ending in MODULE_ENDINGS):
                yield f"{path}:{number}: path `{quoted}` does not exist"


def defines(module, name):
    """Whether the module at `module` (a .py/.pyi file or a package's __init__.py) defines `name`."""
    sources = [module.with_suffix(".py"), module.with_suffix(".pyi"), module / "__init__.py"]
    pattern = re.compile(rf"^\s*(def|class) {name}\b|^\s*{name}\s*[:=]|^\s*(from|import) [^\n]*\b{name}\b", re.M)
    return any(s.exists() and pattern.search(s.read_text()) for s in sources)


def python_name_exists(dotted, root):
    path = root / "python" / dotted.split(".")[0]
    for part in dotted.split(".")[1:]:
        if (path / part).is_dir() or (path / (part + ".py")).exists() or (path / (part + ".pyi")).exists():
            path = path / part
            continue
        return defines(path, part)  # an attribute of the module: deeper parts are its members
    return True


def stale_python_names(path, text, root):
    for number, line in enumerate(text.splitlines(), 1):
        for dotted in PYTHON_NAME.findall(line):
            if dotted not in NOT_PYTHON and not python_name_exists(dotted, root):
                yield f"{path}:{number}: Python name `{dotted}` does not exist under python/"


def incomplete_examples(root):
    """README.md's promise: every example has a README saying what it shows, a run.sh and a picture."""
    for example in sorted(p for p in (root / "examples").glob("*") if p.is_dir()):
        for what, present in (("README.md", (example / "README.md").exists()), ("run.sh", (example / "run.sh").exists()),
                              ("a picture (.png)", any(example.glob("*.png")))):
            if not present:
                yield f"examples/{example.name}: {what} missing (README.md says every example has one)"


def main():
    args = sys.argv[1:]
    printed_dir = None
    if "--printed" in args:
        k = args.index("--printed")
        printed_dir, args = pathlib.Path(args[k + 1]), args[:k] + args[k + 2:]
    binary, root, *files = args
    root = pathlib.Path(root)
    if not files:
        files = [*sorted((root / "docs").rglob("*.md")), root / "README.md", *sorted(root.glob("examples/*/README.md")),
                 *sorted(root.glob("examples/*/run.sh"))]
    files = list(map(pathlib.Path, files))
    if printed_dir is not None:
        sys.exit(check_printed_values(files, root, printed_dir))
    flags = help_tree(binary)
    keys = CaseKeys(binary, root, os.environ.get("DOCS_CURRENT_KEYS_CACHE"))
    problems = list(stale_conditional_keys(keys)) + list(incomplete_examples(root))
    for f in files:
        text = f.read_text()
        problems += stale_flags(f, text, flags)
        if f.suffix == ".md":
            problems += stale_keys(f, text, keys)
            problems += stale_paths(f, text, root)
            problems += stale_python_names(f, text, root)
            problems += stale_values(f, text, root, printed={})
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"ok: {len(files)} files quote only flags the --help lists, keys the readers read, paths and Python names that exist "
          f"({len(flags)} subcommands)")


def check_printed_values(files, root, printed_dir):
    """The quoted-values check alone, on the examples whose run.sh output is in printed_dir (EXAMPLE.txt)."""
    printed = {f.stem: f.read_text() for f in printed_dir.glob("*.txt")}
    texts = {f: f.read_text() for f in files if f.suffix == ".md"}
    problems = [p for f, text in texts.items() for p in stale_values(f, text, root, printed)]
    problems += [f"{example}: its run.sh output was given, but no page quotes a value of it (no marker)"
                 for example in unchecked_examples(texts.values(), printed)]
    for p in problems:
        print(p)
    checked = sum(1 for text in texts.values() for m in markers(text) if m[2] in printed)
    if not problems:
        print(f"ok: {checked} quoted values of {', '.join(sorted(printed))} agree with what run.sh printed")
    return 1 if problems else 0


if __name__ == "__main__":
    main()
