"""Medians of a bench/delaunay_compare.sh log: per data set and program, the wall and CPU
seconds of the division (`seconds`, `cpu_seconds`) and the process CPU (`cpu USER SYS`), and per
query kind the SHT and nanoflann rates.   python3 bench/delaunay_compare_summary.py LOG
"""
import re
import statistics
import sys
from collections import defaultdict

runs = defaultdict(lambda: defaultdict(list))  # (set, program) -> field -> values
rates = defaultdict(list)  # (program, kind) -> rates
data_set, program, query_program = None, None, "after"
for line in open(sys.argv[1]):
    if m := re.match(r"round \d+ (\S+)", line):
        data_set = m.group(1)
    elif m := re.match(r"(before )?(shockfield|cgal|scipy) (\d)d points (\d+) \S+ (\d+) seconds ([\d.]+)"
                       r"(?: cpu_seconds ([\d.]+))?", line):
        program = "before" if m.group(1) else m.group(2)
        key = (data_set if m.group(2) != "scipy" else f"{m.group(3)}d {m.group(4)} points", program)
        runs[key]["simplices"].append(int(m.group(5)))
        runs[key]["seconds"].append(float(m.group(6)))
        if m.group(7):
            runs[key]["cpu_seconds"].append(float(m.group(7)))
    elif m := re.match(r"\s+cpu ([\d.]+) ([\d.]+)", line):
        runs[key]["process_cpu"].append(float(m.group(1)) + float(m.group(2)))
    elif line.startswith("before:"):
        query_program = "before"
    elif m := re.match(r"(nearest|radius): sht ([\d.e+]+) /s, nanoflann ([\d.e+]+) /s", line):
        rates[(query_program, m.group(1), "sht")].append(float(m.group(2)))
        rates[(query_program, m.group(1), "nanoflann")].append(float(m.group(3)))
        rates[(query_program, m.group(1), "ratio")].append(float(m.group(2)) / float(m.group(3)))
        if m.group(1) == "radius":
            query_program = "after"
for (data_set, program), fields in runs.items():
    cells = ", ".join(f"{name} {statistics.median(v):.4g} (n={len(v)})" for name, v in fields.items())
    print(f"{data_set:>16} {program:>10}: {cells}")
for key, v in sorted(rates.items()):
    print(f"queries {' '.join(key)}: median {statistics.median(v):.3g} of {[f'{x:.3g}' for x in v]}")
