"""The shock front of the porous run ([shock_front] of case.toml; docs/mpm.md, "Shock front and
Hugoniot"): the last particle frame binned in slabs along y beside what the tool found in that
frame (shock_front.csv: the front, the top of its rise, the plateau window) and over the run
(hugoniot_al.toml: the pooled plateau and the Rankine–Hugoniot stress of the measured U_s, u_p).

    PYTHONPATH=python /usr/bin/python3 examples/mpm_porous_al/front.py RUN front.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from shockfield.run import Run


def main(folder, out):
    run = Run.open(folder)
    frame = run.last_frame(kind="particles")
    rows = run.table("shock_front")
    row = rows[np.argmin(np.abs(rows["time_s"] - frame.time))]
    state = run.toml("hugoniot_al")
    settings = run.config["shock_front"]
    width, margin = settings["bin_width"], settings["margin_bins"] * settings["bin_width"]
    y = frame.data["points"][:, 1]
    edges = np.arange(0.0, y.max() + width, width)
    count, _ = np.histogram(y, edges)
    centre = 0.5 * (edges[1:] + edges[:-1])[count > 0] * 1e3  # mm
    slab_mean = lambda v: (np.histogram(y, edges, weights=v)[0] / np.maximum(count, 1))[count > 0]
    stress = -slab_mean(frame.data["longitudinal_stress"]) / 1e9
    vy = slab_mean(frame.data["velocity"][:, 1])

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 6), sharex=True)
    window = ((row["impact_face_m"] + margin) * 1e3, (row["rise_m"] - margin) * 1e3)
    for ax in (top, bottom):
        ax.axvspan(*window, color="tab:green", alpha=0.15, label="plateau window")
        ax.axvline(row["front_m"] * 1e3, color="tab:red", label="front (half the jump)")
        ax.axvline(row["rise_m"] * 1e3, color="tab:red", ls=":", label="top of the rise (90 %)")
    top.plot(centre, stress, "k-", lw=1, label=f"slab means, t = {frame.time * 1e9:.0f} ns")
    top.axhline(-state["longitudinal_stress_Pa"] / 1e9, color="tab:blue", ls="--",
                label=f"plateau over the fit: {-state['longitudinal_stress_Pa'] / 1e9:.2f} GPa")
    top.axhline(-state["longitudinal_stress_rankine_hugoniot_Pa"] / 1e9, color="tab:orange", ls="-.",
                label=f"$\\rho_{{00}} U_s u_p$ = {-state['longitudinal_stress_rankine_hugoniot_Pa'] / 1e9:.2f} GPa")
    top.set_ylabel(r"$-\sigma_{yy}$ (GPa)")
    top.legend(fontsize=7, loc="upper right")
    top.set_title(f"porous Al on a wall at 1000 m/s: $U_s$ = {state['us_m_s']:.0f} m/s, "
                  f"$u_p$ = {state['up_m_s']:.0f} m/s", fontsize=10)
    bottom.plot(centre, vy, "k-", lw=1)
    bottom.axhline(state["velocity_ahead_m_s"] + state["up_m_s"], color="tab:blue", ls="--")
    bottom.set_ylabel(r"$v_y$ (m/s)")
    bottom.set_xlabel("y (mm)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"t = {frame.time:.3g} s: front {row['front_m'] * 1e3:.3f} mm, window {window[0]:.3f}-{window[1]:.3f} mm -> {out}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
