#!/usr/bin/env python3
"""Draws the relaxed edge dislocation: atoms of one periodic length seen along the line (z),
coloured by adaptive CNA (fcc left out), with the Burgers circuits of burgers.csv and their vectors.

usage: plot.py ANALYSIS_FOLDER OUTPUT.png"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import read_csv, read_lammps_dump  # noqa: E402  (the shared readers; an analyze folder)

COLOURS = {2: ("hcp (stacking fault)", "#d62728"), 3: ("bcc", "#2ca02c"), 5: ("other (cores, surface)", "#1f77b4")}


def main():
    folder, output = sys.argv[1], sys.argv[2]
    atoms = read_lammps_dump(f"{folder}/dump.0.lammpstrj")[0][3]  # (step, time, box, atoms) of its one frame
    circuits = read_csv(f"{folder}/burgers.csv", text=("b",))  # b: "0" when a circuit closes
    fig, ax = plt.subplots(figsize=(8.5, 6.5))
    x, y = atoms["x"], atoms["y"]
    fcc = atoms["acna"] == 1
    ax.scatter(x[fcc], y[fcc], s=1, c="#dddddd", label="fcc")
    for code, (label, colour) in COLOURS.items():
        m = atoms["acna"] == code
        if m.any():
            ax.scatter(x[m], y[m], s=4, c=colour, label=label)
    for row in circuits:
        k = int(row["circuit"])
        m = atoms["burgers_circuit"] == k
        cx, cy = float(row["centre_x_A"]), float(row["centre_y_A"])
        order = np.argsort(np.arctan2(y[m] - cy, x[m] - cx))
        px, py = np.append(x[m][order], x[m][order][0]), np.append(y[m][order], y[m][order][0])
        ax.plot(px, py, "-", lw=1.2, c="k")
        ax.annotate(f"b = {row['b']}\n({row['kind'].split()[0]})", (cx, cy + float(row["radius_A"]) + 1.5),
                    ha="center", va="bottom", fontsize=9, bbox=dict(fc="white", ec="none", alpha=0.8))
    ax.set_aspect("equal")
    ax.set_xlim(-40, 40)
    ax.set_ylim(-30, 35)
    ax.set_xlabel("x = [1-10] (Å)")
    ax.set_ylabel("y = [111] (Å)")
    ax.set_title("Cu edge dislocation after minimisation: Frank-scheme Burgers circuits (FS/RH)", fontsize=10)
    ax.legend(loc="lower left", fontsize=8, markerscale=3)
    fig.tight_layout()
    fig.savefig(output, dpi=130)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
