#!/usr/bin/python3
"""Figures of macroparticle run folders (docs/macroparticle.md), used by `shockfield plot`.

  python3 -m shockfield_plot.macroparticle_plots stress-strain RUN_DIR [RUN_DIR ...] [--out FILE]
      |stress| against |strain| of the loaded rods (thermo.csv columns Strain, Stress), one
      curve per run labelled by its folder name -> RUN_DIR/stress-strain.png

Reads thermo.csv through shockfield.run.Run.
"""
import argparse, os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from shockfield.run import Run


def stress_strain(runs, out, title="macroparticle rods", ax=None, labels=None):
    """The curves of `runs` into `out`, or into the axes `ax` (then `out` is not written)."""
    fig = None
    if ax is None:
        fig, ax = plt.subplots(figsize=(6, 4))
    for k, run in enumerate(map(Run.open, runs)):
        thermo = run.thermo
        strain, stress = thermo["Strain"], thermo["Stress"]
        label = labels[k] if labels else run.folder.name
        ax.plot(np.abs(strain) * 100, np.abs(stress) / 1e6, label=label)
    ax.set_xlabel("|strain of the loaded layers| (%)")
    ax.set_ylabel("|virial stress σ_zz| (MPa)")
    ax.set_title(title)
    ax.legend(fontsize=8)
    if fig is not None:
        fig.tight_layout()
        fig.savefig(out, dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["stress-strain"])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--out")
    a = ap.parse_args()
    stress_strain(a.runs, a.out or os.path.join(a.runs[0], "stress-strain.png"))


if __name__ == "__main__":
    main()
