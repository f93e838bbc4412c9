#!/usr/bin/env python3
"""Tables and pictures of the phase-separation study (Xu et al. 2015, §4.3, Figs. 63-64, eqs. 34-37).

usage: plot.py RUNS
RUNS holds the sweep folders of run.sh (each with sweep.csv and one run folder per K):
  study64/      the K sweep on 64² (the main table, with study128/ for K = 1e-5)
  study128/     the K that need Δx = 1/128
  conv<n>/      the convergence runs on n² (optional)
  <other>/      sensitivity sweeps (noise amplitude, quench, noise wavelength; optional)
Writes table.md (per K: t_SD, R_SD, D_max, u_DG, the peaks of L(t) and D^F(t); the fits of eqs. 34,
36, 37 beside the paper's; the convergence and sensitivity tables), fig63.png, fig64.png.

Definitions (README): t_SD = time of the peak of D(t) (eq. 35 of Δ*); R_SD = R(t_SD) with R = 2π/k₁
(first moment of the structure factor); D_max = D(t_SD); u_DG = dR/dt in the domain-growth stage,
the least-squares slope of R(t) over [t_SD, t_end] (the paper: "the slope of the R(t) curve presents
a phase separation speed u_DG for the domain growth stage").
"""
import re
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent / "python"))
from shockfield.run import Run, read_csv, read_pvd  # noqa: E402  (the shared run-folder readers)
from shockfield.vtk_arrays import read_vtk_arrays  # noqa: E402

PAPER = {"a": 0.066, "b": 1.51e3, "c": -0.073, "d": 3.30e-3, "e": 0.00764, "f": 1.51e2, "g": 8.06e2, "h": 1.02e3}


def read_rho(vti):
    """Density of a grid frame (cell data) as rows y, columns x."""
    head = Path(vti).read_bytes()[:2048].decode("ascii", "replace")
    ext = [int(v) for v in re.search(r'WholeExtent="([^"]+)"', head).group(1).split()]
    rho = read_vtk_arrays(str(vti))["rho"].astype(float)
    cells = (ext[3], ext[1]) if rho.size == ext[3] * ext[1] else (ext[3] + 1, ext[1] + 1)
    return rho.reshape(cells)


def load(folder):
    """One run: its case values, series and derived measures."""
    folder_run = Run.open(folder)
    cfg, s = folder_run.config, folder_run.series
    run = {"folder": folder, "K": cfg["model"]["K"], "n": cfg["grid"]["nx"], "dt": cfg["run"]["dt"],
           "noise": cfg["initial"]["noise"], "T0": cfg["initial"]["T"],
           "wavelength": cfg["initial"].get("noise_wavelength", 0.0), "series": s,
           "threshold": cfg.get("output", {}).get("threshold", cfg["initial"]["rho0"])}
    t = s["time"]
    i = int(np.argmax(s["D"]))  # first maximum
    run.update(t_SD=t[i], D_max=s["D"][i], R_SD=s["R"][i], t_end=t[-1])
    run["t_DF"] = t[int(np.argmax(s["D_force"]))]
    run["L_peaks"] = {run["threshold"]: t[int(np.argmax(s["L"]))]}
    for name in s.dtype.names:
        if name.startswith("L_rho"):
            run["L_peaks"][float(name[5:])] = t[int(np.argmax(s[name]))] if s[name].max() > 0 else float("nan")
    run["u_DG"] = u_dg(run, t[-1])
    run["energy_drift"] = energy_drift(run, t[-1])
    return run


def energy_drift(run, t_end):
    """(e_T(t_end) − e_T(0))/|e_T(0)|: what the state filter took (e_T is conserved otherwise)."""
    s = run["series"]
    e = s["energy_per_length" if "energy_per_length" in s.dtype.names else "energy"]  # the older runs: energy
    return (e[s["time"] <= t_end + 1e-9][-1] - e[0]) / abs(e[0])


def u_dg(run, t_end):
    """Least-squares slope of R(t) over [t_SD, t_end] (the domain-growth stage)."""
    s = run["series"]
    grow = (s["time"] >= run["t_SD"]) & (s["time"] <= t_end + 1e-9)
    return np.polyfit(s["time"][grow], s["R"][grow], 1)[0] if grow.sum() >= 3 else float("nan")


def group(runs_dir, name):
    d = runs_dir / name
    if not (d / "sweep.csv").is_file():
        return []
    # a run stopped by a signal (checkpoint written, resumable) is tabulated up to its end t
    return [load(d / r["folder"]) for r in read_csv(d / "sweep.csv") if r["status"] in ("finished", "stopped")]


