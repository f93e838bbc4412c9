#!/usr/bin/python3
"""Figures of phase-field run folders (docs/phasefield.md), used by `shockfield plot`.

  python3 -m shockfield_plot.phasefield_plots phasefield RUN_DIR [--out FILE]
      left: the equivalent radius and the principal semi-axes of the hcp set against time
      (series.csv; a sharp-front run: its largest and mean radius), with the growth speed dR/dt (central differences between rows) on a second
      axis; right: ξ on the middle slice (z in 3D) of the last frame, the ξ = 1/2 contour drawn
      -> RUN_DIR/phasefield.png

Reads series.csv and the fields (fields.pvd) through shockfield.run.Run.
"""
import argparse, os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from shockfield.errors import InputError
from shockfield.run import Run


def _last_frame(run):
    """ξ on the middle slice (z) of the run's last field frame and the grid spacing; (None, None)
    for a run without fields."""
    try:
        frame = run.last_frame(array="xi", kind="fields")
    except InputError:
        return None, None
    xi = frame.data[frame.data.shape[0] // 2] if frame.data.ndim == 3 else np.atleast_2d(frame.data)
    return xi, float(np.ravel(frame.extra["spacing"])[0])


def phasefield(run, out):
    run = Run.open(run)
    s = run.series
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    t = s["time"]
    left.plot(t, s["equivalent_radius"], "k-", label="equivalent radius")
    # The field model's semi-axes; the sharp-front option's (kind = "sharp_front") largest and mean radius.
    for key, style in (("axis_a", "C0--"), ("axis_b", "C1--"), ("axis_c", "C2--"), ("max_radius", "C3--"),
                       ("mean_radius", "C4:")):
        if key in s.dtype.names and np.any(s[key] > 0):
            left.plot(t, s[key], style, label=key.replace("_", " "))
    left.set_xlabel("time (model units)")
    left.set_ylabel("length (model units)")
    left.legend(loc="upper left", fontsize=8)
    if len(t) > 2:
        speed = np.gradient(s["equivalent_radius"], t)
        twin = left.twinx()
        twin.plot(t, speed, "r:", label="dR/dt")
        twin.set_ylabel("growth speed dR/dt", color="r")
    left.set_title(f"{run.folder.name} ({run.case_name})")
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
