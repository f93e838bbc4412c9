#!/usr/bin/python3
"""Plots of PD run folders written by `shockfield run` (method = "pd").

  python3 -m shockfield_plot.pd_plots bar RUN_DIR [RUN_DIR ...] [--labels L ...] [--out FILE]
      axial compression -sigma_xx and plastic measure against x at every profile time, one
      column per run (Liu et al. 2025, Fig. 3), with the run's derived HEL and impact stress as dashed
      lines.

  python3 -m shockfield_plot.pd_plots profiles RUN_DIR [--out FILE]
      every displacement and velocity component and the damage against the reference x at up to
      six of the run's profile times (profiles/points.pvd; points of a 2D or 3D body as dots).

  python3 -m shockfield_plot.pd_plots crystal RUN_DIR [RUN_DIR ...] [--labels L ...] [--out FILE]
      at the last profile time: axial compression (Fig. 8/10) and accumulated slip (Fig. 11)
      against x of every run on shared axes, grains of a polycrystal as alternating stripes
      (Fig. 12); prints each run's HEL (the compression where the slip first exceeds 1e-5, 1e-4
      and 2% of its plateau, scanning from the resting end) and mean slip behind the plastic wave.

  python3 -m shockfield_plot.pd_plots compression RUN_DIR [RUN_DIR ...] [--labels L ...] [--out FILE]
      a [homogeneous] run (Liu et al. 2025, Fig. 5): every grain's axial compression against the
      compressive strain, the band mean ± SD, and the Taylor average (eq. 43); below, the
      soft-hard spread (max − min over the grains) and the SD against strain; prints the
      strains where the spread and the SD peak and where the spread first reaches 100 MPa.
      With --johnson-cook A,B,n,C (MPa, MPa, -, -), a Johnson-Cook flow curve (Johnson & Cook 1983)
      at the run's strain rate and room temperature is drawn beside it as a reference, labelled
      --reference-label, and a table of the ratios printed. Further runs add their Taylor average
      only (e.g. another hardening law).

  python3 -m shockfield_plot.pd_plots orientations RUN_DIR [--out FILE]
      a [homogeneous] run's grains (grain_summary.csv): the crystal direction along the loading
      axis before and after, in the standard stereographic triangle [001]-[101]-[111] (inverse
      pole figure; Liu et al. (2025) Fig. 5(a) shows the initial orientations); prints the mean angle from <110>.

  python3 -m shockfield_plot.pd_plots damage RUN_DIR [RUN_DIR ...] [--tips X,Y ...] [--labels L ...] [--out FILE]
      a 2D run's damage at the last profile time on the reference positions (mm); for each notch
      tip (m; by default the `to` end of each [[crack]] of the run), the angle of the crack it grew, from the notch direction +x: the principal
      direction through the tip of the points with damage >= 0.35 ahead of it (x > tip x), more
      than 1 mm off its line and within 25 mm (the Kalthoff-Winkler angle; prints and draws it,
      beside the experiment's ~70 deg, Kalthoff & Winkler 1988, dotted).

Reads profiles/index.csv, profiles/profile_<k>.csv and config.resolved.toml through
shockfield.run.Run. Uses only numpy and matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Frame, Run  # noqa: E402
from shockfield_plot.profile_plots import Panel, chosen_frames, draw_profiles  # noqa: E402


def bar(runs, labels, out):
    fig, axes = plt.subplots(2, len(runs), figsize=(5.5 * len(runs), 6), sharex="col", squeeze=False)
    for col, (run, label) in enumerate(zip(map(Run.open, runs), labels)):
        top, bottom = axes[0][col], axes[1][col]
        for frame in run.frames(kind="profiles"):
            t, p = frame.time, frame.data
            if t <= 0.0:
                continue
            top.plot(p["x_m"] * 1e3, -p["sxx_Pa"] / 1e6, label=f"{t * 1e9:.0f} ns")
            bottom.plot(p["x_m"] * 1e3, p["plastic"], label=f"{t * 1e9:.0f} ns")
        for key, name in (("hel_Pa", "HEL"), ("impact_axial_stress_Pa", "impact state")):
            v = run.value(key)
            if v is not None:
                top.axhline(v / 1e6, color="grey", ls="--", lw=0.8)
                top.annotate(f"{name} {v / 1e6:.1f} MPa", (0.01, v / 1e6), xycoords=("axes fraction", "data"),
                             fontsize="small", va="bottom")
        top.set_title(label)
        top.set_ylabel("axial compression  $-\\sigma_{xx}$ [MPa]")
        bottom.set_ylabel("equivalent plastic strain")
        bottom.set_xlabel("x [mm]")
        top.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def point_columns(frame):
    """A frame of profiles/points.pvd as profile columns: the reference x (m; the file holds
    x + u), the displacement and velocity components and the damage of every point."""
    p = frame.data
    u, v = p["displacement"].astype(float), p["velocity"].astype(float)
    columns = {"x_m": p["points"][:, 0] - u[:, 0]}
    columns.update({f"u{a}_m": u[:, k] for k, a in enumerate("xyz")})
    columns.update({f"v{a}_m_s": v[:, k] for k, a in enumerate("xyz")})
    columns["damage"] = p["damage"]
    table = np.empty(len(p), dtype=[(name, float) for name in columns])
    for name, values in columns.items():
        table[name] = values
    return Frame(time=frame.time, data=table, file=frame.file)


def profiles(runs, labels, out):
    """The first run's points (profiles/points.pvd, written with every profile): displacements
    (µm), velocities (m/s) and damage against the reference x; an impact's v/2 (the velocity
    behind the waves of two equal halves) dashed on vx."""
    run = Run.open(runs[0])
    loading = run.config.get("loading", {})
    half = [("impact speed / 2", loading["speed"] / 2)] if loading.get("type") == "impact" else []
    panels = ([Panel(f"u{a}_m", f"displacement u{a} (µm)", 1e6) for a in "xyz"]
              + [Panel(f"v{a}_m_s", f"velocity v{a} (m/s)", levels=half if a == "x" else []) for a in "xyz"]
              + [Panel("damage", "damage")])
    frames = [point_columns(frame) for frame in chosen_frames(run, kind="particles")]
    draw_profiles(run, panels, "x_m", "x (mm)", out, x_scale=1e3, time_unit="s", columns=3, frames=frames)


def last_profile(run):
    """(time, profile) of the last profile of the run folder `run`."""
    frame = Run.open(run).last_frame(kind="profiles")
    return frame.time, frame.data


def hel(p, threshold=1e-5):
    """Compression where the accumulated slip first exceeds `threshold` from the resting end."""
    for k in range(len(p["x_m"]) - 1, 0, -1):
        if p["plastic"][k] > threshold:
            return -p["sxx_Pa"][k]
    return float("nan")


def crossing(x, f, level):
    """x where f, scanning from the resting end (largest x), first reaches `level` (interpolated)."""
    for i in range(len(x) - 1, 0, -1):
        if f[i - 1] >= level > f[i] or f[i] >= level:
            if f[i] >= level:
                return x[i]
            return x[i] + (level - f[i]) * (x[i - 1] - x[i]) / (f[i - 1] - f[i])
    return x[0]


def plastic_front_width(p, hel_stress, plateau):
    """Distance between 10% and 90% of the plastic jump (HEL to the Hugoniot state) on the
    right-going wave."""
    x, s = p["x_m"], -p["sxx_Pa"]
    jump = plateau - hel_stress
    return crossing(x, s, hel_stress + 0.1 * jump) - crossing(x, s, hel_stress + 0.9 * jump)


def crystal(runs, labels, out):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    striped = False
    for run, label in zip(runs, labels):
        t, p = last_profile(run)
        x = p["x_m"] * 1e3
        middle = 0.5 * (x[0] + x[-1])
        loaded = (x > middle + 0.1 * (x[-1] - middle)) & (x < middle + 0.4 * (x[-1] - middle))
        slip = p["plastic"][loaded].mean()
        offset = hel(p, 0.02 * slip)
        state = -p["sxx_Pa"][loaded].mean()
        print(f"{label}: HEL {hel(p) / 1e6:.1f} MPa (threshold 1e-5), {hel(p, 1e-4) / 1e6:.1f} MPa (1e-4), "
              f"{offset / 1e6:.1f} MPa (2% of the plateau slip, an offset yield); Hugoniot state "
              f"{state / 1e6:.1f} MPa, plastic front 10-90% width "
              f"{plastic_front_width(p, offset, state) * 1e6:.0f} um; "
              f"mean slip behind the plastic wave {slip:.5f} (min {p['plastic'][loaded].min():.5f}, "
              f"max {p['plastic'][loaded].max():.5f}) at {t * 1e9:.0f} ns")
        top.plot(x, -p["sxx_Pa"] / 1e6, label=label)
        bottom.plot(x, p["plastic"], label=label)
        if p["grain"].max() > 0:
            striped = True
            edges = np.flatnonzero(np.diff(p["grain"])) + 1
            bounds = np.concatenate(([0], edges, [len(x) - 1]))
            for a, b, g in zip(bounds[:-1], bounds[1:], p["grain"][bounds[:-1]]):
                if g % 2:
                    bottom.axvspan(x[a], x[b], color="grey", alpha=0.15, lw=0)
    top.set_ylabel("axial compression  $-\\sigma_{xx}$ [MPa]")
    bottom.set_ylabel("accumulated slip $\\gamma_{tot}$")
    bottom.set_xlabel("x [mm]")
    top.legend(fontsize="small")
    note = " (grey stripes: alternate grains of the polycrystal)" if striped else ""
    top.set_title(f"t = {t * 1e9:.0f} ns{note}", fontsize="small")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def johnson_cook(parameters, plastic_strain, rate):
    """Johnson & Cook's flow stress at room temperature, sigma = (A + B eps_p^n)(1 + C ln(rate / 1 s^-1))
    (G. R. Johnson, W. H. Cook, Proc. 7th Int. Symp. on Ballistics, The Hague, 1983, pp. 541-547),
    in the unit of A and B; ``parameters`` (A, B, n, C)."""
    a, b, n, c = parameters
    return (a + b * plastic_strain ** n) * (1.0 + c * np.log(rate))


def compression(runs, labels, out, johnson_cook_mpa=None, reference_label=None):
    run = Run.open(runs[0])
    curve = run.table("stress_strain")
    grains = run.table("grains")
    eps = -curve["strain"]
    sigma = np.array([-grains[k] for k in grains.dtype.names if k.startswith("grain_")]) / 1e6
    taylor, sd = -curve["taylor_axial_Pa"] / 1e6, curve["grain_sd_Pa"] / 1e6
    spread = sigma.max(axis=0) - sigma.min(axis=0)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    for s in sigma:
        top.plot(eps, s, color="grey", lw=0.5, alpha=0.6)
    soft, hard = np.argmin(sigma[:, -1]), np.argmax(sigma[:, -1])
    top.plot(eps, sigma[soft], color="tab:green", lw=1.2, label="softest grain at the end")
    top.plot(eps, sigma[hard], color="tab:red", lw=1.2, label="hardest grain at the end")
    top.fill_between(eps, taylor - sd, taylor + sd, color="tab:blue", alpha=0.2, label="Taylor average ± SD")
    top.plot(eps, taylor, color="tab:blue", lw=2.2,
             label=f"Taylor average (eq. 43), {sigma.shape[0]} grains" + (f", {labels[0]}" if len(runs) > 1 else ""))
    others = [(label, -Run.open(r).table("stress_strain")["taylor_axial_Pa"] / 1e6)
              for r, label in zip(runs[1:], labels[1:])]
    for (label, other), color in zip(others, ("tab:orange", "tab:purple", "tab:brown")):
        top.plot(eps, other, color=color, lw=2.2, label=f"Taylor average, {label}")
    rate = abs(run.value("strain_rate"))
    if johnson_cook_mpa:
        top.plot(eps, johnson_cook(johnson_cook_mpa, eps, rate), color="k", ls="--", lw=1.5,
                 label=f"{reference_label or 'Johnson-Cook ' + ', '.join(f'{v:g}' for v in johnson_cook_mpa)}, {rate:g}/s")
    top.set_ylabel("axial compression (eq. 45) [MPa]")
    top.legend(fontsize="small", loc="lower right")
    top.set_title(run.title("isochoric compression (Liu et al. 2025, eq. 44)") + "\nthin lines: each grain",
                  fontsize="small")
    bottom.plot(eps, spread, color="k", label="spread: hardest − softest grain")
    bottom.plot(eps, sd, color="tab:blue", label="SD over the grains")
    bottom.axhline(100.0, color="grey", ls="--", lw=0.8)
    bottom.set_ylabel("[MPa]")
    bottom.set_xlabel("compressive true strain  $-\\varepsilon$")
    bottom.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    first = eps[np.argmax(spread >= 100.0)] if (spread >= 100.0).any() else float("nan")
    print(f"{runs[0]}: Taylor average {taylor[-1]:.1f} MPa at strain {eps[-1]:.3g}; spread reaches 100 MPa at strain "
          f"{first:.3g}, peaks at {spread.max():.1f} MPa (strain {eps[np.argmax(spread)]:.3g}); SD peaks at "
          f"{sd.max():.1f} MPa (strain {eps[np.argmax(sd)]:.3g}); at strain 0.01/0.05/0.1: spread "
          + ", ".join(f"{np.interp(e, eps, spread):.1f}" for e in (0.01, 0.05, 0.1)) + " MPa, Taylor "
          + ", ".join(f"{np.interp(e, eps, taylor):.1f}" for e in (0.01, 0.05, 0.1)) + " MPa")
    if not johnson_cook_mpa:
        return
    print("strain  Johnson-Cook [MPa]  Taylor average [MPa] (ratio to Johnson-Cook): " + "; ".join(labels[: len(runs)]))
    for e in (0.01, 0.05, 0.1, 0.2, 0.5, 1.0):
        r = johnson_cook(johnson_cook_mpa, e, rate)
        cells = [np.interp(e, eps, t) for t in [taylor] + [o for _, o in others]]
        print(f"{e:6.2f}  {r:18.1f}  " + "  ".join(f"{t:7.1f} ({t / r:4.2f})" for t in cells))


def standard_triangle(h, k, l):
    """Stereographic projection of the cubic-equivalent direction [u v w] with 0 <= v <= u <= w
    (the [001]-[101]-[111] triangle, [101] to the right)."""
    v = np.sort(np.abs(np.stack([h, k, l])), axis=0)
    v /= np.linalg.norm(v, axis=0)
    return v[1] / (1 + v[2]), v[0] / (1 + v[2]), v


def orientations(runs, labels, out):
    g = Run.open(runs[0]).table("grain_summary")
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.8))
    t = np.linspace(0.0, 1.0, 50)
    arc = standard_triangle(t, np.ones_like(t), np.ones_like(t))  # the [101]-[111] edge
    for ax, key, title in ((axes[0], "axis", "initial"), (axes[1], "final_axis", "after compression")):
        x, y, v = standard_triangle(g[key + "_h"], g[key + "_k"], g[key + "_l"])
        ax.plot([0, arc[0][0]], [0, 0], "k", lw=0.8)
        ax.plot([0, arc[0][-1]], [0, arc[1][-1]], "k", lw=0.8)
        ax.plot(arc[0], arc[1], "k", lw=0.8)
        ax.scatter(x, y, s=14, color="tab:blue")
        for name, (px, py) in (("[001]", (0, 0)), ("[101]", (arc[0][0], 0)), ("[111]", (arc[0][-1], arc[1][-1]))):
            ax.annotate(name, (px, py), textcoords="offset points", xytext=(-8, -12 if py == 0 else 4), fontsize="small")
        ax.set_aspect("equal")
        ax.axis("off")
        angle = np.degrees(np.arccos(np.clip((v[1] + v[2]) / np.sqrt(2.0), -1, 1)))
        ax.set_title(f"{title}: loading axis in the crystal\nmean angle from <110> {angle.mean():.1f}°", fontsize="small")
        print(f"{title}: mean angle of the loading axis from <110> {angle.mean():.1f} deg "
              f"({len(angle)} grains, min {angle.min():.1f}, max {angle.max():.1f})")
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    fig.savefig(out, dpi=100)


def crack_angle(x, y, damage, tip, reach=25.0):
    """Angle (deg, from +x) and side (+1 up, -1 down) of the crack grown from `tip` (mm)."""
    near = (damage >= 0.35) & (x > tip[0]) & (np.abs(y - tip[1]) > 1.0) & (np.hypot(x - tip[0], y - tip[1]) < reach)
    if near.sum() < 3:
        return None, 0
    side = 1.0 if np.mean(y[near] - tip[1]) > 0 else -1.0
    near &= side * (y - tip[1]) > 0
    points = np.vstack([x[near] - tip[0], side * (y[near] - tip[1])]).T
    direction = np.linalg.svd(points, full_matrices=False)[2][0]
    return float(np.degrees(np.arctan2(abs(direction[1]), abs(direction[0])))), side


def crack_tips(run):
    """The `to` ends (m) of the run's [[crack]] tables."""
    return [tuple(c["to"]) for c in Run.open(run).config.get("crack", [])]


