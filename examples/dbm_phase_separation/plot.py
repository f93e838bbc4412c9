#!/usr/bin/env python3
"""Pictures, curves and the table of examples/dbm_phase_separation (Xu et al. 2015, §4.3, Figs. 63-64).

usage: plot.py RUNS K1 K2 ...   (RUNS/K<K>/ are the run folders of run.sh)
Writes patterns.png (density at three times per K), curves.png (L, D, R against t),
trends.png (t_SD and D_max against K with the fits of eqs. 36-37) and table.md.
"""
import csv
import re
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent / "python"))
from shockfield.vtk_arrays import read_vtk_arrays  # noqa: E402


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def read_rho(vti):
    """The density of a grid frame (any VTK encoding: shockfield.vtk_arrays) as rows y, columns x."""
    head = Path(vti).read_bytes()[:2048].decode("ascii", "replace")
    ext = [int(v) for v in re.search(r'WholeExtent="([^"]+)"', head).group(1).split()]
    rho = read_vtk_arrays(str(vti))["rho"].astype(float)
    # Cell data (frames since the cell-centred layout) has ext cells per axis, point data ext + 1.
    cells = (ext[3], ext[1]) if rho.size == ext[3] * ext[1] else (ext[3] + 1, ext[1] + 1)
    return rho.reshape(cells)


def growth_exponent(s, t0, t1):
    """Slope of log R against log t over [t0, t1] (the growth law R ~ t^n)."""
    sel = (s["time"] >= t0) & (s["time"] <= t1) & (s["R"] > 0)
    if sel.sum() < 3:
        return "-"
    return f"{np.polyfit(np.log(s['time'][sel]), np.log(s['R'][sel]), 1)[0]:.2f}"


def frames(run):
    text = (run / "grid.pvd").read_text()
    return [(float(t), run / f) for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


def main():
    runs, Ks = Path(sys.argv[1]), sys.argv[2:]
    K = np.array([float(k) for k in Ks])
    series = {k: read_csv(runs / f"K{k}" / "series.csv") for k in Ks}
    summary = {k: read_csv(runs / f"K{k}" / "summary.csv") for k in Ks}

    # Density patterns: the frame nearest t_SD/2, t_SD and the last one of each K.
    fig, ax = plt.subplots(3, len(Ks), figsize=(2.6 * len(Ks), 7.6), squeeze=False)
    for c, k in enumerate(Ks):
        fr = frames(runs / f"K{k}")
        tsd = summary[k]["t_SD"][0]
        picks = [min(fr, key=lambda x: abs(x[0] - t)) for t in (0.5 * tsd, tsd, fr[-1][0])]
        for r, (t, f) in enumerate(picks):
            ax[r][c].imshow(read_rho(f), origin="lower", cmap="viridis", vmin=0.2, vmax=1.9)
            ax[r][c].set_xticks([]), ax[r][c].set_yticks([])
            ax[r][c].set_title(f"K={k}, t={t:.2f}", fontsize=8)
    fig.tight_layout()
    fig.savefig(HERE / "patterns.png", dpi=60)

    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    for k in Ks:
        s = series[k]
        l, = ax[0].plot(s["time"], s["L"], label=f"K={k}")
        ax[0].axvline(summary[k]["t_SD"][0], color=l.get_color(), ls=":")
        ax[1].plot(s["time"], s["D"], color=l.get_color(), label=f"D, K={k}")
        ax[1].plot(s["time"], 10 * s["D_force"], color=l.get_color(), ls="--")
        ax[2].loglog(s["time"][1:], s["R"][1:], color=l.get_color(), label=f"K={k}")
    ax[0].set(xlabel="t", ylabel="boundary length L (threshold in case.toml)", title="L(t); dotted: t_SD = peak of D")
    ax[1].set(xlabel="t", ylabel="D (solid), 10 D^F (dashed)", title="TNE strength D(t), eq. 35")
    ax[2].set(xlabel="t", ylabel="R = 2π/k1", title="domain size R(t)")
    tt = np.linspace(0.4, 1.5, 10)
    ax[2].loglog(tt, 0.2 * (tt / 0.8) ** (2 / 3), "k--", label="t^(2/3)")
    ax[2].loglog(tt, 0.2 * (tt / 0.8) ** (1 / 3), "k:", label="t^(1/3)")
    for a in ax:
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(HERE / "curves.png", dpi=80)

    tsd = np.array([summary[k]["t_SD"][0] for k in Ks])
    dmax = np.array([summary[k]["D_max"][0] for k in Ks])
    tl = np.array([summary[k]["t_L_max"][0] for k in Ks])
    b, a = np.polyfit(K, tsd, 1)
    d, c = np.polyfit(K ** -0.5, dmax, 1)
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.6))
    ax[0].plot(K, tsd, "o", label="t_SD (peak of D)")
    ax[0].plot(K, tl, "x", label="peak of L")
    ax[0].plot(K, a + b * K, "-", label=f"a + bK: a={a:.3f}, b={b:.3g}")
    ax[1].plot(K, dmax, "o", label="D_max")
    kk = np.linspace(K.min(), K.max(), 50)
    ax[1].plot(kk, c + d * kk ** -0.5, "-", label=f"c + d K^-1/2: c={c:.3f}, d={d:.3g}")
    ax[0].set(xlabel="K", ylabel="t"), ax[1].set(xlabel="K", ylabel="D_max")
    ax[0].legend(fontsize=7), ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(HERE / "trends.png", dpi=80)

    lines = ["| K | t_SD (peak of D) | D_max | peak of D^F at t | peak of L at t | L_max | R(t_SD) | R(end) | end t | "
             "growth exponent before / after t_SD | max \\|u\\| | mass drift | e_T drift |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for k in Ks:
        s, m = series[k], summary[k]
        i = int(np.argmin(abs(s["time"] - m["t_SD"][0])))
        lines.append(f"| {k} | {m['t_SD'][0]:.3f} | {m['D_max'][0]:.4f} | {m['t_SD_force'][0]:.3f} | {m['t_L_max'][0]:.3f} | "
                     f"{m['L_max'][0]:.2f} | {s['R'][i]:.4f} | {s['R'][-1]:.4f} | {s['time'][-1]:.2f} | "
                     f"{growth_exponent(s, 0.5 * s['time'][i], s['time'][i])} / {growth_exponent(s, s['time'][i], s['time'][-1])} | "
                     f"{s['u_max'].max():.3f} | "
                     f"{s['mass'][-1] / s['mass'][0] - 1:.1e} | {s['energy'][-1] / s['energy'][0] - 1:.1e} |")
    lines.append("")
    lines.append(f"fits: t_SD = a + bK with a = {a:.4f}, b = {b:.4g} (Xu et al. (2015) eq. 36: a = 0.066, b = 1.51e3); "
                 f"D_max = c + d K^-0.5 with c = {c:.4f}, d = {d:.4g} (eq. 37: c = -0.073, d = 3.30e-3)")
    (HERE / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
