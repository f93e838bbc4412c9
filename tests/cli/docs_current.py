#!/usr/bin/python3
"""Stale-docs check: what the docs quote of the command line and the case files still exists.

    docs_current.py SHOCKFIELD SOURCE_ROOT [FILE ...]

FILEs default to every docs/**/*.md, README.md, examples/*/README.md and examples/*/run.sh of
SOURCE_ROOT. Four checks, each cheap and each catching a sentence that went stale when the code
changed under it:

- Flags: every command line a file quotes, `shockfield SUB [SUB2] ... --flag` (in a code block
  or inline code, continuation lines joined; `"$sf"`/`"$SF"`/`"$SHOCKFIELD"` stand for
  shockfield in scripts), names only flags that `shockfield SUB [SUB2] --help` lists (or
  shockfield's own). The subcommands and their help come from the binary itself.
- Case keys: every key in the first column of a key table (`| `key` | ... |` rows under a heading
  that names a `[section]`) is a string literal, "key", somewhere in src/shockfield: a key the case
  readers no longer read by that name is reported. (It does not prove the key is accepted in that
  section; `tests/cli/case_errors.sh` and the fuzzers do the readers' own checks.)
- Paths: every repository path a Markdown file quotes (`src/…`, `tests/…`, `examples/…`, `docs/…`,
  `python/…`, `bench/…`, `scripts/…`) exists, as written or as a module name with its source
  ending (`io/vtk_xml` for vtk_xml.hpp/.cpp) or a prefix ending in `_` (`crystal_*`); paths with
  a pattern ({ } * < >) and the peers' own paths (FOREIGN_PATHS) are left out.
- Python names: every `shockfield.x.y` / `shockfield_plot.x` a Markdown file quotes in inline code
  is a package, a module (.py, .pyi: the compiled _core) or a name its module defines (def, class,
  assignment, import) under python/.

Prints each stale quote with its file and line; exits 1 if there is any.
"""
import pathlib
import re
import subprocess
import sys

COMMAND = re.compile(r'(?:(?<![\w/.$-])shockfield|"\$(?:sf|SF|SHOCKFIELD)")((?: [a-z][a-z0-9-]*){1,3})([^`|;&)]*)')
FLAG = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")
KEY_ROW = re.compile(r"\| ((?:`[A-Za-z_]\w*`(?:, | or |/)?)+) \|")
SECTION_HEADING = re.compile(r"#+ .*`\[\[?[\w.]+\]?\]`")
REPO_PATH = re.compile(r"(?<![\w./-])((?:src|tests|examples|docs|python|bench|scripts)/[\w./{}*<>-]*\w)")
MODULE_ENDINGS = ("", ".hpp", ".cpp", ".py", ".sh")
# Paths in other projects' trees that the docs cite: LAMMPS's sources and benchmark input, CabanaPD's
# examples.
FOREIGN_PATHS = ("src/SHOCK/", "src/fix_", "bench/in.", "examples/mechanics/")
PYTHON_NAME = re.compile(r"`(shockfield(?:_plot)?(?:\.\w+)+)")
NOT_PYTHON = {"shockfield.pc"}  # the pkg-config file (docs/install.md)


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


def stale_keys(path, text, literals):
    in_section = False
    for number, line in enumerate(text.splitlines(), 1):
        if line.startswith("#"):
            in_section = bool(SECTION_HEADING.match(line))
        row = KEY_ROW.match(line)
        if in_section and row:
            for key in re.findall(r"`([A-Za-z_]\w*)`", row.group(1)):
                if key not in literals:
                    yield f"{path}:{number}: key `{key}` of a key table is read nowhere in src/shockfield (no \"{key}\")"


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


def main():
    binary, root, *files = sys.argv[1:]
    root = pathlib.Path(root)
    if not files:
        files = [*sorted((root / "docs").rglob("*.md")), root / "README.md", *sorted(root.glob("examples/*/README.md")),
                 *sorted(root.glob("examples/*/run.sh"))]
    flags = help_tree(binary)
    source = "\n".join(p.read_text() for p in (root / "src/shockfield").rglob("*.[ch]pp"))
    literals = set(re.findall(r'"([A-Za-z_]\w*)"', source))
    problems = []
    for f in map(pathlib.Path, files):
        text = f.read_text()
        problems += stale_flags(f, text, flags)
        if f.suffix == ".md":
            problems += stale_keys(f, text, literals)
            problems += stale_paths(f, text, root)
            problems += stale_python_names(f, text, root)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"ok: {len(files)} files quote only flags the --help lists, keys the readers read, paths and Python names that exist "
          f"({len(flags)} subcommands)")


if __name__ == "__main__":
    main()
