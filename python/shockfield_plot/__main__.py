"""Plots for `shockfield analyze`:

    python3 -m shockfield_plot minkowski minkowski.csv minkowski.png
    python3 -m shockfield_plot similarity similarity.csv similarity.png
    python3 -m shockfield_plot surfaces voids.csv voids.png      (or domains.csv domains.png)

minkowski: one panel per functional (columns after `threshold`), each functional against time
with one curve per threshold (the paper's Figs. 32-41), or against the threshold when there is a
single time. similarity: process distance d_P against the candidate threshold (Fig. 43's search).
surfaces: the voids or phase domains of `analyze atoms --voids/--domains` (columns timestep, void or
domain, volume, area): their total and the largest one's volume and area against the timestep.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return rows[0], [[float(v) if v not in ("", "nan") else float("nan") for v in r[1:]] for r in rows[1:]]


def minkowski(csv_path, png_path):
    header, rows = read(csv_path)
    names = header[3:]  # columns: file, time, threshold, functionals...
    times = sorted({r[0] for r in rows})
    thresholds = sorted({r[1] for r in rows})
    fig, axes = plt.subplots(1, len(names), figsize=(4 * len(names), 3.4))
    for i, name in enumerate(names):
        ax = axes[i]
        if len(times) > 1:
            step = max(1, len(thresholds) // 8)
            for t in thresholds[::step]:
                pts = sorted((r[0], r[2 + i]) for r in rows if r[1] == t)
                ax.plot([p[0] for p in pts], [p[1] for p in pts], label=f"{t:g}")
            ax.set_xlabel("time")
        else:
            ax.plot([r[1] for r in rows], [r[2 + i] for r in rows])
            ax.set_xlabel("threshold")
        ax.set_title(name)
    if len(times) > 1:
        axes[0].legend(title="threshold", fontsize="small")
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


def similarity(csv_path, png_path):
    header, rows = read(csv_path)
    fig, ax = plt.subplots(figsize=(5, 3.4))
    ax.plot([r[0] for r in rows], [r[1] for r in rows], marker=".")
    best = min(rows, key=lambda r: r[1])
    ax.axvline(best[0], color="grey", ls="--", label=f"best {best[0]:g}")
    ax.set_xlabel("candidate threshold")
    ax.set_ylabel("process distance d_P")
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


def surfaces(csv_path, png_path):
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    what = "domain" if rows and "domain" in rows[0] else "void"
    steps = sorted({int(r["timestep"]) for r in rows})
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.4))
    for ax, column, unit in ((axes[0], "volume", "Å³"), (axes[1], "area", "Å²")):
        total = [sum(float(r[column]) for r in rows if int(r["timestep"]) == t) for t in steps]
        largest = [max((float(r[column]) for r in rows if int(r["timestep"]) == t), default=0.0) for t in steps]
        ax.plot(steps, total, marker="o", label=f"all {what}s")
        ax.plot(steps, largest, marker=".", ls="--", label=f"largest {what}")
        ax.set_xlabel("timestep")
        ax.set_ylabel(f"{column} ({unit})")
    axes[0].legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    {"minkowski": minkowski, "similarity": similarity, "surfaces": surfaces}[sys.argv[1]](sys.argv[2], sys.argv[3])