def fits(runs):
    """Coefficients of eqs. 36, 37 and 34 over the runs (least squares)."""
    K = np.array([r["K"] for r in runs])
    out = {}
    out["b"], out["a"] = np.polyfit(K, [r["t_SD"] for r in runs], 1)
    out["d"], out["c"] = np.polyfit(K ** -0.5, [r["D_max"] for r in runs], 1)
    if len(runs) >= 5:  # u_DG = e + fK − (gK)² + (hK)³: a cubic in K (4 coefficients)
        p3, p2, p1, p0 = np.polyfit(K, [r["u_DG"] for r in runs], 3)
        out.update(e=p0, f=p1, g2=-p2, h3=p3)
    return out


def fit_text(f):
    t = (f"eq. 36 t_SD = a + bK: a = {f['a']:.3f}, b = {f['b']:.3g} (paper 0.066, 1.51e3); "
         f"eq. 37 D_max = c + dK^-0.5: c = {f['c']:.3f}, d = {f['d']:.3g} (paper -0.073, 3.30e-3)")
    if "e" in f:
        g = f"g = {np.sqrt(f['g2']):.3g}" if f["g2"] > 0 else f"(gK)² coefficient {-f['g2']:.3g} (> 0: g imaginary)"
        t += (f"; eq. 34 u_DG = e + fK - (gK)^2 + (hK)^3: e = {f['e']:.3g}, f = {f['f']:.3g}, {g}, "
              f"h = {np.cbrt(f['h3']):.3g} (paper 0.00764, 151, 806, 1020)")
    return t


