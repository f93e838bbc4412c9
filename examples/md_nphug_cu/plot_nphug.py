"""nphug.png for examples/md_nphug_cu: (a) P_zz and (b) T with its Hugoniot target against time
for each run's hug stage, (c) the Hugoniot points in the Us-Up plane beside the piston sweep of
docs/md-validation.md and the MSST state of examples/md_msst_cu (numbers copied from there).
Usage: plot_nphug.py OUT.png RUN_DIR..."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

# docs/md-validation.md, section 2 (shockfield piston sweep): piston speed, Up, Us, Us standard error.
PISTON = [(0.5, 0.5057, 4.983, 0.050), (1.0, 1.0059, 5.386, 0.034), (1.5, 1.5097, 5.964, 0.026),
          (2.0, 2.0152, 6.599, 0.028)]
# examples/md_msst_cu/README.md, relaxed start: Us imposed, Up measured.
MSST = (1.568, 5.964)


def read_thermo(run):
    """The rows of thermo.csv written by the hug stage (nphug_dhugoniot_K a number)."""
    thermo = run.thermo
    return thermo[~np.isnan(thermo["nphug_dhugoniot_K"])]


def main():
    out, runs = sys.argv[1], sys.argv[2:]
    fig, (ax_p, ax_t, ax_h) = plt.subplots(1, 3, figsize=(15, 4.5))
    for folder in runs:
        run = Run.open(folder)
        rows = read_thermo(run)
        result = run.summary["results"]["nphug"][-1]
        label = f"{result['target_pressure_GPa']:.1f} GPa"
        t0 = float(rows[0]["time_ps"])
        t = [float(r["time_ps"]) - t0 for r in rows]
        line, = ax_p.plot(t, [float(r["pzz_bar"]) * 1e-4 for r in rows], label=label)
        ax_t.plot(t, [float(r["temperature_K"]) for r in rows], color=line.get_color(), label=label)
        ax_t.plot(t, [float(r["nphug_target_temperature_K"]) for r in rows], color=line.get_color(), lw=0.5,
                  alpha=0.5)
        ax_h.plot(result["particle_speed_km_s"], result["shock_speed_km_s"], "o", color=line.get_color(),
                  label=f"NPHug {label}")
    ax_h.errorbar([p[1] for p in PISTON], [p[2] for p in PISTON], yerr=[p[3] for p in PISTON], fmt="ks",
                  mfc="none", label="piston sweep (docs/md-validation.md)")
    ax_h.plot(*MSST, "k^", mfc="none", label="MSST, Us = 5.964 km/s (md_msst_cu)")
    ax_p.set(xlabel="time in the hug stage (ps)", ylabel="P_zz (GPa)", title="(a) uniaxial pressure")
    ax_t.set(xlabel="time in the hug stage (ps)", ylabel="T (K)", title="(b) T (thin: Hugoniot target)")
    ax_h.set(xlabel="Up (km/s)", ylabel="Us (km/s)", title="(c) Hugoniot points, [100] Cu_u3")
    for ax in (ax_p, ax_t):
        ax.legend(fontsize=8)
    ax_h.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
