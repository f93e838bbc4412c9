#!/usr/bin/python3
"""shapes.png of examples/phasefield_shapes: for each run, the final domain's middle xz slice
(top row, the ξ = 1/2 contour) and the ratios of its principal semi-axes b/a and c/a against time
(bottom), from series.csv and the last frame.

    plot.py OUT.png RUN_DIR [RUN_DIR ...]

The fields are read by the compiled module: the package of the build tree (build/release/python)
must be on PYTHONPATH, as run.sh sets it.
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from shockfield.run import Run  # (the shared run-folder reader; PYTHONPATH: the build tree's package)

out, runs = sys.argv[1], sys.argv[2:]
fig, axes = plt.subplots(2, len(runs), figsize=(3.2 * len(runs), 6.4))
for col, run in enumerate(runs):
    name = os.path.basename(os.path.normpath(run))
    s = Run.open(run).series
    last = Run.open(run).last_frame(array="xi", kind="fields")
    xi, h = last.data, last.extra["spacing"][0]  # xi shaped (nz, ny, nx)
    n = xi.shape[::-1]
    cy = int(round(s["center_y"][-1] / h)) % n[1]
    slab = xi[:, cy, :]  # z rows, x columns
    top = axes[0, col]
    top.imshow(slab, origin="lower", extent=[0, n[0] * h, 0, n[2] * h], vmin=0, vmax=1, cmap="viridis")
    top.contour(np.arange(n[0]) * h, np.arange(n[2]) * h, slab, levels=[0.5], colors="w", linewidths=1)
    top.set_title(f"{name}: a, b, c = {s['axis_a'][-1]:.1f}, {s['axis_b'][-1]:.1f}, {s['axis_c'][-1]:.1f}", fontsize=9)
    top.set_xlabel("x")
    top.set_ylabel("z")
    bottom = axes[1, col]
    bottom.plot(s["time"], s["axis_b"] / s["axis_a"], "C0-", label="b/a")
    bottom.plot(s["time"], s["axis_c"] / s["axis_a"], "C1-", label="c/a")
    bottom.set_ylim(0, 1.05)
    bottom.set_xlabel("time")
    bottom.set_ylabel("axis ratio")
    bottom.legend(fontsize=8)
fig.suptitle("Growth shapes of an hcp domain (a = 0.2, D = 1): isotropic, and anisotropic D_d = D w_d", fontsize=10)
fig.tight_layout()
fig.savefig(out, dpi=110)
for run in runs:
    series = Run.open(run).series
    first, last = series[0], series[-1]
    print(f"{os.path.basename(os.path.normpath(run)):10s} t = {float(last['time']):5.1f}: semi-axes "
          f"{float(first['axis_a']):5.2f} {float(first['axis_b']):5.2f} {float(first['axis_c']):5.2f} -> "
          f"{float(last['axis_a']):5.2f} {float(last['axis_b']):5.2f} {float(last['axis_c']):5.2f}, long axis "
          f"({float(last['long_axis_x']):.2f}, {float(last['long_axis_y']):.2f}, {float(last['long_axis_z']):.2f})")
