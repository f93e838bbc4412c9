"""Burgers circuits around the Shockley partials that bound the stacking faults of one frame.
The stacking faults are the clusters of hcp atoms (analyze atoms --clusters 3.0 --cluster-select
acna:hcp): flat plates on {111} whose edge is the partial dislocation loop. For each plate of at
least MIN atoms, with principal axes e1 (longest), e2, e3 (the plate normal) and semi-axes a, b, a
circuit of radius R is placed around the line through c ± 0.9 a e1 along e2 and around c ± 0.9 b e2
along e1 — the four places where the loop crosses the plate's principal axes (the plate is an
elliptical disc; for a uniform disc the edge is at 0.89 of √(5λ)). Each circuit is one
`analyze atoms --burgers-line` call (a circuit that does not close is reported, not fatal).
Usage: burgers_partials.py SHOCKFIELD DUMP CLUSTERS_CSV OUT_CSV [MIN=40] [R=6]"""
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import read_csv, read_lammps_dump  # noqa: E402  (the shared readers of analyze outputs)

bin_, dump, clusters_csv, out_csv = sys.argv[1:5]
min_size = int(sys.argv[5]) if len(sys.argv) > 5 else 40
radius = float(sys.argv[6]) if len(sys.argv) > 6 else 6.0
step = read_lammps_dump(dump)[0][0]
rows = [r for r in read_csv(clusters_csv) if int(r["timestep"]) == step and int(r["size"]) >= min_size]
results = []
for r in rows:
    c = np.array([float(r[f"{q}_A"]) for q in "xyz"])
    e1 = np.array([float(r[f"axis1_{q}"]) for q in "xyz"])
    e2 = np.array([float(r[f"axis2_{q}"]) for q in "xyz"])
    a, b = float(r["a_A"]), float(r["b_A"])
    for where, centre, xi in (("+e1", c + 0.9 * a * e1, e2), ("-e1", c - 0.9 * a * e1, -e2),
                              ("+e2", c + 0.9 * b * e2, -e1), ("-e2", c - 0.9 * b * e2, e1)):
        line = f"{centre[0]:.3f},{centre[1]:.3f},{centre[2]:.3f}:{xi[0]:.4f},{xi[1]:.4f},{xi[2]:.4f}:{radius}"
        with tempfile.TemporaryDirectory() as tmp:
            p = subprocess.run([bin_, "analyze", "atoms", dump, "--adaptive-cna", "--burgers-line", line,
                                "--burgers-orient", "1 1 0,-1 1 0,0 0 1", "-o", tmp, "-j", "1"],
                               capture_output=True, text=True)
            if p.returncode != 0:
                results.append(dict(timestep=step, stacking_fault=int(r["cluster"]), sf_atoms=int(r["size"]), place=where,
                                    line=line, b="", kind="no closed circuit", reliable="", max_step_error=""))
                continue
            b = read_csv(os.path.join(tmp, "burgers.csv"), text=("b",))[0]  # b: "0" when the circuit closes
            # max_step_error as analyze atoms writes it ({:.4g}, analyze_atoms_burgers.cpp)
            results.append(dict(timestep=step, stacking_fault=int(r["cluster"]), sf_atoms=int(r["size"]), place=where,
                                line=line, b=b["b"], kind=b["kind"], reliable=int(b["reliable"]),
                                max_step_error=f"{b['max_step_error']:.4g}"))
fields = ["timestep", "stacking_fault", "sf_atoms", "place", "line", "b", "kind", "reliable", "max_step_error"]
new = not os.path.exists(out_csv)
with open(out_csv, "a", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=fields)
    if new:
        w.writeheader()
    for x in results:
        w.writerow(x)
for x in results:
    print(f"step {x['timestep']} SF {x['stacking_fault']} ({x['sf_atoms']} atoms) {x['place']}: {x['b'] or '-'} {x['kind']} "
          f"reliable {x['reliable']} err {x['max_step_error']}")
