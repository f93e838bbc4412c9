#!/usr/bin/python3
"""Plots of an MD run folder written by `shockfield run`.

  md_plots.py profiles RUN_DIR [--out FILE]   binned shock profiles (velocity, pressure,
                                              temperature, density) at several times
  md_plots.py thermo RUN_DIR [--out FILE]     thermo.csv columns against time
  md_plots.py hugoniot SWEEP_DIR [--out FILE] [--compare CSV]
                                              Us-Up points of `shockfield hugoniot` with their
                                              fit, the experimental copper line (Marsh 1980) and
                                              optionally a peer sweep (e.g. LAMMPS) to compare

Uses only numpy and matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        sys.exit(f"{path}: no data rows")
    header = rows[0]
    data = np.array([[float(x) for x in r] for r in rows[1:] if r], dtype=float)
    return {name: data[:, k] for k, name in enumerate(header)}


def plot_profiles(run, out, axis):
    path = os.path.join(run, "profiles.csv")
    if not os.path.exists(path):
        sys.exit(f"{path}: not found (set [output] profile_every > 0 in the case file)")
    p = read_csv(path)
    steps = np.unique(p["step"])
    chosen = steps[np.linspace(0, len(steps) - 1, min(6, len(steps))).round().astype(int)]
    vel = {"x": "vx_A_ps", "y": "vy_A_ps", "z": "vz_A_ps"}[axis]
    press = {"x": "pxx_GPa", "y": "pyy_GPa", "z": "pzz_GPa"}[axis]
    panels = [(vel, "particle velocity (km/s)", 0.1), (press, f"P_{axis}{axis} (GPa)", 1.0),
              ("temperature_K", "temperature (K)", 1.0), ("density_g_cc", "density (g/cm³)", 1.0)]
    fig, axes = plt.subplots(4, 1, figsize=(7, 10), sharex=True)
    cmap = plt.get_cmap("viridis")
    for n, step in enumerate(chosen):
        sel = (p["step"] == step) & (p["count"] > 0)
        t = p["time_ps"][sel][0]
        for ax, (col, label, scale) in zip(axes, panels):
            ax.plot(p["position_A"][sel], p[col][sel] * scale, color=cmap(n / max(len(chosen) - 1, 1)),
                    label=f"t = {t:.2f} ps")
            ax.set_ylabel(label)
    axes[0].legend(fontsize=8, loc="best")
    axes[-1].set_xlabel(f"position along {axis} (Å)")
    fig.suptitle(f"Shock profiles: {os.path.basename(os.path.abspath(run))}")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def plot_thermo(run, out):
    t = read_csv(os.path.join(run, "thermo.csv"))
    cols = [("temperature_K", "T (K)"), ("etotal_eV", "E total (eV)"), ("econserved_eV", "E conserved (eV)"),
            ("press_bar", "P (bar)")]
    fig, axes = plt.subplots(len(cols), 1, figsize=(7, 9), sharex=True)
    for ax, (col, label) in zip(axes, cols):
        ax.plot(t["time_ps"], t[col])
        ax.set_ylabel(label)
    axes[-1].set_xlabel("time (ps)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def plot_hugoniot(run, out, compare):
    """hugoniot_sweep.csv (+ hugoniot_fit.toml): Us against Up with standard errors."""
    p = read_csv(os.path.join(run, "hugoniot_sweep.csv"))
    fig, ax = plt.subplots(figsize=(6, 4.5))
    up = np.linspace(0.0, 1.1 * max(p["up_km_s"]), 50)
    ax.plot(up, 3.940 + 1.489 * up, "k--", label="experiment: 3.94 + 1.489 Up (Marsh 1980)")
    ax.errorbar(p["up_km_s"], p["us_km_s"], yerr=p["us_stderr_km_s"], fmt="o", color="C0", label="shockfield")
    if len(p["up_km_s"]) > 1:
        s, c0 = np.polyfit(p["up_km_s"], p["us_km_s"], 1)
        ax.plot(up, c0 + s * up, color="C0", label=f"fit: {c0:.2f} + {s:.3f} Up")
    if compare:
        q = read_csv(compare)
        ax.errorbar(q["up_km_s"], q["us_km_s"], yerr=q["us_stderr_km_s"], fmt="s", mfc="none", color="C3",
                    label=os.path.basename(compare))
    ax.set_xlabel("particle velocity Up (km/s)")
    ax.set_ylabel("shock velocity Us (km/s)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["profiles", "thermo", "hugoniot"])
    ap.add_argument("run")
    ap.add_argument("--out")
    ap.add_argument("--axis", default="z", choices=["x", "y", "z"])
    ap.add_argument("--compare", help="hugoniot: a peer sweep CSV (up_km_s, us_km_s, us_stderr_km_s)")
    a = ap.parse_args()
    out = a.out or os.path.join(a.run, f"{a.kind}.png")
    if a.kind == "profiles":
        plot_profiles(a.run, out, a.axis)
    elif a.kind == "hugoniot":
        plot_hugoniot(a.run, out, a.compare)
    else:
        plot_thermo(a.run, out)


if __name__ == "__main__":
    main()
