"""Plots for `shockfield analyze`:

    python3 -m shockfield_plot minkowski minkowski.csv minkowski.png
    python3 -m shockfield_plot similarity similarity.csv similarity.png
    python3 -m shockfield_plot surfaces voids.csv voids.png      (or domains.csv domains.png)

minkowski: one panel per functional (columns after `threshold_<unit>`), each functional against time
with one curve per threshold (the paper's Figs. 32-41), or against the threshold when there is a
single time. similarity: process distance d_P against the candidate threshold (Fig. 43's search).
Column names end in their unit (`time_s`, `threshold_K`, `L_m`; `_1` a pure number or model unit,
`_unknown` an input without units: docs/conventions.md); the axis labels show it.
surfaces: the voids or phase domains of `analyze atoms --voids/--domains` (columns timestep, void or
domain, volume, area): their total and the largest one's volume and area against the timestep.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import read_csv  # noqa: E402


def minkowski(csv_path, png_path):
    table = read_csv(csv_path)  # columns: file, time_<unit>, threshold_<unit>, functionals...
    _, time_name, threshold_name, *names = table.dtype.names
    time, threshold = table[time_name], table[threshold_name]
    times, thresholds = np.unique(time), np.unique(threshold)
    fig, axes = plt.subplots(1, len(names), figsize=(4 * len(names), 3.4))
    for ax, name in zip(axes, names):
        if len(times) > 1:
            step = max(1, len(thresholds) // 8)
            for t in thresholds[::step]:
                rows = np.flatnonzero(threshold == t)
                rows = rows[np.argsort(time[rows], kind="stable")]
                ax.plot(time[rows], table[name][rows], label=f"{t:g}")
            ax.set_xlabel(time_name)
        else:
            ax.plot(threshold, table[name])
            ax.set_xlabel(threshold_name)
        ax.set_title(name)
    if len(times) > 1:
        axes[0].legend(title=threshold_name, fontsize="small")
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


def similarity(csv_path, png_path):
    table = read_csv(csv_path)  # columns: candidate, threshold_<unit>, d_P, S_D
    threshold_name = table.dtype.names[1]
    threshold, distance = table[threshold_name], table["d_P"]
    fig, ax = plt.subplots(figsize=(5, 3.4))
    ax.plot(threshold, distance, marker=".")
    best = threshold[np.argmin(distance)]
    ax.axvline(best, color="grey", ls="--", label=f"best {best:g}")
    ax.set_xlabel(f"candidate {threshold_name}")
    ax.set_ylabel("process distance d_P")
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


def surfaces(csv_path, png_path):
    table = read_csv(csv_path)  # columns: timestep, void or domain, volume_A3, area_A2
    what = "domain" if "domain" in table.dtype.names else "void"
    steps = np.unique(table["timestep"]).astype(int)
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.4))
    for ax, (quantity, unit) in zip(axes, (("volume", "Å³"), ("area", "Å²"))):
        column = f"{quantity}_{unit.replace('Å', 'A').replace('³', '3').replace('²', '2')}"  # volume_A3, area_A2
        values = [table[column][table["timestep"] == t] for t in steps]
        ax.plot(steps, [v.sum() for v in values], marker="o", label=f"all {what}s")
        ax.plot(steps, [v.max(initial=0.0) for v in values], marker=".", ls="--", label=f"largest {what}")
        ax.set_xlabel("timestep")
        ax.set_ylabel(f"{quantity} ({unit})")
    axes[0].legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    {"minkowski": minkowski, "similarity": similarity, "surfaces": surfaces}[sys.argv[1]](sys.argv[2], sys.argv[3])
