#!/usr/bin/python3
"""Detonation speed and structure of the reactive DBM runs of run.sh.

  detonation.py SPEED_RUN STRUCTURE_RUN --out detonation.png

Prints the fitted front speed D (least squares of series.csv front_x over the second half of each
run) against D_CJ from config.resolved.toml, the drift of E + Q*sum(rho*lambda), and Δ*_2xx at and
around the pressure peak of the last profile of STRUCTURE_RUN; plots the front x(t) and the last
profile around the peak (p, λ, Δ*_2xx, Δ*_(3,1)x).
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402  (the run-folder reader every plot uses; PYTHONPATH=python)


def derived(run, key):
    return Run.open(run).derived[key]


def speed(run):
    s = Run.open(run).series
    late = s["time"] >= 0.5 * s["time"][-1]
    slope, icpt = np.polyfit(s["time"][late], s["front_x"][late], 1)
    drift = s["total_energy_per_length"][-1] / s["total_energy_per_length"][0] - 1
    return s, slope, icpt, drift


def last_profile(run):
    frame = Run.open(run).last_frame(kind="profiles")
    return frame.data, frame.time


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("speed_run", type=pathlib.Path)
    ap.add_argument("structure_run", type=pathlib.Path)
    ap.add_argument("--out", type=pathlib.Path, required=True)
    a = ap.parse_args()
    d_cj = derived(a.speed_run, "cj_speed")
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for run, label in ((a.speed_run, "fast (k=200, Ea=2)"), (a.structure_run, "slow (k=1)")):
        s, slope, icpt, drift = speed(run)
        print(f"{run.name}: D = {slope:.5f}, D_CJ = {d_cj:.5f} ({100 * (slope / d_cj - 1):+.2f}%), "
              f"E + Q sum(rho lambda) drift {drift:.1e}")
        ax[0].plot(s["time"], s["front_x"], label=f"{label}: D = {slope:.4f}")
    t = np.linspace(0, ax[0].get_xlim()[1], 2)
    ax[0].plot(t, icpt + d_cj * t, "k--", lw=0.8, label=f"slope D_CJ = {d_cj:.4f}")
    ax[0].set(xlabel="t", ylabel="front x (p = (p0 + p_CJ)/2)", title="detonation front")
    ax[0].legend(fontsize=8)

    p, time = last_profile(a.structure_run)
    i = int(np.argmax(p["p"]))
    xi = p["x"] - p["x"][i]
    near = (xi > -1.2) & (xi < 0.2)
    print(f"{a.structure_run.name} t = {time:.3g}: peak p = {p['p'][i]:.4f} (p_vN = "
          f"{derived(a.structure_run, 'von_neumann_p'):.4f}) at x = {p['x'][i]:.3f}, lambda there {p['lambda'][i]:.3f}")
    p0 = p["p"][-1]  # fresh gas at the outflow end
    front = (xi > 0) & (p["p"] > p0 + 0.05 * (p["p"][i] - p0))
    behind = (xi > -0.6) & (xi < -0.05)
    print(f"  D*2xx: at the peak {p['D2xx'][i]:+.4f}, in front (shock) mean {p['D2xx'][front].mean():+.4f} "
          f"max {p['D2xx'][front].max():+.4f}, behind (0.05-0.6 behind the peak) mean {p['D2xx'][behind].mean():+.5f}")
    ax[1].plot(xi[near], p["p"][near], label="p")
    ax[1].plot(xi[near], p["rho"][near], label="rho")
    ax[1].plot(xi[near], p["lambda"][near], label="lambda")
    ax[1].axhline(derived(a.structure_run, "von_neumann_p"), color="grey", ls=":", lw=0.8, label="p_vN")
    ax[1].axhline(derived(a.structure_run, "cj_p"), color="grey", ls="--", lw=0.8, label="p_CJ")
    ax[1].set(xlabel="x - x(peak p)", title=f"slow case, t = {time:.2g}")
    ax[1].legend(fontsize=8)
    ax[2].plot(xi[near], p["D2xx"][near], label="Δ*_2xx")
    ax[2].plot(xi[near], p["D31x"][near], label="Δ*_(3,1)x")
    ax[2].axvline(0, color="grey", lw=0.8)
    ax[2].axhline(0, color="k", lw=0.5)
    ax[2].set(xlabel="x - x(peak p)", title="TNE around the von Neumann peak")
    ax[2].legend(fontsize=8, loc="lower right")
    inset = ax[2].inset_axes([0.08, 0.55, 0.4, 0.4])
    zoom = (xi > -1.0) & (xi < -0.02)
    inset.plot(xi[zoom], p["D2xx"][zoom])
    inset.axhline(0, color="k", lw=0.5)
    inset.set_title("behind the peak", fontsize=7)
    inset.tick_params(labelsize=6)
    fig.tight_layout()
    fig.savefig(a.out, dpi=90)


if __name__ == "__main__":
    main()
