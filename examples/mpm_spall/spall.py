#!/usr/bin/python3
"""Flyer-plate spall runs (examples/mpm_spall): free-surface velocity, pull-back, damage.

  spall.py RUN_WITH_SPALL RUN_WITHOUT [--out spall.png] [--csv spall.csv]

Free-surface velocity u_fs: series.csv `top_h10um_vy_mean_m_s` (the 10 µm below the highest particle).
Plateau: the median of u_fs over the 60 ns after it first exceeds 90 % of its largest value;
pull-back Δu_fs: from the plateau to the first minimum after u_fs falls 15 % below it (the plateau
rings by ±7 %); spall strength from the acoustic approximation σ = ½·ρ0·c0·Δu_fs (Antoun et al.,
Spall Fracture, 2003, §2.2). The damaged zone and the density along y come from the last particle frame.
Uses numpy and matplotlib from Debian (/usr/bin/python3) and the run-folder reader shockfield.run.Run.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402

RHO0, C0 = 2700.0, 5350.0  # aluminium_seed000


def pullback(t, u):
    k = int(np.argmax(u > 0.9 * u.max()))
    plateau = float(np.median(u[(t >= t[k]) & (t <= t[k] + 60e-9)]))
    m = k
    while m + 1 < len(u) and u[m] > 0.85 * plateau:
        m += 1
    while m + 1 < len(u) and u[m + 1] <= u[m]:
        m += 1
    return plateau, float(u[m]), float(t[m])


def last_frame(run):
    frame = Run.open(run).last_frame(kind="particles")
    return frame.time, frame.data


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("spall")
    ap.add_argument("no_spall")
    ap.add_argument("--out", default="spall.png")
    ap.add_argument("--csv", default=None)
    a = ap.parse_args()

    fig, axes = plt.subplots(1, 3, figsize=(13, 4.6), gridspec_kw={"width_ratios": [2.2, 0.7, 1.4]})
    rows = []
    for run, style in ((a.spall, "-"), (a.no_spall, "--")):
        s = Run.open(run).series
        t, u = s["time_s"], s["top_h10um_vy_mean_m_s"]
        plateau, low, t_low = pullback(t, u)
        sigma = 0.5 * RHO0 * C0 * (plateau - low)
        name = os.path.basename(os.path.normpath(run))
        f_t, f = last_frame(run)
        dmg = f["damage"] > 0
        y = f["points"][:, 1]
        zone = (y[dmg].min(), y[dmg].max()) if dmg.any() else (np.nan, np.nan)
        rows.append(dict(run=name, plateau=plateau, minimum=low, t_min=t_low, pullback=plateau - low, sigma=sigma,
                         damaged=int(dmg.sum()), zone_lo=zone[0], zone_hi=zone[1], top=y.max()))
        print(f"{name}: plateau {plateau:.1f} m/s, first minimum {low:.1f} m/s at {t_low * 1e9:.0f} ns, "
              f"pull-back {plateau - low:.1f} m/s -> ½ρ0c0Δu = {sigma / 1e9:.3f} GPa; "
              f"{dmg.sum()} failed particles, y in [{zone[0] * 1e3:.3f}, {zone[1] * 1e3:.3f}] mm, "
              f"top {y.max() * 1e3:.3f} mm at {f_t * 1e9:.0f} ns")
        axes[0].plot(t * 1e9, u, style, label=f"{name}: Δu_fs = {plateau - low:.0f} m/s → {sigma / 1e9:.2f} GPa")
        if run == a.spall:
            axes[0].plot([t_low * 1e9], [low], "ko", ms=4)
            p = f["points"] * 1e3
            sc = axes[1].scatter(p[:, 0], p[:, 1], c=f["damage"], s=2, cmap="Reds", vmin=0, vmax=1, rasterized=True)
            axes[1].set_title(f"damage at {f_t * 1e9:.0f} ns", fontsize="small")
            axes[1].set_xlabel("x (mm)")
            axes[1].set_ylabel("y (mm)")
            fig.colorbar(sc, ax=axes[1], shrink=0.6)
        order = np.argsort(y)
        axes[2].plot(y[order] * 1e3, f["density"][order], style, lw=0.8, label=f"{name} at {f_t * 1e9:.0f} ns")
    axes[0].set_xlabel("t (ns)")
    axes[0].set_ylabel("free-surface velocity (m/s)")
    axes[0].set_title("300 m/s Al flyer (0.5 mm) on Al target (1.5 mm), σ_sp = 1 GPa", fontsize="small")
    axes[0].legend(fontsize="x-small", loc="lower center")
    axes[2].set_xlabel("y (mm)")
    axes[2].set_ylabel("particle density (kg/m³)")
    axes[2].set_title("density along the strip", fontsize="small")
    axes[2].legend(fontsize="x-small")
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    if a.csv:
        with open(a.csv, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(rows[0]))
            w.writeheader()
            for r in rows:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
