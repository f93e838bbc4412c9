#!/usr/bin/python3
"""Plots of `shockfield analyze atoms` (and of an MD run's in-run [analysis]).

  python3 -m shockfield_plot.atoms_plots structures FOLDER [--out FILE]
      structure fractions against time from FOLDER/structures.csv (one panel per method: cna,
      acna, bpa; one curve per structure present) -> FOLDER/structures.png
  python3 -m shockfield_plot.atoms_plots slice DUMP [--out FILE] [--axis z] [--at POS] [--thickness W] [--column NAME]
                            [--frame K]
      the atoms of a slice |r_axis - POS| < W/2 (default: the box middle, W = 3 A) of frame K
      (default the last) of an annotated dump, coloured by structure type (column acna, else cna,
      bpa, or NAME; LAMMPS cna/atom codes 1 fcc, 2 hcp, 3 bcc, 4 ico, 5 other; for dia the diamond
      codes 0 other, 1 cubic, 2-3 its first and second neighbours, 4 hexagonal, 5-6 its neighbours)
      -> DUMP without its extension + _slice.png

Each prints what it drew (frames and methods; atoms per type in the slice), so tests can check
the figure's content. Reads structures.csv and the dump through shockfield.run (read_csv,
read_lammps_dump); a missing file or column raises shockfield.InputError. Uses only numpy and
matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.errors import InputError  # noqa: E402
from shockfield.run import read_csv, read_lammps_dump  # noqa: E402

STRUCTURES = ["fcc", "hcp", "bcc", "ico", "other"]
# OVITO's colours of the types (fcc green, hcp red, bcc blue, ico yellow, other grey).
COLOURS = {"fcc": "#66cc66", "hcp": "#ff4d4d", "bcc": "#6680ff", "ico": "#e6cc1a", "other": "#bfbfbf"}
# The dia column (OVITO's Identify diamond structure codes 0 other, 1-6).
DIAMOND = ["other", "cubic", "cubic_first", "cubic_second", "hexagonal", "hexagonal_first", "hexagonal_second"]
DIAMOND_COLOURS = {"other": "#bfbfbf", "cubic": "#1966ff", "cubic_first": "#3399ff", "cubic_second": "#80c0ff",
                   "hexagonal": "#ff8c1a", "hexagonal_first": "#ffb366", "hexagonal_second": "#ffd9b3"}
METHODS = {"cna": "conventional CNA", "acna": "adaptive CNA", "bpa": "bond pairs", "dia": "diamond"}


def structures(folder, out):
    path = os.path.join(folder, "structures.csv")
    if not os.path.exists(path):
        raise InputError(f"{path}: not found (the output folder of `shockfield analyze atoms`, or an MD run with "
                         "[analysis])")
    table = read_csv(path)
    if len(table) == 0:
        raise InputError(f"{path}: no data rows")
    col = {name: table[name] for name in table.dtype.names}
    x, xlabel = (col["time_ps"], "time (ps)") if "time_ps" in col else (col["timestep"], "timestep")
    if len(x) > 1 and not np.all(np.diff(x) > 0):  # frames of one timestep (separate samples)
        x, xlabel = col["frame"], "frame"
    methods = [m for m in METHODS if f"{m}_fcc_fraction" in col or f"{m}_cubic_fraction" in col]
    if not methods:
        raise InputError(f"{path}: no <method>_<structure>_fraction columns")
    fig, axes = plt.subplots(len(methods), 1, figsize=(7, 3.2 * len(methods)), sharex=True, squeeze=False)
    for ax, m in zip(axes[:, 0], methods):
        names, colours = (DIAMOND[1:] + DIAMOND[:1], DIAMOND_COLOURS) if m == "dia" else (STRUCTURES, COLOURS)
        for s in names:
            y = col[f"{m}_{s}_fraction"]
            if np.any(y > 0):
                ax.plot(x, y, "o-", ms=3, color=colours[s], label=s)
        ax.set_ylabel(f"fraction ({METHODS[m]})")
        ax.set_ylim(-0.02, 1.02)
        ax.legend(fontsize=8, loc="best")
    axes[-1, 0].set_xlabel(xlabel)
    fig.suptitle(f"Structure fractions: {os.path.basename(os.path.abspath(folder))}")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"structures: {len(x)} frames, methods {' '.join(methods)}")


def read_frame(path, k):
    """Frame k (negative: from the end) of a LAMMPS text dump: (timestep, lo, hi, columns dict)."""
    frames = read_lammps_dump(path)
    if not frames:
        raise InputError(f"{path}: not a LAMMPS text dump (no ITEM: TIMESTEP)")
    try:
        step, _, box, atoms = frames[k]
    except IndexError:
        raise InputError(f"{path}: --frame {k}: the file has {len(frames)} frames") from None
    return step, box.lo, box.hi, {name: atoms[name] for name in atoms.dtype.names}


def slice_plot(dump, out, axis, at, thickness, column, frame):
    step, lo, hi, col = read_frame(dump, frame)
    name = column or next((c for c in ("acna", "cna", "bpa") if c in col), None)
    if name is None or name not in col:
        raise InputError(f"{dump}: no structure column ({column or 'acna, cna or bpa'}); analyse it with "
                         "`shockfield analyze atoms` first")
    d = "xyz".index(axis)
    pos = np.column_stack([col[c] for c in ("x", "y", "z")]) if "x" in col else \
        np.column_stack([col[c] for c in ("xu", "yu", "zu")])
    centre = 0.5 * (lo[d] + hi[d]) if at is None else at
    inside = np.abs(pos[:, d] - centre) < 0.5 * thickness
    u, v = [k for k in range(3) if k != d]
    codes = col[name][inside].round().astype(int)
    fig, ax = plt.subplots(figsize=(6.5, 6.5 * (hi[v] - lo[v]) / max(hi[u] - lo[u], 1e-9) + 0.8))
    counts = []
    types = list(enumerate(DIAMOND)) if name == "dia" else list(enumerate(STRUCTURES, start=1))
    colours = DIAMOND_COLOURS if name == "dia" else COLOURS
    for code, s in types:
        sel = codes == code
        counts.append(f"{s} {int(sel.sum())}")
        if sel.any():
            ax.scatter(pos[inside][sel, u], pos[inside][sel, v], s=14, color=colours[s], label=f"{s} ({sel.sum()})",
                       edgecolors="k", linewidths=0.2)
    ax.set_xlim(lo[u], hi[u])
    ax.set_ylim(lo[v], hi[v])
    ax.set_aspect("equal")
    ax.set_xlabel(f"{'xyz'[u]} (Å)")
    ax.set_ylabel(f"{'xyz'[v]} (Å)")
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title(f"{os.path.basename(dump)}, timestep {step}: {name}, |{axis} - {centre:.3g}| < {thickness / 2:g} Å")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"slice: timestep {step}, {int(inside.sum())} atoms by {name}: {', '.join(counts)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["structures", "slice"])
    ap.add_argument("path", help="structures: the analysis output folder; slice: an annotated dump")
    ap.add_argument("--out")
    ap.add_argument("--axis", default="z", choices=["x", "y", "z"])
    ap.add_argument("--at", type=float, help="slice centre along the axis (Å; default the box middle)")
    ap.add_argument("--thickness", type=float, default=3.0, help="slice thickness (Å)")
    ap.add_argument("--column", help="the structure column (default acna, else cna, else bpa)")
    ap.add_argument("--frame", type=int, default=-1, help="frame index in the dump (0 first; default -1, the last)")
    a = ap.parse_args()
    if a.kind == "structures":
        out = a.out or os.path.join(a.path, "structures.png")
        structures(a.path, out)
    else:
        if not a.thickness > 0:
            raise InputError(f"--thickness {a.thickness}: expected a number > 0 (Å)")
        out = a.out or os.path.splitext(a.path)[0] + "_slice.png"
        slice_plot(a.path, out, a.axis, a.at, a.thickness, a.column, a.frame)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
