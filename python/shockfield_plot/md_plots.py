#!/usr/bin/python3
"""Plots of an MD run folder written by `shockfield run` (`shockfield plot profiles|hugoniot`).

  python3 -m shockfield_plot.md_plots profiles RUN_DIR [--out FILE] [--axis z]
      binned shock profiles (velocity, pressure, temperature, density) at several times
  python3 -m shockfield_plot.md_plots hugoniot SWEEP_DIR [--out FILE] [--compare CSV]
      Us-Up points of `shockfield hugoniot` with their fit, the experimental line the sweep
      wrote into hugoniot_fit.toml (copper, Marsh 1980) and optionally a peer sweep (e.g. LAMMPS)

Reads the files through shockfield.run (Run, read_csv, read_toml). Uses only numpy and
matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.errors import InputError  # noqa: E402
from shockfield.run import Run, read_csv, read_toml  # noqa: E402


def plot_profiles(run, out, axis=None):
    """profiles.csv of the MD run folder `run` at six times; `axis` default the run's
    [output] profile_axis."""
    run = Run.open(run)
    axis = axis or run.config.get("output", {}).get("profile_axis", "z")
    p = run.table("profiles")
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
    fig.suptitle(run.title("shock profiles"))
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def plot_hugoniot(folder, out, compare=None):
    """hugoniot_sweep.csv (+ hugoniot_fit.toml's experimental line): Us against Up with
    standard errors."""
    sweep = os.path.join(folder, "hugoniot_sweep.csv")
    if not os.path.isfile(sweep):
        raise InputError(f"{folder}: no hugoniot_sweep.csv (the folder of `shockfield hugoniot`)")
    p = read_csv(sweep)
    fit_file = os.path.join(folder, "hugoniot_fit.toml")
    fit = read_toml(fit_file) if os.path.isfile(fit_file) else {}
    fig, ax = plt.subplots(figsize=(6, 4.5))
    up = np.linspace(0.0, 1.1 * max(p["up_km_s"]), 50)
    for table, line in fit.items():  # [experiment_<material>]: the sweep's reference line
        if table.startswith("experiment_") and isinstance(line, dict):
            c0, s = line["c0_km_s"], line["s"]
            ax.plot(up, c0 + s * up, "k--",
                    label=f"experiment, {table.removeprefix('experiment_')}: {c0:g} + {s:g} Up")
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
    ax.set_title(f"Hugoniot sweep {os.path.basename(os.path.abspath(folder))}", fontsize="medium")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["profiles", "hugoniot"])
    ap.add_argument("run")
    ap.add_argument("--out")
    ap.add_argument("--axis", choices=["x", "y", "z"])
    ap.add_argument("--compare", help="hugoniot: a peer sweep CSV (up_km_s, us_km_s, us_stderr_km_s)")
    a = ap.parse_args()
    out = a.out or os.path.join(a.run, f"{a.kind}.png")
    if a.kind == "profiles":
        plot_profiles(a.run, out, a.axis)
    else:
        plot_hugoniot(a.run, out, a.compare)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