def table(runs, title):
    levels = sorted({lv for r in runs for lv in r["L_peaks"]})
    columns = (["K", "grid", "t_SD", "R_SD", "D_max", "u_DG", "peak of D^F at t"]
               + [f"peak of L(ρ_th={lv:g}) at t" for lv in levels] + ["end t", "Δe_T/\\|e_T(0)\\| at end"])
    lines = [f"### {title}", "", "| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    for r in sorted(runs, key=lambda r: (r["K"], r["n"])):
        peaks = " | ".join(f"{r['L_peaks'].get(lv, float('nan')):.3f}" for lv in levels)
        lines.append(f"| {r['K']:g} | {r['n']}² | {r['t_SD']:.3f} | {r['R_SD']:.4f} | {r['D_max']:.4f} | "
                     f"{r['u_DG']:.4f} | {r['t_DF']:.3f} | {peaks} | {r['t_end']:.2f} | {r['energy_drift']:+.4f} |")
    return lines + [""]


def nearest_frame(run, t):
    return min(read_pvd(run["folder"] / "grid.pvd"), key=lambda x: abs(x[0] - t))


def fig63(study, out):
    """Fig. 63: density at three stages for K = 1e-5, 3e-5, 6e-5 (columns)."""
    picks = [r for K in (1e-5, 3e-5, 6e-5) for r in study if np.isclose(r["K"], K)]
    if not picks:
        return
    fig, ax = plt.subplots(3, len(picks), figsize=(2.8 * len(picks), 8.2), squeeze=False)
    for c, r in enumerate(picks):
        for row, t in enumerate((0.5 * r["t_SD"], r["t_SD"], r["t_end"])):
            tf, f = nearest_frame(r, t)
            ax[row][c].imshow(read_rho(f), origin="lower", cmap="viridis", vmin=0.2, vmax=1.9)
            ax[row][c].set_xticks([]), ax[row][c].set_yticks([])
            ax[row][c].set_title(f"K={r['K']:g} ({r['n']}²), t={tf:.2f}", fontsize=8)
    fig.suptitle("density at t_SD/2, t_SD and the end of the run (Fig. 63: t = 0.045, 0.153, 4)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=60)


def fig64(study, f, out):
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(study)))
    for r, col in zip(study, colours):  # (a) R(t) with t_SD marked
        s = r["series"]
        ax[0][0].plot(s["time"], s["R"], color=col, label=f"K={r['K']:g}, u_DG={r['u_DG']:.3f}")
        ax[0][0].plot(r["t_SD"], r["R_SD"], "v", color=col)
    ax[0][0].set(xlabel="t", ylabel="R = 2π/k1", title="(a) domain size R(t); ▼ end of SD (t_SD, R_SD)")
    first = min(study, key=lambda r: r["K"])  # (b) L and the TNE of the smallest K
    s = first["series"]
    b2 = ax[0][1].twinx()
    for name in [n for n in s.dtype.names if n == "L" or n.startswith("L_rho")]:
        lv = first["threshold"] if name == "L" else float(name[5:])
        ax[0][1].plot(s["time"], s[name], label=f"L, ρ_th={lv:g}")
    for name, style in (("D", "k-"), ("D_force", "k--"), ("D_gradient", "k:")):
        b2.plot(s["time"], s[name], style, label=name)
    ax[0][1].set(xlabel="t", ylabel="L", title=f"(b) K={first['K']:g} ({first['n']}²): L(t) and D, D^F, D^G")
    ax[0][1].legend(fontsize=7, loc="upper right"), b2.legend(fontsize=7, loc="center right")
    c2 = ax[1][0].twinx()  # (c) L(t) and D^F(t) per K
    for r, col in zip(study, colours):
        s = r["series"]
        ax[1][0].plot(s["time"], s["L"], color=col, label=f"{r['K'] * 1e5:g}")
        c2.plot(s["time"][::5], s["D_force"][::5], "o", ms=2.5, color=col)
    ax[1][0].set(xlabel="t", ylabel=f"L (solid, ρ_th={first['threshold']:g})",
                 title="(c) L(t) and D^F(t) (dots), labels K/1e-5")
    c2.set_ylabel("D^F")
    ax[1][0].legend(fontsize=7, ncol=2)
    K = np.array([r["K"] for r in study])  # (d) t_SD and D_max against K with eqs. 36, 37
    kk = np.linspace(K.min(), K.max(), 100)
    ax[1][1].plot(K, [r["t_SD"] for r in study], "o", label="t_SD (peak of D)")
    ax[1][1].plot(kk, f["a"] + f["b"] * kk, "-", label=f"a+bK: a={f['a']:.3f}, b={f['b']:.3g}")
    ax[1][1].plot(kk, PAPER["a"] + PAPER["b"] * kk, ":", color="C0", label="paper eq. 36")
    d2 = ax[1][1].twinx()
    d2.plot(K, [r["D_max"] for r in study], "s", color="C3", label="D_max")
    d2.plot(kk, f["c"] + f["d"] * kk ** -0.5, "-", color="C3", label=f"c+dK^-1/2: c={f['c']:.3f}, d={f['d']:.3g}")
    d2.plot(kk, PAPER["c"] + PAPER["d"] * kk ** -0.5, ":", color="C3", label="paper eq. 37")
    ax[1][1].set(xlabel="K", ylabel="t_SD", title="(d) t_SD and D_max against K (dotted: the paper's fits)")
    d2.set_ylabel("D_max")
    ax[1][1].legend(fontsize=7, loc="upper left"), d2.legend(fontsize=7, loc="upper right")
    ax[0][0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(out, dpi=70)


def main():
    runs_dir = Path(sys.argv[1])
    study = group(runs_dir, "study64") + group(runs_dir, "study128")
    study.sort(key=lambda r: r["K"])
    f = fits(study)
    lines = ["## The study (Δx = 1/64; K = 1e-5 on 1/128)", ""] + table(study, "per K") + [fit_text(f), ""]
    conv = [r for d in sorted(runs_dir.glob("conv*")) for r in group(runs_dir, d.name)]
    if conv:  # u_DG of a K over the window all its grids ran: [t_SD, their shortest end]
        rows = []
        for K in sorted({r["K"] for r in conv}):
            same = [r for r in conv + study if np.isclose(r["K"], K)]
            end = min(r["t_end"] for r in same)
            rows += [dict(r, u_DG=u_dg(r, end), energy_drift=energy_drift(r, end)) for r in same]
        lines += table(rows, "convergence in Δx (the same band-limited noise on every grid; u_DG over [t_SD, end of "
                             "the shortest run of that K], Δe_T at that end)")
    for d in sorted(p for p in runs_dir.iterdir() if (p / "sweep.csv").is_file()):
        if d.name in ("study64", "study128") or d.name.startswith("conv"):
            continue
        other = group(runs_dir, d.name)
        if len(other) >= 2:
            same = [r for r in study if r["n"] == 64 and any(np.isclose(r["K"], o["K"]) for o in other)]
            lines += table(other, f"sensitivity: {d.name}") + [f"fits of {d.name}: " + fit_text(fits(other)), ""]
            if len(same) >= 2:
                lines += [f"the study's fits over the same K: " + fit_text(fits(same)), ""]
    (HERE / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    fig63(study, HERE / "fig63.png")
    fig64(study, f, HERE / "fig64.png")


if __name__ == "__main__":
    main()
