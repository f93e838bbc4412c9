"""R(t) of the synthetic MD domain (adaptive-CNA hcp atoms, equivalent sphere of their atomic
volume), the law it was made with, the law the bridge fitted on t <= t_fit, and the phase-field
model run from the MD frame at t_fit (radius of its xi > 1/2 volume) -> compare.png; prints the
fitted c0 and D against the true ones and the largest deviation of the phase field from the MD.
usage: plot.py RUNS T_FIT TAU_PS. CHECK=1: exit 1 when a number leaves the bounds of README.md."""
import math
import os
import sys

import numpy as np

from growth_io import fitted, md_radius
from shockfield.run import Run  # the shared run-folder reader (growth_io puts it on the path)

C0, D = 1.0, 4.0  # the law generate.py used (Å/ps, Å²/ps)
runs, t_fit, tau = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])


def law(R0, c0, d, t):  # RK4 of dR/dt = c0 - 2D/R from R0 at t[0]
    out, R = [R0], R0
    for a, b in zip(t[:-1], t[1:]):
        h = (b - a) / 200
        for _ in range(200):
            f = lambda r: c0 - 2 * d / r
            k1 = f(R); k2 = f(R + h / 2 * k1); k3 = f(R + h / 2 * k2); k4 = f(R + h * k3)
            R += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out.append(R)
    return np.array(out)


tm, Rm = md_radius(f"{runs}/analysis/tracks.csv")
fit, c0, c0_e, d, d_e = fitted(f"{runs}/fe_pf.toml")
pf = Run.open(f"{runs}/pf")
n, dx = pf.config["grid"]["nodes"], pf.config["grid"]["spacing"]
tp = t_fit + tau * pf.series["time"]
Rp = np.cbrt(3 * pf.series["volume_fraction"] * np.prod(n) * dx**3 / (4 * math.pi))
later = tm > t_fit
dev = np.interp(tm[later], tp, Rp) / Rm[later] - 1
tt = np.linspace(0, tm[-1], 300)
print(f"fit on t <= {t_fit:g} ps: c0 = {c0:.3f} +- {c0_e:.3f} A/ps (true {C0}), D = {d:.3f} +- {d_e:.3f} A^2/ps (true {D})")
print(f"phase field from the {t_fit:g} ps frame: R {Rp[0]:.3f} A at the start (MD {Rm[tm == t_fit][0]:.3f}); "
      f"largest |R_pf/R_md - 1| at later frames {np.abs(dev).max():.4f}, at {tm[-1]:g} ps {dev[-1]:+.4f}")

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, ax = plt.subplots(figsize=(6.4, 4.4))
ax.plot(tm[~later], Rm[~later], "ko", label="synthetic MD (a-CNA hcp), fitted")
ax.plot(tm[later], Rm[later], "ko", mfc="none", label="synthetic MD, later")
ax.plot(tt, law(Rm[0], C0, D, tt), "k:", lw=1, label=f"made with: c0 = {C0:g} Å/ps, D = {D:g} Å²/ps")
ax.plot(tt, law(fit["R0_m"] * 1e10, c0, d, tt), "b--", lw=1, label=f"fitted: c0 = {c0:.2f}±{c0_e:.2f}, D = {d:.2f}±{d_e:.2f}")
ax.plot(tp, Rp, "r-", label="phase field from the MD frame")
ax.axvline(t_fit, color="grey", lw=0.5)
ax.set_xlabel("t (ps)")
ax.set_ylabel("equivalent radius R (Å)")
ax.set_title("hcp domain: dR/dt = c0 − 2D/R (synthetic MD, not Fe)", fontsize=10)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{runs}/compare.png", dpi=110)
print(f"-> {runs}/compare.png")
if os.environ.get("CHECK") == "1":
    ok = abs(c0 - C0) <= 2 * c0_e and abs(d - D) <= 2 * d_e and np.abs(dev).max() <= 0.06
    sys.exit(0 if ok else 1)
