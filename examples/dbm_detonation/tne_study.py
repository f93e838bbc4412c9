#!/usr/bin/python3
"""Local and global TNE of the detonation against the relaxation time τ (tne_study.sh's sweeps).

  tne_study.py RUNS --table tne_table.md --out tne_viscosity.png

RUNS holds the sweeps of tne_study.sh: RUNS/tau (τ swept at Δx = 0.0025) and RUNS/dx<Δx> (the same
case at other grids). From the last profile of every run (t = 2) it measures, with x measured from
the pressure peak (+ toward the fresh gas):
  - the shock width δ = (p_peak − p0) / max|dp/dx| and the cells it spans, δ/Δx;
  - where Δ*_2xx changes sign: coming back from its maximum in the shock toward the burnt gas, the
    first zero (linear interpolation), in cells and in shock widths from the peak;
  - local TNE: the largest Δ*_2xx (in the shock), also per pressure jump p_peak − p0, and
    |Δ*_2xx| at the pressure peak;
  - global TNE: ∫|Δ*_2xx| dx and ∫|Δ*_(3,1)x| dx over the wave (from 0.6 behind the peak, most
    of the reaction zone of ≈ 0.7, to the fresh gas), and ∫D dx over the box (the series' mean D × length,
    D of Xu et al. (2015) eq. 35).
Writes the two tables (markdown) and a figure: the Δ*_2xx profiles, local and global TNE against τ.
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402  (PYTHONPATH=python)

# How far behind the pressure peak the global TNE integrates: most of the reaction zone (≈ 0.7).
# Farther back, 0.6-1.0 behind the peak, Δ*_2xx (≈ −0.002) carries grid-scale noise that grows
# with refinement (±0.008 at Δx = 0.0025, ±0.02 at 0.00125 for τ = 0.005; the short-wave
# instability the stability check flags, tne.toml) and would make ∫|Δ*| dx grow with the grid.
WAVE_BEHIND = 0.6


def measure(folder):
    """The TNE measures of one run's last profile (see the module docstring)."""
    run = Run.open(folder)
    frame = run.last_frame(kind="profiles")
    end = run.value("end_time")
    if abs(frame.time - end) > 1e-6 * end:
        raise SystemExit(f"{folder}: its last profile is at t = {frame.time}, not at end_time = {end}")
    p = frame.data
    x, pressure, d2, d31 = p["x"], p["p"], p["D2xx"], p["D31x"]
    dx = x[1] - x[0]
    peak = int(np.argmax(pressure))
    p0 = pressure[-1]  # fresh gas at the outflow end
    width = (pressure[peak] - p0) / (np.max(-np.diff(pressure[peak:])) / dx)
    top = int(np.argmax(d2))  # Δ*_2xx maximum, in the shock ahead of the peak
    j = top
    while d2[j] > 0:
        j -= 1
    x_zero = x[j] + dx * d2[j] / (d2[j] - d2[j + 1])
    wave = (x > x[peak] - WAVE_BEHIND)
    series = run.series
    return {
        "tau": run.value("tau"), "dx": dx, "time": frame.time, "p_peak": pressure[peak],
        "lambda_peak": p["lambda"][peak], "width": width, "width_cells": width / dx,
        "zero_cells": (x_zero - x[peak]) / dx, "zero_widths": (x_zero - x[peak]) / width,
        "d2_max": d2[top], "d2_peak": d2[peak], "d2_max_per_jump": d2[top] / (pressure[peak] - p0),
        "global_d2": np.sum(np.abs(d2[wave])) * dx, "global_d31": np.sum(np.abs(d31[wave])) * dx,
        "global_D_box": series["D"][-1] * len(x) * dx,
        "profile": (x - x[peak], d2),
    }


def runs_of(sweep):
    return sorted((measure(f) for f in sweep.iterdir() if (f / "config.resolved.toml").is_file()),
                  key=lambda m: m["tau"])


