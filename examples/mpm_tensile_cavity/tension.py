#!/usr/bin/python3
"""Tensile single-cavity runs (examples/mpm_tensile_cavity): cavity area measured on the particle
frames, where the tension is highest, and a picture of the pressure field.

  tension.py RUN [RUN ...] [--times T ...] [--out pressure.png] [--csv cavity_area.csv]

For every particle frame (particles.pvd) of every run:
  - cavity area: the run's own tracker (series.csv `cavity_size_m2`, each particle covering its
    deformed domain F·box) and, as a cross-check, a measurement on the frame: a raster of
    0.0625 µm cells over the block, each particle covering the cells within its square of
    half-width (spacing/2)·(ρ0/ρ)^(1/2) (its current area, but not its shape, which the frames do
    not carry); the cavity is the uncovered component containing the last cavity centroid
    (periodic in x), not touching the raster's top or bottom rows.
  - highest tension: the lowest particle pressure (−tr σ/3) and where it sits relative to the
    cavity (the 0.5 % most negative particles: their mean |x − x_c| and mean y − y_c).
The picture has one row per run: particle pressure at --times, and the cavity area against time.
Uses numpy, scipy and matplotlib from Debian (/usr/bin/python3) and the run-folder reader shockfield.run.Run.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy import ndimage  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402

RHO0, SPACING, WIDTH, CELL = 2700.0, 0.25e-6, 40e-6, 0.0625e-6




def cavity_area(f, centre):
    p = f["points"][:, :2]
    a = 0.5 * SPACING * np.sqrt(RHO0 / f["density"])
    nx = int(round(WIDTH / CELL))
    ny = int(np.ceil((p[:, 1].max() + SPACING) / CELL)) + 2
    covered = np.zeros((ny, nx), dtype=bool)
    for x, y, h in zip(p[:, 0], p[:, 1], a):
        i0, i1 = int(np.ceil((x - h) / CELL - 0.5)), int(np.floor((x + h) / CELL - 0.5))
        j0, j1 = max(0, int(np.ceil((y - h) / CELL - 0.5))), min(ny - 1, int(np.floor((y + h) / CELL - 0.5)))
        if j0 > j1 or i0 > i1:
            continue
        covered[j0:j1 + 1, np.arange(i0, i1 + 1) % nx] = True
    labels, _ = ndimage.label(~covered)
    # periodic in x: merge components that meet across x = 0 / x = W
    for j in range(ny):
        l, r = labels[j, 0], labels[j, -1]
        if l and r and l != r:
            labels[labels == r] = l
    ci, cj = int(centre[0] / CELL), int(centre[1] / CELL)
    lab = labels[cj, ci]
    if lab == 0:  # centroid covered: take the nearest uncovered cell within 2 µm
        jj, ii = np.nonzero(labels[max(0, cj - 32):cj + 33, max(0, ci - 32):ci + 33])
        if len(jj) == 0:
            return 0.0, centre
        k = np.argmin((jj - min(32, cj)) ** 2 + (ii - min(32, ci)) ** 2)
        lab = labels[max(0, cj - 32) + jj[k], max(0, ci - 32) + ii[k]]
    cells = labels == lab
    if cells[0].any() or cells[-1].any():
        return float("nan"), centre  # open to the wall or above the top: not a closed cavity
    jj, ii = np.nonzero(cells)
    return cells.sum() * CELL ** 2, np.array([(ii.mean() + 0.5) * CELL, (jj.mean() + 0.5) * CELL])


def analyse(run):
    s = Run.open(run).series
    centre = np.array([WIDTH / 2, 20e-6])
    rows = []
    for frame in Run.open(run).frames(kind="particles"):
        t, f = frame.time, frame.data
        area, centre = cavity_area(f, centre)
        k = np.argmin(np.abs(s["time_s"] - t))
        pr = f["pressure"]
        low = pr <= np.percentile(pr, 0.5)
        q = f["points"][low, :2]
        rows.append(dict(t=t, area=area, tracker=s["cavity_size_m2"][k], pmin=pr.min(), low=q,
                         dx=np.abs(q[:, 0] - centre[0]).mean(), dy=(q[:, 1] - centre[1]).mean(),
                         f=f, centre=centre.copy()))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--times", type=float, nargs="+", default=[4e-9, 8e-9])
    ap.add_argument("--out", default="pressure.png")
    ap.add_argument("--csv", default=None)
    a = ap.parse_args()
    results = {os.path.basename(os.path.normpath(r)): analyse(r) for r in a.runs}

    table = []
    for name, rows in results.items():
        a0 = rows[0]["tracker"]
        print(f"{name}: t (ns), tracker area (µm²), Φ, frame area (µm²), min pressure (MPa), "
              "0.5 % most negative particles mean |x − x_c| and y − y_c (µm)")
        for r in rows:
            phi = (a0 - r["tracker"]) / a0
            print(f"  {r['t'] * 1e9:5.1f} {r['tracker'] * 1e12:8.2f} {phi:+7.3f} {r['area'] * 1e12:8.2f} "
                  f"{r['pmin'] / 1e6:9.0f} {r['dx'] * 1e6:+6.1f} {r['dy'] * 1e6:+6.1f}")
            table.append([name, f"{r['t']:.3g}", f"{r['tracker']:.5g}", f"{phi:.4f}", f"{r['area']:.5g}",
                          f"{r['pmin']:.4g}", f"{r['dx']:.3g}", f"{r['dy']:.3g}"])
    if a.csv:
        with open(a.csv, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["run", "time_s", "tracker_area_m2", "collapsibility", "frame_area_m2", "min_pressure_Pa",
                        "tension_abs_dx_m", "tension_dy_m"])
            w.writerows(table)

    n = len(a.times) + 1
    fig, axes = plt.subplots(len(results), n, figsize=(3.6 * n, 4.2 * len(results)), squeeze=False)
    for row, (name, rows) in zip(axes, results.items()):
        for ax, t in zip(row, a.times):
            r = min(rows, key=lambda q: abs(q["t"] - t))
            p = r["f"]["points"] * 1e6
            lim = max(50.0, np.percentile(np.abs(r["f"]["pressure"]), 99) / 1e6)
            sc = ax.scatter(p[:, 0], p[:, 1], c=r["f"]["pressure"] / 1e6, s=0.2, cmap="coolwarm",
                            vmin=-lim, vmax=lim, rasterized=True)
            ax.plot(r["low"][:, 0] * 1e6, r["low"][:, 1] * 1e6, "k.", ms=1.5)
            ax.set_aspect("equal")
            ax.set_xlabel("x (µm)")
            ax.set_ylabel("y (µm), wall at y = 0")
            ax.set_title(f"{name}: pressure at t = {r['t'] * 1e9:.0f} ns\nblack = 0.5 % most negative "
                         f"(min {r['pmin'] / 1e6:.0f} MPa)", fontsize="small")
            fig.colorbar(sc, ax=ax, label="p (MPa), blue = tension", shrink=0.7)
        ax = row[-1]
        t = np.array([r["t"] for r in rows]) * 1e9
        ax.plot(t, [r["tracker"] * 1e12 for r in rows], "o-", label="run's tracker (series.csv)")
        ax.plot(t, [r["area"] * 1e12 for r in rows], "s:", ms=4, label="frames, isotropic boxes (tension.py)")
        ax.set_xlabel("t (ns)")
        ax.set_ylabel("cavity area (µm²)")
        ax.set_title(f"{name}: cavity area", fontsize="small")
        ax.legend(fontsize="x-small")
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
