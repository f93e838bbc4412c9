#!/usr/bin/env python3
"""Tables and pictures of the phase-separation study (Xu et al. 2015, §4.3, Figs. 63-64, eqs. 34-37).

usage: plot.py RUNS
RUNS holds the sweep folders of run.sh (each with sweep.csv and one run folder per K):
  study64/      the K sweep on 64² (the main table, with study128/ for K = 1e-5)
  study128/     the K that need Δx = 1/128
  conv<n>/      the convergence runs on n² (optional)
  box<n>*/      the same case in a box n times as large, same Δx and noise wavelength, and box1_seed<s>/
                with another noise seed (the spread of the realisations; optional)
  <other>/      sensitivity sweeps (noise amplitude, quench, noise wavelength; optional)
Writes table.md (per K: t_SD, R_SD, D_max, u_DG, the peaks of L(t) and D^F(t); the fits of eqs. 34,
36, 37 beside the paper's; the convergence, window, sensitivity and box tables), fig63.png, fig64.png
and, with box<n>/, figbox.png.

Definitions (README): t_SD = time of the peak of D(t) (eq. 35 of Δ*); R_SD = R(t_SD) with R = 2π/k₁
(first moment of the structure factor); D_max = D(t_SD); u_DG = dR/dt in the early domain-growth
stage, the least-squares slope of R(t) over [t_SD, t_SD + 0.5] (the paper: "the slope of the R(t)
curve presents a phase separation speed u_DG for the domain growth stage"). u_DG and its window are
the run's own (summary.csv, written by shockfield: [output] growth_window); the other windows of the
window table are recomputed here with the same least squares, checked against the run's at 0.5.
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
WINDOWS = (0.25, 0.5, 1.0, 1.5, None)  # u_DG windows [t_SD, t_SD + Δ] of the window table; None: [t_SD, t_end]


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
           "box": cfg["grid"]["nx"] * cfg["grid"]["dx"], "seed": cfg["initial"]["seed"],
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
    summary = read_csv(Path(folder) / "summary.csv")  # the run's own t_SD and u_DG (shockfield, write_phase_summary)
    if "u_DG" not in summary.dtype.names:
        sys.exit(f"{folder}/summary.csv has no u_DG: written by an older shockfield; rewrite it with "
                 f"`shockfield run <case> --output {folder} --resume` (a finished run: the summary only)")
    assert np.isclose(summary["t_SD"][0], run["t_SD"], rtol=0, atol=1e-9), folder
    run.update(u_DG=summary["u_DG"][0], t_DG=(summary["t_DG_begin"][0], summary["t_DG_end"][0]))
    window = cfg.get("output", {}).get("growth_window", 0.5)
    assert np.isclose(u_dg(run, window), run["u_DG"], rtol=1e-6), (folder, u_dg(run, window), run["u_DG"])
    run["energy_drift"] = energy_drift(run, t[-1])
    return run


def energy_drift(run, t_end):
    """(e_T(t_end) − e_T(0))/|e_T(0)|: what the state filter took (e_T is conserved otherwise)."""
    s = run["series"]
    e = s["energy_per_length" if "energy_per_length" in s.dtype.names else "energy"]  # the older runs: energy
    return (e[s["time"] <= t_end + 1e-9][-1] - e[0]) / abs(e[0])


def u_dg(run, window=None):
    """Least-squares slope of R(t) over [t_SD, t_SD + window] (None: to the run's end), cut at its end."""
    s = run["series"]
    t_end = run["t_end"] if window is None else run["t_SD"] + window
    grow = (s["time"] >= run["t_SD"] - 1e-9) & (s["time"] <= t_end + 1e-9)
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
    if len(runs) >= 5:
        out.update(eq34_fit(K, [r["u_DG"] for r in runs]))
    return out


def eq34_fit(K, u):
    """u_DG = e + fK − (gK)² + (hK)³ (eq. 34): a cubic in K, least squares; g², h³ as fitted."""
    p3, p2, p1, p0 = np.polyfit(K, u, 3)
    return dict(e=p0, f=p1, g2=-p2, h3=p3)


def eq34_text(f):
    g = f"g = {np.sqrt(f['g2']):.3g}" if f["g2"] > 0 else f"(gK)² coefficient {-f['g2']:.3g} (> 0: g imaginary)"
    return f"e = {f['e']:.3g}, f = {f['f']:.3g}, {g}, h = {np.cbrt(f['h3']):.3g}"


def eq34_leave_one_out(runs):
    """How well the points determine the eq. 34 cubic: its coefficients with each K left out in turn."""
    K, u = np.array([r["K"] for r in runs]), np.array([r["u_DG"] for r in runs])
    lines = [f"eq. 34 with one K left out (u_DG mean {u.mean():.4f}, standard deviation {u.std():.4f}):", ""]
    for i in range(len(K)):
        keep = np.arange(len(K)) != i
        lines.append(f"- without K = {K[i]:g}: {eq34_text(eq34_fit(K[keep], u[keep]))}")
    return lines + [""]


def fit_text(f):
    t = (f"eq. 36 t_SD = a + bK: a = {f['a']:.3f}, b = {f['b']:.3g} (paper 0.066, 1.51e3); "
         f"eq. 37 D_max = c + dK^-0.5: c = {f['c']:.3f}, d = {f['d']:.3g} (paper -0.073, 3.30e-3)")
    if "e" in f:
        t += f"; eq. 34 u_DG = e + fK - (gK)^2 + (hK)^3: {eq34_text(f)} (paper 0.00764, 151, 806, 1020)"
    return t


def table(runs, title):
    levels = sorted({lv for r in runs for lv in r["L_peaks"]})
    columns = (["K", "grid", "t_SD", "R_SD", "D_max", "u_DG", "u_DG over t", "peak of D^F at t"]
               + [f"peak of L(ρ_th={lv:g}) at t" for lv in levels] + ["end t", "Δe_T/\\|e_T(0)\\| at end"])
    lines = [f"### {title}", "", "| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    for r in sorted(runs, key=lambda r: (r["K"], r["n"])):
        peaks = " | ".join(f"{r['L_peaks'].get(lv, float('nan')):.3f}" for lv in levels)
        lines.append(f"| {r['K']:g} | {r['n']}² | {r['t_SD']:.3f} | {r['R_SD']:.4f} | {r['D_max']:.4f} | "
                     f"{r['u_DG']:.4f} | {r['t_DG'][0]:.2f}–{r['t_DG'][1]:.2f} | {r['t_DF']:.3f} | {peaks} | {r['t_end']:.2f} | {r['energy_drift']:+.4f} |")
    return lines + [""]


def window_name(w):
    return "[t_SD, t_end]" if w is None else f"[t_SD, t_SD+{w:g}]"


def window_tables(study, conv):
    """u_DG per window: over the study's K with the eq. 34 fit of each window, and across the grids of
    each K that has convergence runs (a window the shorter runs do not reach is left out: '—')."""
    head = "| K | grid | " + " | ".join(f"u_DG {window_name(w)}" for w in WINDOWS) + " |"
    rule = "|" + "---|" * (2 + len(WINDOWS))
    row = lambda r, cells: f"| {r['K']:g} | {r['n']}² | " + " | ".join(cells) + " |"
    lines = ["### u_DG by window (the study; the run's own is [t_SD, t_SD+0.5])", "", head, rule]
    lines += [row(r, [f"{u_dg(r, w):.4f}" for w in WINDOWS]) for r in study]
    lines += ["", "eq. 34 fitted per window (paper e = 0.00764, f = 151, g = 806, h = 1020):", ""]
    K = np.array([r["K"] for r in study])
    lines += [f"- {window_name(w)}: {eq34_text(eq34_fit(K, [u_dg(r, w) for r in study]))}" for w in WINDOWS]
    lines += ["", "### u_DG by window across the grids (convergence; '—': a run ends inside the window)", "",
              head, rule]
    for K_conv in sorted({r["K"] for r in conv}):
        same = sorted((r for r in conv + study if np.isclose(r["K"], K_conv)), key=lambda r: r["n"])
        reached = lambda w: (all(r["t_end"] >= r["t_SD"] + w - 1e-9 for r in same) if w is not None
                             else np.ptp([r["t_end"] for r in same]) < 1e-6)  # [t_SD, t_end]: one end for all
        lines += [row(r, [f"{u_dg(r, w):.4f}" if reached(w) else "—" for w in WINDOWS]) for r in same]
    return lines + [""]


def box_table(box_runs, study):
    """The box-size check: each run of a larger box (or of box 1 with another noise seed, the spread of
    the realisations) beside the study's run of its K (same Δx, same noise wavelength), with the relative
    differences of R_SD, D_max and u_DG and the shifts of the times."""
    columns = ["K", "box", "seed", "grid", "t_SD", "R_SD", "R_SD/box", "D_max", "u_DG", "peak of D^F at t",
               "peak of L(ρ_th=1.2) at t", "peak of L(ρ_th=1.4) at t"]
    lines = ["### box size and noise seed (the same Δx = 1/64 and noise wavelength 1/16; the study: box 1, seed 7)", "",
             "| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    cells = lambda r: [f"{r['K']:g}", f"{r['box']:g}", f"{r['seed']}", f"{r['n']}²", f"{r['t_SD']:.3f}", f"{r['R_SD']:.4f}",
                       f"{r['R_SD'] / r['box']:.3f}", f"{r['D_max']:.4f}", f"{r['u_DG']:.4f}", f"{r['t_DF']:.3f}",
                       f"{r['L_peaks'].get(1.2, float('nan')):.3f}", f"{r['L_peaks'].get(1.4, float('nan')):.3f}"]
    notes, tabulated = [], []
    for big in sorted(box_runs, key=lambda r: (r["K"], r["box"])):
        base = [r for r in study if np.isclose(r["K"], big["K"]) and np.isclose(r["box"] / r["n"], big["box"] / big["n"])]
        shown = any(np.isclose(big["K"], r["K"]) for r in tabulated)  # the study's row once per K
        tabulated += [big]
        lines += ["| " + " | ".join(cells(r)) + " |" for r in ([] if shown else base[:1]) + [big]]
        if base:
            b = base[0]
            rel = lambda key: f"{(big[key] - b[key]) / b[key]:+.1%}"
            notes.append(f"- K = {big['K']:g}, box {big['box']:g} seed {big['seed']} against the study: t_SD {big['t_SD'] - b['t_SD']:+.2f}, "
                         f"R_SD {rel('R_SD')}, D_max {rel('D_max')}, u_DG {rel('u_DG')}, peak of D^F "
                         f"{big['t_DF'] - b['t_DF']:+.2f}, peak of L(1.2) {big['L_peaks'][1.2] - b['L_peaks'][1.2]:+.2f}")
    return lines + [""] + notes + [""]


def fig_box(box_runs, study, out):
    """R(t), D(t) and L(t) per unit area (ρ_th = 1.2) of the larger box and of the other seed beside the study's."""
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    colour = {K: f"C{i}" for i, K in enumerate(sorted({r["K"] for r in box_runs}))}
    base = [(b, "-") for b in study if b["K"] in colour]
    for r, style in base + [(r, "--" if r["box"] > 1 else ":") for r in box_runs]:
        s, col, label = r["series"], colour[r["K"]], f"K={r['K']:g}, box {r['box']:g}, seed {r['seed']}"
        ax[0].plot(s["time"], s["R"], style, color=col, label=label)
        ax[1].plot(s["time"], s["D"], style, color=col, label=label)
        ax[2].plot(s["time"], s["L"] / r["box"] ** 2, style, color=col, label=label)
    for a, name in zip(ax, ("R = 2π/k1", "D (eq. 35)", "L(ρ_th=1.2) per unit area")):
        a.set(xlabel="t", ylabel=name, title=name)
        a.legend(fontsize=7)
    fig.suptitle("box 1, seed 7 (the study: solid), box 1, seed 8 (dotted), box 2, seed 7 (dashed); Δx = 1/64", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=60)


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


def growth_line(ax, r, **style):
    """The least-squares line of u_DG over the run's window, drawn on that window."""
    s = r["series"]
    t0, t1 = r["t_DG"]
    inside = (s["time"] >= t0 - 1e-9) & (s["time"] <= t1 + 1e-9)
    t, R = s["time"][inside], s["R"][inside]
    ax.plot([t0, t1], R.mean() + r["u_DG"] * (np.array([t0, t1]) - t.mean()), **style)


def fig64(study, conv, f, out):
    fig, ax = plt.subplots(2, 3, figsize=(16, 8))
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(study)))
    for r, col in zip(study, colours):  # (a) R(t) with t_SD marked and u_DG's line on its window
        s = r["series"]
        ax[0][0].plot(s["time"], s["R"], color=col, label=f"K={r['K']:g}, u_DG={r['u_DG']:.3f}")
        ax[0][0].plot(r["t_SD"], r["R_SD"], "v", color=col)
        growth_line(ax[0][0], r, color="k", lw=2.5, ls="--")
    ax[0][0].set(xlabel="t", ylabel="R = 2π/k1",
                 title="(a) R(t); ▼ (t_SD, R_SD); dashed: u_DG over [t_SD, t_SD+0.5]")
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
    u_dg_panel(ax[0][2], study)
    k5 = sorted((r for r in conv + study if np.isclose(r["K"], 1e-5)), key=lambda r: r["n"])
    for r in k5:  # (f) the smallest K on every grid: where the runs part, and the window before it
        line = ax[1][2].plot(r["series"]["time"], r["series"]["R"], label=f"{r['n']}², u_DG = {r['u_DG']:.4f}")[0]
        growth_line(ax[1][2], r, color=line.get_color(), lw=2.5, ls="--")
    if k5:
        ax[1][2].axvspan(*k5[-1]["t_DG"], color="0.9")
    ax[1][2].set(xlabel="t", ylabel="R", title="(f) K = 1e-5 on 64²–160²; grey: u_DG window")
    ax[1][2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=70)


