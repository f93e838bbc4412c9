"""The void of examples/md_void_shock_111 against time: its missing volume and the volume of the
polyhedron through the atoms around it (analyze atoms --voids, voids.csv), 0 in the frames where
no void is found. Usage: plot_void.py VOIDS_DIR RUN_DIR OUT.png"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import read_csv  # noqa: E402  (the shared reader; VOIDS_DIR is no run folder)

voids_dir, run_dir, out = sys.argv[1:4]
dt, shock_start = 0.001, 500          # ps per step; the piston starts at step 500 (case.toml)
steps = sorted(int(f.split(".")[1]) for f in os.listdir(os.path.join(run_dir, "dumps")) if f.startswith("dump."))
rows = read_csv(os.path.join(voids_dir, "voids.csv"))
missing = {s: 0.0 for s in steps}
poly = {s: 0.0 for s in steps}
for r in rows:
    s = int(r["timestep"])
    missing[s] += float(r["missing_volume_A3"])
    poly[s] += float(r["volume_A3"])
t = [(s - shock_start) * dt for s in steps]
fig, ax = plt.subplots(figsize=(6.4, 4))
ax.plot(t, [poly[s] for s in steps], "s-", ms=3, label="polyhedron through the surface atoms' centres")
ax.plot(t, [missing[s] for s in steps], "o-", ms=3, label="missing volume (atoms' own cells removed)")
ax.axhline(43 * 3.615**3 / 4, color="gray", lw=0.8, ls=":", label="43 deleted atoms × a³/4")
ax.set_xlabel("time after the piston starts (ps)")
ax.set_ylabel("void volume (Å³)")
ax.set_title("1 nm void in Cu, 1.5 km/s shock along [111]")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=110)
for s in steps:
    print(f"{s} {(s - shock_start) * dt:.2f} ps: volume {poly[s]:.0f} Å3, missing {missing[s]:.0f} Å3")
