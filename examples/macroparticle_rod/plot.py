#!/usr/bin/python3
"""Pictures of examples/macroparticle_rod (run.sh): plot.py OUT_DIR PICTURE_DIR.

e_vs_division.png      E of the rod against n_phi for each n_h/n_phi (beside Fig 4)
nu_vs_division.png     Poisson's ratio against n_phi (beside Fig 5)
stress_strain.png      tension and compression with the plastic pair law (beside Fig 6)
compression_buckling.png  the L/D = 3.5 rod in compression: its stress drop and the buckled slice
"""
import glob, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield_plot.macroparticle_plots import stress_strain  # noqa: E402  (`shockfield plot stress-strain`)
from shockfield.run import Run, read_csv  # noqa: E402  (the shared readers)


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


def in_id_order(frame):
    """A dump frame's particles sorted by id."""
    return frame.data[np.argsort(frame.data["id"])]


def bonds(d, r0):
    """Pairs of particle ids closer than the pair law's cutoff (1.2071 r0)."""
    x = np.c_[d["x"], d["y"], d["z"]] / r0
    i, j = np.nonzero(np.triu(np.linalg.norm(x[:, None] - x[None], axis=2) < 1.2071, 1))
    return set(zip(d["id"][i].astype(int), d["id"][j].astype(int)))


def plot_buckling(out, pictures):
    """Stress-strain of the L/D = 3.5 rod in compression (imperfect with sliding ends, imperfect
    with clamped ends, perfect) and the buckled rod's (1-10) slice through the axis."""
    folder = os.path.join(out, "buckling")
    if not glob.glob(os.path.join(folder, "dumps", "dump.*.lammpstrj")):
        return
    run = Run.open(folder)
    r0 = run.value("r0")
    first, last = in_id_order(next(run.frames(kind="dumps"))), in_id_order(run.last_frame(kind="dumps"))
    lost = len(bonds(first, r0) - bonds(last, r0))
    fig, axes = plt.subplots(1, 2, figsize=(10, 5), gridspec_kw={"width_ratios": [1.4, 1]})
    runs = [(os.path.join(out, n), l) for n, l in (("buckling", "imperfect (1e-3 r0), sliding ends"),
                                                  ("buckling_clamped", "imperfect, clamped ends"),
                                                  ("buckling_perfect", "perfect, sliding ends"))]
    runs = [(r, l) for r, l in runs if os.path.exists(os.path.join(r, "thermo.csv"))]
    stress_strain([r for r, _ in runs], None, "", ax=axes[0], labels=[l for _, l in runs])
    axes[0].axvline(3.2, color="0.5", ls=":", label="Saitoh et al. Fig 6(b): drop at 3.2 %")
    axes[0].legend(fontsize=8)
    axes[0].set_title("Al rod n_phi = 4, n_h = 16 (L/D = 3.5), compression")
    # The slice through the axis normal to [1-10]: the sway is along [110] (x = y).
    xc, yc = first["x"].mean(), first["y"].mean()
    def slab(d, x0, y0):
        along = ((d["x"] - x0) + (d["y"] - y0)) / np.sqrt(2)
        across = ((d["x"] - x0) - (d["y"] - y0)) / np.sqrt(2)
        return along, across
    a0, c0 = slab(first, xc, yc)
    keep = np.abs(c0) < 0.4 * r0
    a1, _ = slab(last, xc, yc)
    axes[1].scatter(a0[keep] * 1e3, first["z"][keep] * 1e3, s=14, facecolors="none", edgecolors="0.75", label="start")
    sc = axes[1].scatter(a1[keep] * 1e3, last["z"][keep] * 1e3, s=14, c=last["szz"][keep] / 1e9, cmap="coolwarm_r",
                         vmin=-2.5, vmax=0.5, label="5 % strain")
    fig.colorbar(sc, ax=axes[1], label="particle σ_zz (GPa)")
    axes[1].set_xlabel("x along [110] (mm)")
    axes[1].set_ylabel("z along [001] (mm)")
    axes[1].set_aspect("equal")
    axes[1].set_title(f"slice through the axis at 5 %: bonds lost {lost}", fontsize=9)
    axes[1].legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(pictures, "compression_buckling.png"), dpi=120)


def main():
    out, pictures = sys.argv[1], sys.argv[2]
    plot_division(out, pictures)
    plot_stress_strain(out, pictures)
    plot_buckling(out, pictures)


if __name__ == "__main__":
    main()