def u_dg_panel(ax, study):
    """(e) u_DG against K, the run's window and the former [t_SD, t_end], with eq. 34 fitted to each."""
    K = np.array([r["K"] for r in study])
    kk = np.linspace(K.min(), K.max(), 200)
    for w, style, name in ((0.5, "o", "u_DG [t_SD, t_SD+0.5] (the run's)"), (None, "s", "u_DG [t_SD, 4] (former)")):
        u = [r["u_DG"] if w == 0.5 else u_dg(r, w) for r in study]
        f = eq34_fit(K, u)
        col = ax.plot(K, u, style, mfc="none" if w is None else None, label=name)[0].get_color()
        ax.plot(kk, f["e"] + f["f"] * kk - f["g2"] * kk ** 2 + f["h3"] * kk ** 3, "-", color=col, label="eq. 34 fitted")
    P = PAPER
    ax.plot(kk, P["e"] + P["f"] * kk - (P["g"] * kk) ** 2 + (P["h"] * kk) ** 3, "k:", label="paper eq. 34")
    ax.set(xlabel="K", ylabel="u_DG", ylim=(0, 0.085), title="(e) u_DG against K with eq. 34 (dotted: the paper's)")
    ax.legend(fontsize=6, ncol=2, loc="upper center")


def main():
    runs_dir = Path(sys.argv[1])
    study = group(runs_dir, "study64") + group(runs_dir, "study128")
    study.sort(key=lambda r: r["K"])
    f = fits(study)
    lines = ["## The study (Δx = 1/64; K = 1e-5 on 1/128)", ""] + table(study, "per K") + [fit_text(f), ""] + eq34_leave_one_out(study)
    conv = [r for d in sorted(runs_dir.glob("conv*")) for r in group(runs_dir, d.name)]
    if conv:  # Δe_T of a K at the end all its grids ran to; u_DG the run's own
        rows = []
        for K in sorted({r["K"] for r in conv}):
            same = [r for r in conv + study if np.isclose(r["K"], K)]
            end = min(r["t_end"] for r in same)
            rows += [dict(r, energy_drift=energy_drift(r, end)) for r in same]
        lines += table(rows, "convergence in Δx (the same band-limited noise on every grid; Δe_T at the end of the "
                             "shortest run of that K)")
    lines += window_tables(study, conv)
    for d in sorted(p for p in runs_dir.iterdir() if (p / "sweep.csv").is_file()):
        if d.name in ("study64", "study128") or d.name.startswith(("conv", "box")):
            continue
        other = group(runs_dir, d.name)
        if len(other) >= 2:
            same = [r for r in study if any(np.isclose(r["K"], o["K"]) and r["n"] == o["n"] for o in other)]
            lines += table(other, f"sensitivity: {d.name}") + [f"fits of {d.name}: " + fit_text(fits(other)), ""]
            if len(same) >= 2:
                lines += ["the study's fits over the same K: " + fit_text(fits(same)), ""]
    boxes = [r for d in sorted(runs_dir.glob("box*")) for r in group(runs_dir, d.name)]
    if boxes:
        lines += box_table(boxes, study)
        fig_box(boxes, study, HERE / "figbox.png")
    (HERE / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    fig63(study, HERE / "fig63.png")
    fig64(study, conv, f, HERE / "fig64.png")


if __name__ == "__main__":
    main()
