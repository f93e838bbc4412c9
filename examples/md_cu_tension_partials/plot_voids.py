"""Voids opening in Cu under [110] tension: per frame the missing volume of each void (analyze atoms
--voids, voids.csv) and their sum against strain and time, beside the tensile stress.
Usage: plot_voids.py RUN VOIDS_DIR OUT.png"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run, read_csv  # noqa: E402  (the shared readers; VOIDS_DIR is no run folder)

run, vdir, out = sys.argv[1:4]
rate, dt, start = 0.01, 0.002, 1000
rows = read_csv(os.path.join(vdir, "voids.csv"))
steps = sorted({int(r["timestep"]) for r in rows})
frames = sorted(int(r["timestep"]) for r in read_csv(os.path.join(vdir, "structures.csv")))
total = {s: sum(float(r["missing_volume_A3"]) for r in rows if int(r["timestep"]) == s) for s in frames}
largest = {s: max([float(r["missing_volume_A3"]) for r in rows if int(r["timestep"]) == s] or [0.0]) for s in frames}
count = {s: sum(1 for r in rows if int(r["timestep"]) == s) for s in frames}
thermo = Run.open(run).thermo
fig, ax = plt.subplots(figsize=(6.4, 4.2))
t = [(s - start) * dt for s in frames]
ax.semilogy(t, [max(total[s], 1) for s in frames], "o-", label="all voids (missing volume)")
ax.semilogy(t, [max(largest[s], 1) for s in frames], "s--", ms=4, label="largest void")
ax.set_xlabel(f"time since the stretch began (ps); strain = {rate} × t")
ax.set_ylabel("void volume (Å³)")
ax.set_ylim(5, 1e5)
ax2 = ax.twinx()
tt = [(int(r["step"]) - start) * dt for r in thermo if int(r["step"]) >= frames[0]]
ax2.plot(tt, [-float(r["pxx_bar"]) / 1e4 for r in thermo if int(r["step"]) >= frames[0]], "k-", lw=0.8, label="σxx")
ax2.set_ylabel("σxx (GPa)")
h1, l1 = ax.get_legend_handles_labels()
h2, l2 = ax2.get_legend_handles_labels()
ax.legend(h1 + h2, l1 + l2, fontsize=8, loc="center left")
ax.set_title("Cu_u3, [110] tension at 1e10 /s: voids open (rolling ball R = 2.17 Å)", fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=110)
print("| step | strain | voids | largest (Å³) | all (Å³) |")
print("|---|---|---|---|---|")
for s in frames:
    print(f"| {s} | {(s - start) * dt * rate:.3f} | {count[s]} | {largest[s]:.0f} | {total[s]:.0f} |")
