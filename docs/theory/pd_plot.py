#!/usr/bin/env python3
"""Plots the profiles written by tests/validation/pd_bar_waves.cpp (PdBarSlow.*):
  pd_elastic_30.png   30 m/s elastic wave, plain correspondence vs Riemann-corrected (Liu et al. 2025, Fig. 3)
  pd_front_width.png  300 m/s two-wave profiles for ΔX and δ (Liu et al. 2025, Fig. 4)
Usage: SHOCKFIELD_PD_OUT=/tmp/shockfield_pd test_validation --gtest_filter='PdBarSlow*'
       python3 docs/theory/pd_plot.py /tmp/shockfield_pd docs/theory"""
import csv
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r["x_m"]) * 1e3 for r in rows], [float(r["axial_compression_Pa"]) / 1e6 for r in rows]


src, dst = Path(sys.argv[1]), Path(sys.argv[2])
fig, ax = plt.subplots(figsize=(7, 3.5))
for name, label in (("elastic_30_plain.csv", "correspondence (eq. 11)"),
                    ("elastic_30_riemann.csv", "Riemann-corrected (eqs. 12-17)")):
    x, s = read(src / name)
    ax.plot(x, s, lw=1, label=label)
ax.axhline(265.56, color="k", ls="--", lw=0.8, label="ρ c_L u_p = 265.56 MPa")
ax.set_xlabel("x [mm]"), ax.set_ylabel("axial compression [MPa]")
ax.set_title("30 m/s impact, ΔX = 10 µm, δ = 3ΔX, t = 0.75 µs")
ax.set_xlim(5.5, 11.5), ax.legend(fontsize=8)
fig.tight_layout(), fig.savefig(dst / "pd_elastic_30.png", dpi=120)

fig, axes = plt.subplots(1, 2, figsize=(10, 3.5), sharey=True)
for dx in (20, 10, 5):
    x, s = read(src / f"elastic_plastic_dx{dx}um_m3.csv")
    axes[0].plot(x, s, lw=1, label=f"ΔX = {dx} µm")
for m in (1, 2, 3, 4):
    x, s = read(src / f"elastic_plastic_dx10um_m{m}.csv")
    axes[1].plot(x, s, lw=1, label=f"δ = {m}ΔX")
for a, title in zip(axes, ("δ = 3ΔX", "ΔX = 10 µm")):
    a.axhline(541.63, color="k", ls=":", lw=0.8), a.axhline(2269, color="k", ls="--", lw=0.8)
    a.set_xlim(19, 24), a.set_xlabel("x [mm]"), a.set_title(f"300 m/s, t = 1.5 µs, {title}"), a.legend(fontsize=8)
axes[0].set_ylabel("axial compression [MPa]")
fig.tight_layout(), fig.savefig(dst / "pd_front_width.png", dpi=120)
