"""The decelerating synthetic MD domain (R = 8 Å (t/2 ps)^0.465, a-CNA hcp atoms, equivalent sphere
of their atomic volume) beside the sharp-front run of the paper's law fitted to it
(bridge domain-growth --law paper, [model] kind = "sharp_front") -> paper_law.png; prints the fit
and the largest deviation of the run from the MD radii. The well-posed law's fit of the same
series (D < 0) was refused by the bridge (refused.txt).
usage: plot_paper.py RUNS. CHECK=1: exit 1 when the run leaves 3x the fit's rms residual."""
import os
import sys

import numpy as np

from growth_io import fitted, md_radius
from shockfield.run import Run  # the shared run-folder reader (growth_io puts it on the path)

runs = sys.argv[1]
tm, Rm = md_radius(f"{runs}/decelerating/analysis/tracks.csv")
fit, c0, c0_e, d, d_e = fitted(f"{runs}/paper.toml")
rms = fit["residual_rms_m"] * 1e10
tracks = Run.open(f"{runs}/sharp").table("tracks")
run = tracks[tracks["track"] == 1]
ts = tm[0] + run["time"]
Rs = run["L"]
dev = np.interp(tm, ts, Rs) - Rm
refused = open(f"{runs}/refused.txt").read()
d_ac = refused.split("fitted D = ")[1].split(" A^2/ps")[0] if "fitted D = " in refused else "?"
print(f"paper's law on the t^0.465 domain: c0 = {c0:.4f} +- {c0_e:.4f} A/ps, D = {d:.3f} +- {d_e:.3f} A^2/ps, "
      f"rms {rms:.4f} A; sharp-front run: largest |R_run - R_md| {np.abs(dev).max():.4f} A")

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(6.4, 4.4))
ax.plot(tm, Rm, "ko", label="synthetic MD (a-CNA hcp), R = 8 Å (t/2 ps)^0.465")
ax.plot(ts, Rs, "r-", label=f"sharp front, paper's law: c0 = {c0:.3f}±{c0_e:.3f} Å/ps, D = {d:.2f}±{d_e:.2f} Å²/ps")
tt = np.linspace(tm[0], tm[-1], 200)
ax.plot(tt, 8 * (tt / 2) ** 0.465, "k:", lw=1, label="t^0.465 (made with)")
ax.text(0.03, 0.97, f"well-posed field model (dR/dt = c0 − 2D/R):\nfitted D = {d_ac.replace(' +- ', ' ± ')} Å²/ps < 0, refused",
        transform=ax.transAxes, va="top", fontsize=8, color="b")
ax.set_xlabel("t (ps)")
ax.set_ylabel("equivalent radius R (Å)")
ax.set_title("decelerating hcp domain: dR/dt = c0 + 2D/R (Xu et al. 2015 eq 43; synthetic MD)", fontsize=9)
ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()
fig.savefig(f"{runs}/paper_law.png", dpi=110)
print(f"-> {runs}/paper_law.png")
if os.environ.get("CHECK") == "1":
    sys.exit(0 if np.abs(dev).max() <= 3 * rms and d > 0 else 1)
