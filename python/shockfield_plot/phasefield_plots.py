#!/usr/bin/python3
"""Figures of phase-field run folders (docs/phasefield.md), used by `shockfield plot`.

  phasefield_plots.py phasefield RUN_DIR [--out FILE]
      left: the equivalent radius and the principal semi-axes of the hcp set against time
      (series.csv; a sharp-front run: its largest and mean radius), with the growth speed dR/dt (central differences between rows) on a second
      axis; right: ξ on the middle slice (z in 3D) of the last frame, the ξ = 1/2 contour drawn
      -> RUN_DIR/phasefield.png
"""
import argparse, csv, glob, os, re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from shockfield_plot.vtk_arrays import read_vtk_arrays


def _series(run):
    rows = list(csv.DictReader(open(os.path.join(run, "series.csv"))))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def _last_frame(run):
    frames = glob.glob(os.path.join(run, "fields", "xi_*.vti"))
    if not frames:
        return None, None
    last = max(frames, key=lambda f: int(re.search(r"xi_(\d+)\.vti$", f).group(1)))
    text = open(last, "rb").read(4000).decode("latin-1")
    extent = [int(v) for v in re.search(r'WholeExtent="([^"]+)"', text).group(1).split()]
    n = [extent[1] + 1, extent[3] + 1, extent[5] + 1]
    spacing = float(re.search(r'Spacing="([^ "]+)', text).group(1))
    xi = read_vtk_arrays(last)["xi"].reshape(n[2], n[1], n[0])
    return xi[n[2] // 2], spacing


def phasefield(run, out):
    s = _series(run)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    t = s["time"]
    left.plot(t, s["equivalent_radius"], "k-", label="equivalent radius")
    # The field model's semi-axes; the sharp-front option's (kind = "sharp_front") largest and mean radius.
    for key, style in (("axis_a", "C0--"), ("axis_b", "C1--"), ("axis_c", "C2--"), ("max_radius", "C3--"),
                       ("mean_radius", "C4:")):
        if key in s and np.any(s[key] > 0):
            left.plot(t, s[key], style, label=key.replace("_", " "))
    left.set_xlabel("time (model units)")
    left.set_ylabel("length (model units)")
    left.legend(loc="upper left", fontsize=8)
    if len(t) > 2:
        speed = np.gradient(s["equivalent_radius"], t)
        twin = left.twinx()
        twin.plot(t, speed, "r:", label="dR/dt")
        twin.set_ylabel("growth speed dR/dt", color="r")
    left.set_title(os.path.basename(os.path.normpath(run)))
    xi, h = _last_frame(run)
    if xi is None:
        right.set_axis_off()
    else:
        ny, nx = xi.shape
        im = right.imshow(xi, origin="lower", extent=[0, nx * h, 0, ny * h], cmap="viridis", vmin=0, vmax=1)
        if ny > 1:
            right.contour(np.arange(nx) * h, np.arange(ny) * h, xi, levels=[0.5], colors="w", linewidths=1)
        fig.colorbar(im, ax=right, label="ξ (0 bcc, 1 hcp)")
        right.set_title(f"last frame, t = {t[-1]:g} (middle slice)")
        right.set_xlabel("x")
        right.set_ylabel("y")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["phasefield"])
    ap.add_argument("run")
    ap.add_argument("--out")
    a = ap.parse_args()
    phasefield(a.run, a.out or os.path.join(a.run, "phasefield.png"))


if __name__ == "__main__":
    main()
