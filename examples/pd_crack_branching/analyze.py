#!/usr/bin/python3
"""Crack tip, crack speed and branching of a pd_crack_branching run (README.md).

The crack is the set of points with damage >= 0.3: the first row of points on each face of a
straight crack has lost 1/3, 0.39 and 0.42 of its bonds at m = δ/ΔX = 2, 3 and 4, the second row
0.08, 0.21 and 0.27 (measured on the notch of the convergence runs), so 0.3 takes the faces alone
at every m studied. Its tip at each profile is the largest x of a crack point beyond the
notch; the crack speed is the least-squares slope of the tip position over the frames where it
runs (from 1 mm past the notch until 5 mm before the right edge). The crack has branched at a
column x when the crack points of that column form two or more runs of rows separated by at
least two horizons of undamaged rows; the branching point is the first such column.

    analyze.py RUN_DIR --notch 0.05 --horizon 1.5e-3 [--plot out.png] [--check-branching] [--check-symmetry]

The plate and its loads are mirror-symmetric about the notch line (the lattice is offset by ΔX/2,
[body] origin, so no row of points lies on it), so the solution is too: --check-symmetry fails
unless at every profile the damage at (x, y) and (x, y_mid − (y − y_mid)) differ by at most
SYMMETRY_DAMAGE and v_y is antisymmetric (v_x symmetric) within SYMMETRY_VELOCITY of its largest
magnitude. Mirrored points sum their bond forces in different orders, so they differ by round-off
(1e-9 of the velocity measured: the profiles' 10 significant digits); a bond that round-off tips
over its critical stretch one step early would change one point's damage by one bond of its ~28,
0.036, which SYMMETRY_DAMAGE allows once (the runs here show none).

Prints the speed against the Rayleigh speed of the 2D PMB glass (plane stress fixes ν = 1/3;
E = 72 GPa, ρ = 2440 kg/m³: c_R = c_s (0.862 + 1.14ν)/(1 + ν), Viktorov's fit). --check: exit 1
unless the crack ran past the notch below c_R; --check-branching also needs a branch.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

E, RHO, NU = 72e9, 2440.0, 1.0 / 3.0
C_S = math.sqrt(E / (2.0 * (1.0 + NU)) / RHO)
C_R = C_S * (0.862 + 1.14 * NU) / (1.0 + NU)
CRACK_DAMAGE = 0.3
SYMMETRY_DAMAGE = 0.04
SYMMETRY_VELOCITY = 1e-6


def frames(run):
    """(time, profile) of each profile of the run (profiles/index.csv), in time order."""
    for profile in Run.open(run).frames(kind="profiles"):
        yield profile.time, profile.data


def branch_runs(x, y, crack, column, gap):
    """Runs of crack rows in the column nearest `column`, split where undamaged rows span > gap."""
    at = np.isclose(x, column, atol=1e-9) & crack
    ys = np.sort(y[at])
    if ys.size == 0:
        return 0
    return 1 + int(np.count_nonzero(np.diff(ys) > gap))


def mirror_of(d):
    """Index of each point's mirror image about the plate's mid-line (the profiles hold reference
    positions, in the same order at every frame)."""
    x, y = d["x_m"], d["y_m"]
    grid = max(np.min(np.diff(np.unique(y))), 1e-300)
    ix, iy = np.rint(x / grid).astype(np.int64), np.rint(y / grid).astype(np.int64)
    code = ix * (1 << 32) + iy
    order = np.argsort(code)
    mirrored = ix * (1 << 32) + (iy.min() + iy.max() - iy)
    at = np.searchsorted(code[order], mirrored)
    if np.any(at >= code.size) or np.any(code[order][np.minimum(at, code.size - 1)] != mirrored):
        sys.exit("the points are not mirror-symmetric about the plate's mid-line")
    return order[at]


def asymmetry(d, mirror):
    """Largest |D − D_mirror| and the largest mirror defects of v_x and v_y relative to max |v|."""
    speed = max(np.abs(d["vx_m_s"]).max(), np.abs(d["vy_m_s"]).max(), 1e-300)
    return (np.abs(d["damage"] - d["damage"][mirror]).max(),
            np.abs(d["vx_m_s"] - d["vx_m_s"][mirror]).max() / speed,
            np.abs(d["vy_m_s"] + d["vy_m_s"][mirror]).max() / speed)


class Crack:
    """The crack of a run: tip against time, speed while it runs, first branching column, last frame."""

    def __init__(self, run, notch, horizon, symmetry=False):
        times, tips, self.asymmetry, mirror = [], [], np.zeros(3), None
        for t, d in frames(run):
            if symmetry:
                mirror = mirror_of(d) if mirror is None else mirror
                self.asymmetry = np.maximum(self.asymmetry, asymmetry(d, mirror))
            crack = d["damage"] >= CRACK_DAMAGE
            times.append(t), tips.append(d["x_m"][crack].max() if crack.any() else 0.0)
            self.last = d
        self.times, self.tips = np.array(times), np.array(tips)
        width = self.last["x_m"].max()
        self.running = (self.tips > notch + 1e-3) & (self.tips < width - 5e-3)
        r = self.running
        self.speed = np.polyfit(self.times[r], self.tips[r], 1)[0] if r.sum() >= 3 else float("nan")
        x, y, crack = self.last["x_m"], self.last["y_m"], self.last["damage"] >= CRACK_DAMAGE
        branched = [c for c in np.unique(x[x > notch]) if branch_runs(x, y, crack, c, 2.0 * horizon) >= 2]
        self.branch_x = branched[0] if branched else float("nan")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("run")
    p.add_argument("--notch", type=float, required=True)
    p.add_argument("--horizon", type=float, required=True)
    p.add_argument("--plot")
    p.add_argument("--check", action="store_true")
    p.add_argument("--check-branching", action="store_true")
    p.add_argument("--check-symmetry", action="store_true")
    a = p.parse_args()
    c = Crack(a.run, a.notch, a.horizon, a.check_symmetry)
    times, tips, running, speed, last, worst = c.times, c.tips, c.running, c.speed, c.last, c.asymmetry
    branched = not math.isnan(c.branch_x)
    x, y, width = last["x_m"], last["y_m"], last["x_m"].max()
    print(f"crack tip {tips[-1] * 1e3:.1f} mm at t = {times[-1] * 1e6:.1f} us; speed {speed:.0f} m/s over "
          f"{running.sum()} frames = {speed / C_R:.2f} of the Rayleigh speed {C_R:.0f} m/s")
    print(f"branches: {'first two branches at x = %.1f mm' % (c.branch_x * 1e3) if branched else 'none'}")
    if a.check_symmetry:
        print(f"mirror defects over all profiles: damage {worst[0]:.3g}, v_x {worst[1]:.2e}, v_y {worst[2]:.2e} "
              f"of max |v|")
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
    if a.check_symmetry and not (worst[0] <= SYMMETRY_DAMAGE and max(worst[1], worst[2]) <= SYMMETRY_VELOCITY):
        print(f"check failed: the solution is not mirror-symmetric about the notch line (damage within "
              f"{SYMMETRY_DAMAGE}, velocities within {SYMMETRY_VELOCITY:g} of max |v|)")
        sys.exit(1)


if __name__ == "__main__":
    main()
