#!/usr/bin/python3
"""Pictures of examples/macroparticle_rod (run.sh): plot.py OUT_DIR PICTURE_DIR.

e_vs_division.png      E of the rod against n_phi for each n_h/n_phi (beside Fig 4)
nu_vs_division.png     Poisson's ratio against n_phi (beside Fig 5)
stress_strain.png      tension and compression with the plastic pair law (beside Fig 6)
compression_slip.png   the compressed rod's particles, coloured by their displacement across z
"""
import csv, glob, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield_plot.macroparticle_plots import stress_strain  # noqa: E402  (`shockfield plot stress-strain`)


def read_csv(path):
    rows = list(csv.DictReader(open(path)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def studies(out):
    found = {}
    for path in sorted(glob.glob(os.path.join(out, "elastic", "study_*.csv"))):
        ratio = os.path.basename(path)[len("study_"):-len(".csv")]
        found[float(ratio)] = read_csv(path)
    return found


def division_figure(data, column, scale, ylabel, fig_number, references, png):
    """One quantity of the elastic studies against n_phi, one line per n_h/n_phi."""
    fig, ax = plt.subplots(figsize=(6, 4))
    for ratio, d in sorted(data.items()):
        ax.plot(d["n_phi"], d[column] / scale, "o-", label=f"n_h/n_phi = {ratio:g}")
    for draw in references:
        draw(ax)
    ax.set_xscale("log", base=2)
    ax.set_xlabel("n_phi (cells across the 14 mm diameter)")
    ax.set_ylabel(ylabel)
    ax.set_title(f"Al rod, 0.1 % tension at T = 0 (cf. Saitoh et al. Fig {fig_number})")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def plot_division(out, pictures):
    data = studies(out)
    if not data:
        return
    any_study = next(iter(data.values()))
    e15, e001 = any_study["E_eq15_Pa"][0] / 1e9, any_study["E_lattice_Pa"][0] / 1e9
    division_figure(data, "E_Pa", 1e9, "Young's modulus of the rod (GPa)", 4, [
        lambda ax: ax.axhline(e001, color="k", ls="--", label=f"fcc packing along [001]: {e001:.1f} GPa"),
        lambda ax: ax.axhline(e15, color="r", ls=":", label=f"eq 15 (p = 4, q = 9): {e15:.1f} GPa")],
        os.path.join(pictures, "e_vs_division.png"))
    division_figure(data, "nu", 1.0, "Poisson's ratio of the rod", 5, [
        lambda ax: ax.axhline(1 / 3, color="k", ls="--", label="fcc packing along [001]: 1/3 (Cauchy)"),
        lambda ax: ax.axhspan(0.30, 0.33, color="0.85", label="Saitoh et al. Fig 5: 0.30-0.33")],
        os.path.join(pictures, "nu_vs_division.png"))


def plot_stress_strain(out, pictures):
    runs = [os.path.join(out, m) for m in ("tension", "compression") if os.path.exists(os.path.join(out, m, "thermo.csv"))]
    if runs:
        stress_strain(runs, os.path.join(pictures, "stress_strain.png"),
                      "Al rod (n_phi = 4, n_h = 8), plastic pair law (cf. Saitoh et al. Fig 6)")


def read_last_dump(folder):
    files = sorted(glob.glob(os.path.join(folder, "dumps", "dump.*.lammpstrj")),
                   key=lambda p: int(p.split(".")[-2]))
    if not files:
        return None, None
    def read(path):
        lines = open(path).read().split("\n")
        n = int(lines[lines.index("ITEM: NUMBER OF ATOMS") + 1])
        head = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        cols = lines[head].split()[2:]
        a = np.array([[float(v) for v in l.split()] for l in lines[head + 1:head + 1 + n]])
        return {c: a[:, k] for k, c in enumerate(cols)}
    return read(files[0]), read(files[-1])


def plot_slip(out, pictures):
    first, last = read_last_dump(os.path.join(out, "compression"))
    if first is None:
        return
    order0, order1 = np.argsort(first["id"]), np.argsort(last["id"])
    x0, z0 = first["x"][order0], first["z"][order0]
    x1, z1 = last["x"][order1], last["z"][order1]
    fig, axes = plt.subplots(1, 2, figsize=(7, 5), sharey=True)
    axes[0].scatter(x0 * 1e3, z0 * 1e3, s=6, c="0.5")
    axes[0].set_title("start")
    sc = axes[1].scatter(x1 * 1e3, z1 * 1e3, s=6, c=(x1 - x0) * 1e3, cmap="coolwarm")
    axes[1].set_title("end of compression")
    fig.colorbar(sc, ax=axes[1], label="x displacement (mm)")
    for ax in axes:
        ax.set_xlabel("x (mm)")
        ax.set_aspect("equal")
    axes[0].set_ylabel("z (mm)")
    fig.tight_layout()
    fig.savefig(os.path.join(pictures, "compression_slip.png"), dpi=120)


def main():
    out, pictures = sys.argv[1], sys.argv[2]
    plot_division(out, pictures)
    plot_stress_strain(out, pictures)
    plot_slip(out, pictures)


if __name__ == "__main__":
    main()