def damage(runs, labels, out, given_tips):
    fig, axes = plt.subplots(1, len(runs), figsize=(4.2 * len(runs), 7.5), squeeze=False)
    for ax, run, label in zip(axes[0], runs, labels):
        tips = given_tips or crack_tips(run)
        t, p = last_profile(run)
        x, y, phi = 1e3 * p["x_m"], 1e3 * p["y_m"], p["damage"]
        dots = ax.scatter(x, y, c=phi, s=3.0, cmap="inferno_r", vmin=0.0, vmax=0.5, marker="s", linewidths=0)
        for tip in tips:
            tip = (1e3 * tip[0], 1e3 * tip[1])
            angle, side = crack_angle(x, y, phi, tip)
            if angle is None:
                print(f"{label}: no crack from the tip at ({tip[0]:.2f}, {tip[1]:.2f}) mm")
                continue
            print(f"{label}: crack from ({tip[0]:.2f}, {tip[1]:.2f}) mm at {angle:.1f} deg from the notch direction")
            r = 25.0
            a = np.radians(angle)
            ax.plot([tip[0], tip[0] + r * np.cos(a)], [tip[1], tip[1] + side * r * np.sin(a)], "c--", lw=1)
            ax.annotate(f"{angle:.0f}°", (tip[0] + 4 + r * np.cos(a), tip[1] + side * r * np.sin(a)), color="c")
            e = np.radians(70.0)  # Kalthoff & Winkler (1988)
            ax.plot([tip[0], tip[0] + r * np.cos(e)], [tip[1], tip[1] + side * r * np.sin(e)], ":", color="0.4", lw=1.2,
                    label="experiment, ~70°" if side > 0 else None)
        ax.set_aspect("equal")
        if ax.get_legend_handles_labels()[0]:  # the experiment line is drawn for a crack going up
            ax.legend(loc="lower right", fontsize=8)
        ax.set_xlabel("x (mm, impact direction)")
        ax.set_ylabel("y (mm)")
        ax.set_title(f"{label}, t = {1e6 * t:.0f} µs")
        fig.colorbar(dots, ax=ax, label="damage", shrink=0.6)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["bar", "profiles", "crystal", "compression", "orientations", "damage"])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--labels", nargs="*")
    ap.add_argument("--out", default="bar.png")
    ap.add_argument("--tips", nargs="*", default=[], help="notch tips X,Y in m (damage)")
    ap.add_argument("--johnson-cook", help="compression: a reference flow curve A,B,n,C (A, B in MPa)")
    ap.add_argument("--reference-label", help="compression: the legend of --johnson-cook's curve")
    a = ap.parse_args()
    labels = a.labels or [os.path.basename(os.path.normpath(r)) for r in a.runs]
    if a.kind == "damage":
        damage(a.runs, labels, a.out, [tuple(float(v) for v in tip.split(",")) for tip in a.tips])
        return
    if a.kind == "compression":
        reference = [float(v) for v in a.johnson_cook.split(",")] if a.johnson_cook else None
        if reference is not None and len(reference) != 4:
            ap.error(f"--johnson-cook: expected A,B,n,C (four numbers), got '{a.johnson_cook}'")
        compression(a.runs, labels, a.out, reference, a.reference_label)
        return
    {"bar": bar, "profiles": profiles, "crystal": crystal, "compression": compression, "orientations": orientations}[a.kind](
        a.runs, labels, a.out)


if __name__ == "__main__":
    main()
