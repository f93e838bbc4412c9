#!/usr/bin/python3
"""Plots of an MPM run folder written by `shockfield run` (method = "mpm").

  python3 -m shockfield_plot.mpm_plots porous RUN_DIR [--out FILE]
      bottom-window means of density, pressure, temperature and u_y against time (Xu et al. (2015) Fig 19)
      with Xu et al.'s (2015) values at 250 ns when the run is their case, and the particles'
      temperature at the last frame
  python3 -m shockfield_plot.mpm_plots cavity RUN_DIR [RUN_DIR ...] [--out FILE]
      per run: particles around the cavity coloured by temperature at the last frame, and the
      cavity area and collapsibility against time (Xu et al. (2015) Figs 46, 50, 53)

Reads series.csv, config.resolved.toml and particles.pvd through shockfield.run.Run. Uses only
numpy and matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402

# Xu et al. (2015) §4.1.1, Fig 19: the bottom window (h = 800 µm) at 250 ns of porous aluminium
# (their §4.1 parameters, Δ = 0.029) driven at 1000 m/s against a rigid wall.
SEED_250NS = {"density_mean_kg_m3": 3140.0, "pressure_mean_Pa": 16.7e9, "temperature_mean_K": 432.0}
SEED_CASE = {"library": "aluminium_seed000", "porosity": 0.029, "speed": 1000.0}


def last_frame(run):
    """(time, particles) of the last particle frame of the Run `run`."""
    frame = run.last_frame(kind="particles")
    return frame.time, frame.data


def porous_case(run):
    """(material, porosity, void radius, speed, loading type) of the run's first body."""
    c = run.config
    body = c["body"][0]
    material = next((m for m in c["material"] if m["name"] == body["material"]), {})
    return (material.get("library", body["material"]), body.get("porosity", 0.0), body.get("void_radius", 0.0),
            c["loading"].get("speed", 0.0), c["loading"].get("type", ""))


def porous(run, out):
    run = Run.open(run)
    s = run.series
    t_ns = s["time_s"] * 1e9
    heights = sorted({k.split("_")[1] for k in s.dtype.names if k.startswith("bottom_h") and k.endswith("_count")},
                     key=lambda h: -float(h[1:-2]))
    material, porosity, radius, speed, loading = porous_case(run)
    seed_case = (material == SEED_CASE["library"] and abs(porosity - SEED_CASE["porosity"]) < 1e-9
                 and speed == SEED_CASE["speed"] and loading == "wall" and "h800um" in heights)
    # series.csv window means, each named with its unit (docs/conventions.md): <where>_<h>_<q>_mean_<unit>
    panels = [("density_mean_kg_m3", 1e-3, "density (g/cm³)"), ("pressure_mean_Pa", 1e-9, "pressure (GPa)"),
              ("temperature_mean_K", 1.0, "temperature (K)"), ("vy_mean_m_s", 1.0, "v_y (m/s)")]
    fig, axes = plt.subplots(2, 3, figsize=(13, 7))
    for ax, (q, scale, label) in zip(axes.flat, panels):
        for h in heights:
            ax.plot(t_ns, s[f"bottom_{h}_{q}"] * scale, label=f"bottom, h = {h[1:-2]} µm")
            ax.plot(t_ns, s[f"top_{h}_{q}"] * scale, ls=":", lw=1, label=f"top, h = {h[1:-2]} µm")
        if seed_case and q in SEED_250NS:
            ax.plot([250], [SEED_250NS[q] * scale], "k*", ms=12, label="Xu et al. (2015) Fig 19, h = 800 µm")
        ax.set_xlabel("t (ns)")
        ax.set_ylabel(label)
    axes[0, 0].legend(fontsize="x-small")
    t, f = last_frame(run)
    axes[1, 1].remove()
    axes[1, 2].remove()
    ax = fig.add_subplot(2, 3, (5, 6))
    x, y = f["points"][:, 0] * 1e3, f["points"][:, 1] * 1e3
    sc = ax.scatter(y, x, c=f["temperature"], s=0.05, cmap="inferno", vmin=300, vmax=900, rasterized=True)
    ax.set_aspect("equal")
    ax.set_xlabel("y (mm), wall at y = 0")
    ax.set_ylabel("x (mm)")
    ax.set_title(f"temperature at t = {t * 1e9:.0f} ns")
    fig.colorbar(sc, ax=ax, label="T (K)", shrink=0.7)
    against = "on a rigid wall" if loading == "wall" else f"({loading})"
    fig.suptitle(f"{run.folder.name} ({run.case_name}): porous {material}, Δ = {porosity:g}, r = {radius * 1e6:g} µm, "
                 f"{speed:g} m/s {against}")
    fig.tight_layout()
    fig.savefig(out, dpi=130)


def cavity(runs, out):
    fig, axes = plt.subplots(1, len(runs) + 1, figsize=(4.2 * (len(runs) + 1), 4.6))
    for ax, run in zip(axes, map(Run.open, runs)):
        s = run.series
        t, f = last_frame(run)
        p = f["points"] * 1e6
        sel = p[:, 1] < p[:, 1].max() / 2  # the lower body, where the tracked cavity is
        sc = ax.scatter(p[sel, 0], p[sel, 1], c=f["temperature"][sel], s=0.3, cmap="inferno", vmin=300,
                        vmax=max(400, np.percentile(f["temperature"][sel], 99.5)), rasterized=True)
        ax.set_aspect("equal")
        ax.set_xlabel("x (µm)")
        ax.set_ylabel("y (µm)")
        ax.set_title(f"{run.folder.name}: t = {t * 1e9:.1f} ns\n"
                     f"Φ = {s['collapsibility'][-1]:.2f}", fontsize="small")
        fig.colorbar(sc, ax=ax, label="T (K)", shrink=0.7)
        axes[-1].plot(s["time_s"] * 1e9, s["collapsibility"], label=run.folder.name)
    axes[-1].set_xlabel("t (ns)")
    axes[-1].set_ylabel("collapsibility Φ = (A0 − A)/A0")
    axes[-1].legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(out, dpi=130)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["porous", "cavity"])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    out = a.out or os.path.join(a.runs[0], f"{a.kind}.png")
    if a.kind == "porous":
        porous(a.runs[0], out)
    else:
        cavity(a.runs, out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
