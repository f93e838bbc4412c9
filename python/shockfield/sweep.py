"""Parameter sweeps: one case run for every combination of values, side by side, into one folder.

    rows = shockfield.sweep.run_sweep("case.toml", {"loading.speed": [200, 400]}, "runs/speeds", jobs=2)

Also ``shockfield sweep CASE --set key=v1,v2,... [-j N] -o DIR`` (this module's ``main``). Every
combination is checked first (a bad key or value stops the sweep before anything runs, naming
them); the runs go to DIR/<key>=<value>[,...] and DIR/sweep.csv holds one row per run: the swept
values, status, steps, wall seconds and every number of summary.json's "results" (nested keys and
list positions joined with "."). docs/python.md.
"""

import argparse
import concurrent.futures
import csv
import itertools
import json
import pathlib
import re
import sys

from .case import Case, toml_value
from .errors import InputError, RunError, StopRequested


def split_values(text):
    """``v1,v2,...`` split at the commas outside brackets and quotes (TOML values)."""
    values, depth, quote, current = [], 0, None, ""
    for c in text:
        if quote:
            quote = None if c == quote else quote
        elif c in "\"'":
            quote = c
        elif c in "[{":
            depth += 1
        elif c in "]}":
            depth -= 1
        elif c == "," and depth == 0:
            values.append(current.strip())
            current = ""
            continue
        current += c
    values.append(current.strip())
    if any(v == "" for v in values):
        raise InputError(f"--set: empty value in '{text}'")
    return values


def _folder_name(combination):
    text = ",".join(f"{k}={v}" for k, v in combination)
    return re.sub(r"[^A-Za-z0-9_.,=+-]", "_", text)


def _flatten(prefix, value, out):
    if isinstance(value, dict):
        for k, v in value.items():
            _flatten(f"{prefix}.{k}" if prefix else k, v, out)
    elif isinstance(value, list):
        for k, v in enumerate(value):
            _flatten(f"{prefix}.{k}", v, out)
    elif isinstance(value, (int, float, str, bool)) or value is None:
        out[prefix] = value


def run_sweep(case_file, values, output, jobs=1, threads=1, overwrite=False):
    """Runs ``case_file`` for every combination of ``values`` ({key: [value, ...]}; values as
    Python values or TOML text) in ``jobs`` processes of ``threads`` OpenMP threads each. Returns
    the table rows (dicts) also written to OUTPUT/sweep.csv."""
    keys = list(values)
    if not keys:
        raise InputError("sweep: give at least one --set key=v1,v2,...")
    texts = {k: [v if isinstance(v, str) else toml_value(v) for v in vs] for k, vs in values.items()}
    combinations = [list(zip(keys, combo)) for combo in itertools.product(*(texts[k] for k in keys))]
    cases = []
    for combination in combinations:
        case = Case.load(case_file)
        for key, text in combination:
            case.overrides.append(f"{key}={text}")
        try:
            case.check()
        except InputError as error:
            raise InputError(f"sweep: {', '.join(f'{k}={v}' for k, v in combination)}: {error}") from None
        cases.append(case)
    output = pathlib.Path(output)
    output.mkdir(parents=True, exist_ok=True)

    def one(index):
        folder = output / _folder_name(combinations[index])
        try:
            run = cases[index].run(output=folder, threads=threads, overwrite=overwrite, quiet=True)
            return run.summary, ""
        except (RunError, StopRequested) as error:
            summary_file = folder / "summary.json"
            return (json.loads(summary_file.read_text()) if summary_file.is_file() else None), str(error)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        outcomes = list(pool.map(one, range(len(cases))))
    rows = []
    for combination, (summary, error) in zip(combinations, outcomes):
        row = {k: v for k, v in combination}
        row["folder"] = _folder_name(combination)
        summary = summary or {}
        row["status"] = summary.get("status", "failed")
        row["steps"] = summary.get("steps")
        row["wall_seconds"] = summary.get("wall_seconds")
        _flatten("", summary.get("results", {}), row)
        if error:
            row["message"] = error
        rows.append(row)
    columns = []
    for row in rows:
        columns += [c for c in row if c not in columns]
    with open(output / "sweep.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        writer.writerows(rows)
    return rows


def format_table(rows, width=14):
    """The rows as an aligned text table (numbers to 6 significant digits)."""
    columns = []
    for row in rows:
        columns += [c for c in row if c not in columns and c != "message"]
    def cell(v):
        return f"{v:.6g}" if isinstance(v, float) else ("" if v is None else str(v))
    widths = [max(len(c), *(len(cell(r.get(c))) for r in rows)) for c in columns]
    lines = ["  ".join(c.ljust(w) for c, w in zip(columns, widths))]
    lines += ["  ".join(cell(r.get(c)).ljust(w) for c, w in zip(columns, widths)) for r in rows]
    return "\n".join(lines)


def main(argv=None):
    """`shockfield sweep` (docs/python.md, Sweeps): runs the sweep the arguments describe, prints
    its table; returns the exit code (0 every run finished, 2 bad input, 3 a run failed)."""
    parser = argparse.ArgumentParser(prog="shockfield sweep", description=__doc__.split("\n\n")[0])
    parser.add_argument("case")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=V1,V2,...")
    parser.add_argument("-j", "--jobs", type=int, default=1)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--overwrite", action="store_true")
    args = parser.parse_args(argv)
    try:
        values = {}
        for item in args.set:
            key, sep, text = item.partition("=")
            if not sep or not key:
                raise InputError(f"--set '{item}': expected KEY=V1,V2,...")
            values[key.strip()] = split_values(text)
        rows = run_sweep(args.case, values, args.output, jobs=args.jobs, threads=args.threads,
                         overwrite=args.overwrite)
    except InputError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    print(format_table(rows))
    print(f"wrote {pathlib.Path(args.output) / 'sweep.csv'} ({len(rows)} runs)")
    return 0 if all(r["status"] == "finished" for r in rows) else 3


if __name__ == "__main__":
    sys.exit(main())
