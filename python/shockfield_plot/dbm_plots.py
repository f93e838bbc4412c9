#!/usr/bin/python3
"""Figures of discrete Boltzmann run folders (docs/dbm.md), used by `shockfield plot`.

  python3 -m shockfield_plot.dbm_plots profiles RUN_DIR [--out FILE]
      rho, u_x (u_y when ny > 1), p, T (and the reaction progress lambda of a [reaction] run)
      along x on the profile row at up to six of the run's profile times, with the exact star
      state of a Riemann run (Sod: [derived] exact_*) and the von Neumann and CJ pressures of a
      detonation as dashed levels -> RUN_DIR/profiles.png
  python3 -m shockfield_plot.dbm_plots tne RUN_DIR [--out FILE]
      the TNE measures the run writes: the domain mean of the TNE strength D against time
      (series.csv; a GLS run also its force part D_force), and Δ*_2xx and Δ*_(3,1)x along x at
      the profile times -> RUN_DIR/tne.png
  python3 -m shockfield_plot.dbm_plots phase-separation RUN_DIR [--out FILE]
      a GLS run ([model] kind = "gls", Xu et al. (2015) §4.3, Figs. 63-64): the density at four
      frames (the one nearest t_SD/2, t_SD, 2 t_SD and the last; colour scale from the vapour to
      the liquid density of the Maxwell construction, [derived]), the boundary length L (at
      [output] threshold), the TNE strengths D and D_force and the domain size R against time,
      t_SD (the peak of D, summary.csv) dotted -> RUN_DIR/phase-separation.png

Reads everything through shockfield.run.Run; the density frames through the compiled module
(shockfield._core). Uses only numpy and matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402
from shockfield_plot.profile_plots import Panel, draw_profiles  # noqa: E402


def is_gls(run):
    return run.config.get("model", {}).get("kind") == "gls"


def _levels(run, names):
    """(label, value) of the [derived] values of `names` ({key: label}) the run has."""
    return [(label, run.derived[key]) for key, label in names.items() if key in run.derived]


def profiles(run, out):
    run = Run.open(run)
    ny = run.config.get("grid", {}).get("ny", 1)
    reaction = "reaction" in run.config
    panels = [Panel("rho", "density ρ", levels=_levels(run, {"exact_rho_star_left": "exact ρ*L",
                                                               "exact_rho_star_right": "exact ρ*R"})),
              Panel("vx", "velocity u_x", levels=_levels(run, {"exact_u_star": "exact u*"}))]
    if ny > 1:
        panels.append(Panel("vy", "velocity u_y"))
    panels += [Panel("p", "pressure p", levels=_levels(run, {"exact_p_star": "exact p*", "von_neumann_p": "p_vN",
                                                             "cj_p": "p_CJ"})),
               Panel("T", "temperature T")]
    if reaction:
        panels.append(Panel("lambda", "reaction progress λ"))
    draw_profiles(run, panels, "x", f"x (row j = {run.config.get('output', {}).get('profile_row', ny // 2)})", out,
                  title_what="profiles (lattice units)")


def tne(run, out):
    run = Run.open(run)
    panels = [Panel("D2xx", "Δ*_2xx (momentum flux)"), Panel("D31x", "Δ*_(3,1)x (energy flux)")]
    fig, (series_ax,) = draw_profiles(run, panels, "x", "x", out, title_what="TNE measures (lattice units)",
                                      extra_axes=1)
    s = run.series
    series_ax.plot(s["time"], s["D"], label="D (mean TNE strength)")
    if "D_force" in s.dtype.names:
        series_ax.plot(s["time"], s["D_force"], "--", label="D_force")
    series_ax.set(xlabel="t", ylabel="domain mean")
    series_ax.legend(fontsize="x-small")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def _picks(frames, t_sd):
    """The frames nearest t_SD/2, t_SD, 2 t_SD and the last one (four, repeats allowed)."""
    times = np.array([f.time for f in frames])
    return [frames[int(np.argmin(np.abs(times - t)))] for t in (0.5 * t_sd, t_sd, 2 * t_sd)] + [frames[-1]]


def phase_separation(run, out):
    run = Run.open(run)
    s, summary = run.series, run.table("summary")
    t_sd = float(summary["t_SD"][0])
    frames = list(run.frames(array="rho", kind="fields"))
    rho_v, rho_l = (run.derived.get(k) for k in ("gls_expected_rho_vapour", "gls_expected_rho_liquid"))
    fig = plt.figure(figsize=(14, 7))
    grid = fig.add_gridspec(2, 12, left=0.06, right=0.97, wspace=2.0, hspace=0.3)
    image, pictures = None, []
    for k, frame in enumerate(_picks(frames, t_sd)):
        ax = fig.add_subplot(grid[0, 3 * k:3 * k + 3])
        pictures.append(ax)
        image = ax.imshow(frame.data, origin="lower", cmap="viridis", vmin=rho_v, vmax=rho_l)
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(f"ρ at t = {frame.time:.3g}", fontsize="small")
    fig.colorbar(image, ax=pictures, shrink=0.8,
                 label="ρ (colour range: Maxwell ρ_v to ρ_l)" if rho_v is not None else "ρ")
    threshold = run.config.get("output", {}).get("threshold", run.config.get("initial", {}).get("rho0"))
    curves = [fig.add_subplot(grid[1, 4 * k:4 * k + 4]) for k in range(3)]
    curves[0].plot(s["time"], s["L"])
    curves[0].set(xlabel="t", ylabel=f"boundary length L (ρ = {threshold:g})")
    curves[1].plot(s["time"], s["D"], label="D")
    curves[1].plot(s["time"], s["D_force"], "--", label="D_force")
    curves[1].set(xlabel="t", ylabel="TNE strength (eq. 35)")
    curves[1].legend(fontsize="x-small")
    positive = (s["time"] > 0) & (s["R"] > 0)
    curves[2].loglog(s["time"][positive], s["R"][positive])
    curves[2].set(xlabel="t", ylabel="domain size R = 2π/k1")
    for ax in curves:
        ax.axvline(t_sd, color="grey", ls=":", lw=0.8)
    model = run.config.get("model", {})
    fig.suptitle(run.title(f"phase separation, K = {model.get('K', float('nan')):g}, "
                           f"T = {run.config.get('initial', {}).get('T', float('nan')):g}; dotted: t_SD = {t_sd:.3g}"))
    fig.savefig(out, dpi=90)
    plt.close(fig)


KINDS = {"profiles": profiles, "tne": tne, "phase-separation": phase_separation}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=list(KINDS))
    ap.add_argument("run")
    ap.add_argument("--out")
    a = ap.parse_args()
    out = a.out or os.path.join(a.run, f"{a.kind}.png")
    KINDS[a.kind](a.run, out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
