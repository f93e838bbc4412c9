#!/usr/bin/python3
"""Crack tip, crack speed and branching of a pd_crack_branching run (README.md).

The crack is the set of points with damage >= 0.35 (a point that has lost over a third of its
bonds: on the crack faces). Its tip at each profile is the largest x of a crack point beyond the
notch; the crack speed is the least-squares slope of the tip position over the frames where it
runs (from 1 mm past the notch until 5 mm before the right edge). The crack has branched at a
column x when the crack points of that column form two or more runs of rows separated by at
least two horizons of undamaged rows; the branching point is the first such column.

    analyze.py RUN_DIR --notch 0.05 --horizon 1.5e-3 [--plot out.png] [--check-branching]

Prints the speed against the Rayleigh speed of the 2D PMB glass (plane stress fixes ν = 1/3;
E = 72 GPa, ρ = 2440 kg/m³: c_R = c_s (0.862 + 1.14ν)/(1 + ν), Viktorov's fit). --check: exit 1
unless the crack ran past the notch below c_R; --check-branching also needs a branch.
"""
import argparse
import csv
import math
import sys

import numpy as np

E, RHO, NU = 72e9, 2440.0, 1.0 / 3.0
C_S = math.sqrt(E / (2.0 * (1.0 + NU)) / RHO)
C_R = C_S * (0.862 + 1.14 * NU) / (1.0 + NU)
CRACK_DAMAGE = 0.35


def frames(run):
    with open(f"{run}/profiles/index.csv") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        d = np.genfromtxt(f"{run}/profiles/profile_{row['profile']}.csv", delimiter=",", names=True)
        yield float(row["time_s"]), d


def branch_runs(x, y, crack, column, gap):
    """Runs of crack rows in the column nearest `column`, split where undamaged rows span > gap."""
    at = np.isclose(x, column, atol=1e-9) & crack
    ys = np.sort(y[at])
    if ys.size == 0:
        return 0
    return 1 + int(np.count_nonzero(np.diff(ys) > gap))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("run")
    p.add_argument("--notch", type=float, required=True)
    p.add_argument("--horizon", type=float, required=True)
    p.add_argument("--plot")
    p.add_argument("--check", action="store_true")
    p.add_argument("--check-branching", action="store_true")
    a = p.parse_args()
    times, tips, last = [], [], None
    for t, d in frames(a.run):
        crack = d["damage"] >= CRACK_DAMAGE
        tip = d["x_m"][crack].max() if crack.any() else 0.0
        times.append(t), tips.append(tip)
        last = d
    times, tips = np.array(times), np.array(tips)
    width = last["x_m"].max()
    running = (tips > a.notch + 1e-3) & (tips < width - 5e-3)
    speed = np.polyfit(times[running], tips[running], 1)[0] if running.sum() >= 3 else float("nan")
    x, y, crack = last["x_m"], last["y_m"], last["damage"] >= CRACK_DAMAGE
    columns = np.unique(x[x > a.notch])
    branched = [c for c in columns if branch_runs(x, y, crack, c, 2.0 * a.horizon) >= 2]
    branch_x = branched[0] if branched else float("nan")
    print(f"crack tip {tips[-1] * 1e3:.1f} mm at t = {times[-1] * 1e6:.1f} us; speed {speed:.0f} m/s over "
          f"{running.sum()} frames = {speed / C_R:.2f} of the Rayleigh speed {C_R:.0f} m/s")
    print(f"branches: {'first two branches at x = %.1f mm' % (branch_x * 1e3) if branched else 'none'}")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 3.6), gridspec_kw={"width_ratios": [2.2, 1]})
        sc = ax0.scatter(x * 1e3, y * 1e3, c=last["damage"], s=2, cmap="viridis", vmin=0, vmax=0.5)
        ax0.set_aspect("equal")
        ax0.set_xlabel("x (mm)"), ax0.set_ylabel("y (mm)")
        ax0.set_title(f"damage at t = {times[-1] * 1e6:.0f} µs")
        fig.colorbar(sc, ax=ax0, shrink=0.8)
        ax1.plot(times * 1e6, tips * 1e3, "o-", ms=3, label=f"tip: {speed:.0f} m/s")
        t0 = times[running][0] if running.any() else 0.0
        x0 = tips[running][0] if running.any() else a.notch
        ax1.plot(times * 1e6, x0 * 1e3 + C_R * (times - t0) * 1e3, "--", label=f"Rayleigh {C_R:.0f} m/s")
        ax1.set_ylim(a.notch * 1e3 - 2, width * 1e3 + 2)
        ax1.set_xlabel("t (µs)"), ax1.set_ylabel("crack tip x (mm)")
        ax1.legend(loc="upper left", fontsize=8)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)
    if a.check or a.check_branching:
        ok = running.sum() >= 3 and 0.0 < speed < C_R and (branched or not a.check_branching)
        if not ok:
            print("check failed: the crack must run past the notch below the Rayleigh speed"
                  + (" and branch" if a.check_branching else ""))
            sys.exit(1)


if __name__ == "__main__":
    main()
