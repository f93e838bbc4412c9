#!/usr/bin/python3
"""The MSST shock of examples/md_msst_cu against time: particle speed Up = Us(1 - V/V0), pressure
P_zz, density and temperature of the cell (thermo.csv of the run), with the piston's Hugoniot state
at the same shock speed (hugoniot_shock.toml of a piston run, or the numbers given) as bands.
Usage: /usr/bin/python3 plot_msst.py RUN_DIR OUT.png [PISTON_HUGONIOT_TOML]
"""
import csv
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

AMU_A3_TO_G_CC = 1.66053904


def read_thermo(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    rows = [r for r in rows if r["msst_lagrangian_speed_A_ps"] not in ("nan", "")]
    return rows


def main():
    run, out = sys.argv[1], sys.argv[2]
    rows = read_thermo(f"{run}/thermo.csv")
    t0 = float(rows[0]["time_ps"])
    t = [float(r["time_ps"]) - t0 for r in rows]
    up = [0.1 * float(r["msst_lagrangian_speed_A_ps"]) for r in rows]
    pzz = [1e-4 * float(r["pzz_bar"]) for r in rows]
    v0 = float(rows[0]["volume_A3"])
    temp = [float(r["temperature_K"]) for r in rows]
    vratio = [float(r["volume_A3"]) / v0 for r in rows]
    piston = None
    if len(sys.argv) > 3:
        with open(sys.argv[3], "rb") as f:
            piston = tomllib.load(f)
    fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    panels = [(axes[0, 0], up, "Up (km/s)", "up_km_s"), (axes[0, 1], pzz, "P_zz (GPa)", "pressure_GPa"),
              (axes[1, 0], vratio, "V/V0", None), (axes[1, 1], temp, "T (K)", "temperature_K")]
    for ax, y, label, key in panels:
        ax.plot(t, y, lw=1, label="MSST (shockfield)")
        if piston and key and key in piston:
            ax.axhline(piston[key], color="C3", ls="--", lw=1, label="piston, same Us")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    if piston and "density_g_cc" in piston and "density0_g_cc" in piston:
        axes[1, 0].axhline(piston["density0_g_cc"] / piston["density_g_cc"], color="C3", ls="--", lw=1,
                           label="piston, same Us")
    axes[0, 0].legend(fontsize=8)
    for ax in axes[1]:
        ax.set_xlabel("time in the msst stage (ps)")
    fig.suptitle("Cu [100], MSST at Us = 5.964 km/s (10,000 atoms)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
