#!/usr/bin/python3
"""The MSST shocks of examples/md_msst_cu against time: particle speed Up = Us(1 - V/V0), pressure
P_zz, V/V0 and temperature of the cell (thermo.csv of each run), with the piston's Hugoniot state
at the same shock speed (hugoniot_shock.toml of a piston run) as dashed lines.
Usage: /usr/bin/python3 plot_msst.py OUT.png PISTON_HUGONIOT_TOML RUN_DIR[=LABEL] [RUN_DIR[=LABEL] ...]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run, read_toml  # noqa: E402  (the shared run-folder readers)

AMU_A3_TO_G_CC = 1.66053904


def read_thermo(run):
    """The rows of thermo.csv written by the msst stage (msst_lagrangian_speed_A_ps a number)."""
    thermo = run.thermo
    return thermo[~np.isnan(thermo["msst_lagrangian_speed_A_ps"])]


def series(folder):
    run = Run.open(folder)
    rows = read_thermo(run)
    # The stage's first row (its start) belongs to the stage before, which wrote that step: the
    # stage starts one row interval before the first MSST row; V0 is the fix's (summary.json).
    t1, t2 = float(rows[0]["time_ps"]), float(rows[1]["time_ps"])
    t0 = t1 - (t2 - t1)
    v0 = run.summary["results"]["msst"][0]["v0_A3"]
    return {"t": [0.0] + [float(r["time_ps"]) - t0 for r in rows],
            "up_km_s": [0.0] + [0.1 * float(r["msst_lagrangian_speed_A_ps"]) for r in rows],
            "pressure_GPa": [float("nan")] + [1e-4 * float(r["pzz_bar"]) for r in rows],
            "vratio": [1.0] + [float(r["volume_A3"]) / v0 for r in rows],
            "temperature_K": [float("nan")] + [float(r["temperature_K"]) for r in rows]}


def main():
    out, piston_file = sys.argv[1], sys.argv[2]
    piston = read_toml(piston_file)
    fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    panels = [(axes[0, 0], "up_km_s", "Up (km/s)"), (axes[0, 1], "pressure_GPa", "P_zz (GPa)"),
              (axes[1, 0], "vratio", "V/V0"), (axes[1, 1], "temperature_K", "T (K)")]
    for k, arg in enumerate(sys.argv[3:]):
        run, _, label = arg.partition("=")
        s = series(run)
        for ax, key, _ in panels:
            ax.plot(s["t"], s[key], lw=1, color=f"C{k}", label=f"MSST, {label or run}")
    reference = dict(piston)
    if "density_g_cc" in piston and "density0_g_cc" in piston:
        reference["vratio"] = piston["density0_g_cc"] / piston["density_g_cc"]
    for ax, key, label in panels:
        if key in reference:
            ax.axhline(reference[key], color="k", ls="--", lw=1, label="piston, same Us")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7, loc="lower right")
    for ax in axes[1]:
        ax.set_xlabel("time in the msst stage (ps)")
    fig.suptitle("Cu [100], MSST at Us = 5.964 km/s (10,000 atoms) and the piston's state")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
