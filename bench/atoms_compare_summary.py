"""Medians of bench/atoms_compare.sh's rounds: shockfield 1 and 2 threads against LAMMPS's three
computes (with − without), per round and median, with the load average before each run.
Usage: atoms_compare_summary.py runs/bench_atoms/rounds.txt"""
import re
import statistics as st
import sys

rounds = {}
load = None
atoms = None
extra = []
for line in open(sys.argv[1]):
    m = re.match(r"round (\d+) load ([\d.]+) ([\d.]+) ([\d.]+)", line)
    if m:
        load = float(m.group(2))
        rounds.setdefault(int(m.group(1)), {}).setdefault("load", []).append(load)
        continue
    m = re.match(r"round (\d+) ours: shockfield (\d) thread\(s\): wall median ([\d.]+) s .*CPU median ([\d.]+) s", line)
    if m:
        rounds[int(m.group(1))][f"ours{m.group(2)}"] = (float(m.group(3)), float(m.group(4)))
        continue
    m = re.match(r"round (\d+) ours: atoms (\d+)", line)
    if m:
        atoms = int(m.group(2))
        continue
    m = re.match(r"round (\d+) ours: shockfield: fcc (\d+); neighbour table ([\d.]+) bytes/atom; peak RSS ([\d.]+) MB", line)
    if m:
        rounds[int(m.group(1))]["ours_fcc"] = int(m.group(2))
        rounds[int(m.group(1))]["table"] = float(m.group(3))
        continue
    m = re.match(r"round (\d+) lammps (with|without): ([\d.]+) ([\d.]+) ([\d.]+) (\d+)", line)
    if m:
        e, u, s, kb = float(m.group(3)), float(m.group(4)), float(m.group(5)), int(m.group(6))
        rounds[int(m.group(1))][m.group(2)] = (e, u + s, kb)
        continue
    if line.startswith(("cli", "lammps fcc", "load")):
        extra.append(line.rstrip())
print(f"atoms {atoms}")
print("| round | load avg (1 min) before the runs | ours 1 thread wall (s) | ours 2 threads wall (s) | speed-up | ours 1 thread CPU (s) | LAMMPS computes wall (s) | LAMMPS computes CPU (s) | LAMMPS/ours wall | LAMMPS/ours CPU |")
print("|---|---|---|---|---|---|---|---|---|---|")
cols = {k: [] for k in ("o1", "o2", "sp", "c1", "lw", "lc", "ratio", "cratio")}
for r, d in sorted(rounds.items()):
    if not all(k in d for k in ("ours1", "ours2", "with", "without")):
        continue
    o1, o2 = d["ours1"][0], d["ours2"][0]
    lw = d["with"][0] - d["without"][0]
    lc = d["with"][1] - d["without"][1]
    c1 = d["ours1"][1]
    vals = dict(o1=o1, o2=o2, sp=o1 / o2, c1=c1, lw=lw, lc=lc, ratio=lw / o1, cratio=lc / c1)
    for k, v in vals.items():
        cols[k].append(v)
    print(f"| {r} | {', '.join(f'{x:.2f}' for x in d['load'])} | {o1:.3f} | {o2:.3f} | {o1 / o2:.2f} | {c1:.3f} | {lw:.2f} | {lc:.2f} | "
          f"{lw / o1:.1f} | {lc / c1:.1f} |")
med = {k: st.median(v) for k, v in cols.items() if v}
print(f"| median | | {med['o1']:.3f} | {med['o2']:.3f} | {med['sp']:.2f} | {med['c1']:.3f} | {med['lw']:.2f} | {med['lc']:.2f} | "
      f"{med['ratio']:.1f} | {med['cratio']:.1f} |")
if atoms:
    print(f"atoms/s: ours 1 thread {atoms / med['o1']:.3g}, 2 threads {atoms / med['o2']:.3g}, LAMMPS {atoms / med['lw']:.3g}")
last = rounds[max(rounds)]
if "with" in last:
    print(f"LAMMPS peak RSS with computes {last['with'][2] / 1024:.0f} MB, without {last['without'][2] / 1024:.0f} MB: "
          f"{(last['with'][2] - last['without'][2]) * 1024 / atoms:.0f} bytes/atom for the computes, "
          f"{last['with'][2] * 1024 / atoms:.0f} bytes/atom in all")
print(f"ours: neighbour table {last.get('table', 0):.1f} bytes/atom; fcc {last.get('ours_fcc')}")
for line in extra:
    print(line)
