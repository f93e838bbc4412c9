"""Cu under [110] tension (examples/md_cu_tension_partials): stress and structure fractions against
strain, and snapshots of the defect atoms with the Burgers vectors found around them.
Usage: plot.py RUN ANALYSIS BURGERS OUT.png
Reads RUN/thermo.csv (pxx), ANALYSIS/dump.*.lammpstrj (columns coord, cna, acna), BURGERS/burgers.csv
(circuits around core clusters) and BURGERS/partials.csv (around the stacking faults' edges);
writes OUT.png and prints the table of the README (fractions against strain)."""
import glob
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run, read_csv, read_lammps_dump  # noqa: E402  (the shared readers)

run, ana, bdir, out = sys.argv[1:5]
rate, dt, start = 0.01, 0.002, 1000     # 1/ps, ps per step, first step of the stretch (case.toml)


def strain(step):
    return max(step - start, 0) * dt * rate


thermo = Run.open(run).thermo
ts = thermo["step"].astype(np.int64)
sxx = -thermo["pxx_bar"] / 1e4   # GPa, tension positive
frames = []
for path in sorted(glob.glob(os.path.join(ana, "dump.*.lammpstrj")), key=lambda p: int(p.split(".")[-2])):
    step, _, _, c = read_lammps_dump(path)[0]  # the annotated dump's one frame: step, time, box, atoms
    frames.append(dict(step=step, c=c, hcp=np.mean(c["acna"] == 2), other=np.mean(c["acna"] == 5),
                       bcc=np.mean(c["acna"] == 3), cna_hcp=np.mean(c["cna"] == 2), cna_other=np.mean(c["cna"] == 5),
                       c13=np.mean(c["coord"] == 13), cnot12=np.mean(c["coord"] != 12)))
burgers = []
for name in ("burgers.csv", "partials.csv"):
    p = os.path.join(bdir, name)
    if os.path.exists(p):
        table = read_csv(p, text=("b", "circuit", "reliable", "stacking_fault"))  # compared and shown as text
        for r in (dict(zip(table.dtype.names, row)) for row in table):
            if "line" in r:   # partials.csv: the line's centre
                r["circuit"] = f"SF{r['stacking_fault']}{r['place']}"
                r["centre_x_A"], r["centre_y_A"], r["centre_z_A"] = r["line"].split(":")[0].split(",")
            burgers.append(r)
eps = np.array([strain(f["step"]) for f in frames])

print("| strain | σxx (GPa) | a-CNA hcp | a-CNA other | a-CNA bcc | CNA hcp (2) | CNA other (5) | coord 13 | coord ≠ 12 |")
print("|---|---|---|---|---|---|---|---|---|")
for f in frames:
    if f["step"] < start:
        continue
    s = sxx[np.argmin(abs(ts - f["step"]))]
    print(f"| {strain(f['step']):.3f} | {s:.1f} | {f['hcp']:.4f} | {f['other']:.4f} | {f['bcc']:.4f} | {f['cna_hcp']:.4f} | "
          f"{f['cna_other']:.4f} | {f['c13']:.4f} | {f['cnot12']:.4f} |")

# Snapshots: the frame with the most reliable Shockley circuits, and the frame of the largest hcp fraction.
shock = [b for b in burgers if b["reliable"] == "1" and b["kind"].startswith("Shockley")]
per_frame = {}
for b in shock:
    per_frame[int(b["timestep"])] = per_frame.get(int(b["timestep"]), 0) + 1
first = max(per_frame, key=lambda s: (per_frame[s], -s)) if per_frame else None
peak = max(frames, key=lambda f: f["hcp"])["step"]
snaps = [s for s in (first, peak) if s is not None]
if len(snaps) == 2 and snaps[0] == snaps[1]:
    snaps = snaps[:1]

fig = plt.figure(figsize=(6 + 5 * len(snaps), 4.8))
ax = fig.add_subplot(1, 1 + len(snaps), 1)
ax.plot(ts * 0 + [strain(s) for s in ts], sxx, "k-", lw=1.2, label="σxx (GPa)")
ax.set_xlabel("engineering strain along [110]")
ax.set_ylabel("tensile stress σxx (GPa)")
ax2 = ax.twinx()
ax2.plot(eps, [f["hcp"] for f in frames], "g-o", ms=3, label="a-CNA hcp (stacking faults)")
ax2.plot(eps, [f["other"] for f in frames], "r-o", ms=3, label="a-CNA other (partials, cores, surfaces)")
ax2.plot(eps, [f["bcc"] for f in frames], "b-", lw=0.8, label="a-CNA bcc")
ax2.plot(eps, [f["c13"] for f in frames], "m--", lw=0.8, label="coordination 13")
ax2.set_ylabel("fraction of atoms")
ax2.set_ylim(0, 1)
h1, l1 = ax.get_legend_handles_labels()
h2, l2 = ax2.get_legend_handles_labels()
ax.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper left")
ax.set_title("Cu_u3, uniaxial strain along [110], 1e10 /s, 300 K")
for k, s in enumerate(snaps):
    f = next(fr for fr in frames if fr["step"] == s)
    c = f["c"]
    a3 = fig.add_subplot(1, 1 + len(snaps), 2 + k, projection="3d")
    for code, colour, name in ((2, "tab:green", "hcp (CNA 2)"), (5, "tab:red", "other (CNA 5)")):
        m = c["acna"] == code
        a3.scatter(c["x"][m], c["y"][m], c["z"][m], s=1.0, c=colour, depthshade=False, label=name)
    a3.set_xlabel("x [110] (Å)")
    a3.set_ylabel("y [-110] (Å)")
    a3.set_zlabel("z [001] (Å)")
    lines = []
    for b in burgers:
        if int(b["timestep"]) != s or b["reliable"] != "1" or b["b"] == "0":
            continue
        cx, cy, cz = (float(b[f"centre_{q}_A"]) for q in "xyz")
        a3.text(cx, cy, cz, b["circuit"], fontsize=7)
        lines.append(f"{b['circuit']}: b = {b['b']} ({b['kind'].split()[0]})")
    a3.set_title(f"strain {strain(s):.3f}: {f['hcp']:.3f} hcp, {f['other']:.3f} other", fontsize=9)
    a3.text2D(0.0, -0.02, "\n".join(lines[:8]) + ("\n..." if len(lines) > 8 else ""), transform=a3.transAxes, fontsize=7,
              va="top")
    a3.legend(fontsize=7, loc="upper right", markerscale=6)
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"snapshots at steps {snaps}; {len(shock)} reliable Shockley circuits in all")