def tau_table(rows):
    out = ["| τ | δ (cells) | p peak | λ at peak | local: max Δ*_2xx | max Δ*_2xx / (p_peak − p0) | "
           "local: Δ*_2xx at peak | "
           "global: ∫\\|Δ*_2xx\\| dx | global: ∫\\|Δ*_(3,1)x\\| dx | global: ∫D dx (box) |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for m in rows:
        out.append(f"| {m['tau']:g} | {m['width_cells']:.1f} | {m['p_peak']:.4f} | {m['lambda_peak']:.3f} | "
                   f"{m['d2_max']:.4f} | {m['d2_max_per_jump']:.4f} | {m['d2_peak']:+.4f} | {m['global_d2']:.5f} | {m['global_d31']:.5f} | "
                   f"{m['global_D_box']:.4f} |")
    return out


def grid_table(rows):
    out = ["| τ | Δx | δ | δ (cells) | Δ*_2xx = 0: cells from the peak | in shock widths | Δ*_2xx at peak | "
           "max Δ*_2xx | ∫\\|Δ*_2xx\\| dx |", "|---|---|---|---|---|---|---|---|---|"]
    for m in sorted(rows, key=lambda m: (m["tau"], -m["dx"])):
        out.append(f"| {m['tau']:g} | {m['dx']:g} | {m['width']:.4f} | {m['width_cells']:.1f} | "
                   f"{m['zero_cells']:+.2f} | {m['zero_widths']:+.3f} | {m['d2_peak']:+.4f} | {m['d2_max']:.4f} | "
                   f"{m['global_d2']:.5f} |")
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", type=pathlib.Path)
    ap.add_argument("--table", type=pathlib.Path, required=True)
    ap.add_argument("--out", type=pathlib.Path, required=True)
    a = ap.parse_args()
    trend = runs_of(a.runs / "tau")
    grids = [m for sweep in sorted(a.runs.glob("dx*")) for m in runs_of(sweep)]
    grids += [m for m in trend if any(abs(m["tau"] - g["tau"]) < 1e-12 for g in grids)]
    lines = [f"TNE of the detonation at t = {trend[0]['time']:g} against τ (Δx = {trend[0]['dx']:g}; "
             "+ is toward the fresh gas):", ""] + tau_table(trend)
    lines += ["", "The sign change of Δ*_2xx against the grid:", ""] + grid_table(grids)
    a.table.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for m in trend:
        xi, d2 = m["profile"]
        near = (xi > -0.5) & (xi < 0.7)
        ax[0].plot(xi[near], d2[near], label=f"τ = {m['tau']:g}")
    ax[0].axvline(0, color="grey", lw=0.8)
    ax[0].axhline(0, color="k", lw=0.5)
    ax[0].set(xlabel="x − x(peak p)", ylabel="Δ*_2xx", title=f"Δx = {trend[0]['dx']:g}, t = {trend[0]['time']:g}")
    ax[0].legend(fontsize=8)
    taus = [m["tau"] for m in trend]
    ax[1].plot(taus, [m["d2_max"] for m in trend], "o-", label="max Δ*_2xx (shock)")
    ax[1].plot(taus, [m["d2_max_per_jump"] for m in trend], "^-", label="max Δ*_2xx / (p_peak − p0)")
    ax[1].plot(taus, [abs(m["d2_peak"]) for m in trend], "s-", label="|Δ*_2xx| at the p peak")
    ax[1].set(xscale="log", xlabel="τ (μ = pτ, κ ∝ pτ)", title="local TNE")
    ax[1].set_xticks(taus, [f"{t:g}" for t in taus])
    ax[1].minorticks_off()
    ax[1].legend(fontsize=8)
    ax[2].plot(taus, [m["global_d2"] for m in trend], "o-", label="∫|Δ*_2xx| dx (wave)")
    ax[2].plot(taus, [m["global_d31"] for m in trend], "s-", label="∫|Δ*_(3,1)x| dx (wave)")
    ax[2].plot(taus, [m["global_D_box"] for m in trend], "^-", label="∫D dx (box)")
    ax[2].set(xscale="log", yscale="log", xlabel="τ", title="global TNE")
    ax[2].set_xticks(taus, [f"{t:g}" for t in taus])
    ax[2].minorticks_off()
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=90)


if __name__ == "__main__":
    main()
