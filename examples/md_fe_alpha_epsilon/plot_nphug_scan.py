"""The Hugoniostat scan of bcc Fe: per potential and pressure the Hugoniot state (log line) and
the adaptive-CNA fractions of the dumps; writes nphug_scan.csv and nphug_scan.png.
Usage: plot_nphug_scan.py RUNS/nphug OUT_DIR"""
import csv
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

root, out = sys.argv[1], sys.argv[2]
pat = re.compile(r"P = ([\d.]+) GPa.*V/V0 = ([\d.]+), T = ([\d.]+) K, Us = ([\d.]+) km/s, Up = ([\d.]+)")
rows, series = [], {}
for pot in sorted(os.listdir(root)):
    for p in sorted(os.listdir(os.path.join(root, pot)), key=lambda s: float(s[1:])):
        d = os.path.join(root, pot, p)
        state = None
        for line in open(os.path.join(d, "log.txt")):
            if "Hugoniostat" in line:
                m = pat.search(line)
                state = [float(v) for v in m.groups()]
        fr = Run.open(d).table("analysis/structures")
        hug = [r for r in fr if int(r["timestep"]) > 3000]   # the hug stage (relax: 3000 steps)
        t = [(int(r["timestep"]) - 3000) * 0.001 for r in hug]
        f = {s: [float(r[f"acna_{s}_fraction"]) for r in hug] for s in ("bcc", "hcp", "fcc", "other")}
        series[(pot, p)] = (t, f)
        last = {s: sum(v[-3:]) / 3 for s, v in f.items()}   # mean of the last 3 ps
        rows.append(dict(potential=pot, target_GPa=float(p[1:]) / 1e4, P_GPa=state[0], V_V0=state[1], T_K=state[2],
                         Us_km_s=state[3], Up_km_s=state[4], **{f"{s}_last3ps": last[s] for s in last},
                         hcp_max=max(f["hcp"]), fcc_max=max(f["fcc"])))
with open(os.path.join(out, "nphug_scan.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(rows[0]))
    w.writeheader()
    for r in rows:
        w.writerow({k: (f"{v:.4f}" if isinstance(v, float) else v) for k, v in r.items()})
print("| potential | P (GPa) | V/V0 | T (K) | Us (km/s) | bcc | hcp | fcc | other | max hcp |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['potential']} | {r['P_GPa']:.1f} | {r['V_V0']:.3f} | {r['T_K']:.0f} | {r['Us_km_s']:.2f} | "
          f"{r['bcc_last3ps']:.3f} | {r['hcp_last3ps']:.3f} | {r['fcc_last3ps']:.3f} | {r['other_last3ps']:.3f} | {r['hcp_max']:.3f} |")

pots = sorted({r["potential"] for r in rows})
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
for pot in pots:
    rr = [r for r in rows if r["potential"] == pot]
    l, = axes[0].plot([r["P_GPa"] for r in rr], [r["hcp_last3ps"] + r["fcc_last3ps"] for r in rr], "o-", label=f"{pot}: hcp + fcc")
    axes[0].plot([r["P_GPa"] for r in rr], [r["bcc_last3ps"] for r in rr], "s--", color=l.get_color(), alpha=0.5, label=f"{pot}: bcc")
axes[0].set_xlabel("Hugoniostat $P_{zz}$ (GPa), [001]")
axes[0].set_ylabel("a-CNA fraction (mean of the last 3 ps)")
axes[0].axvline(13, color="k", lw=0.8, ls=":")
axes[0].text(13.5, 0.5, "α→ε in experiment, 13 GPa", rotation=90, fontsize=8, va="center")
axes[0].set_ylim(-0.03, 1.03)
axes[0].legend(fontsize=7)
axes[0].set_title("bcc Fe on its Hugoniot: does it transform?")
shown = "Fe_mm" if "Fe_mm" in pots else pots[0]
for (pot, p), (t, f) in series.items():
    if pot == shown:
        axes[1].plot(t, f["bcc"], label=f"{float(p[1:]) / 1e4:.0f} GPa")
axes[1].set_xlabel("time in the Hugoniostat (ps)")
axes[1].set_ylabel(f"a-CNA bcc fraction ({shown})")
axes[1].set_ylim(-0.03, 1.03)
axes[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(out, "nphug_scan.png"), dpi=110)
