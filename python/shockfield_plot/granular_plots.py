#!/usr/bin/python3
"""Figures of granular chain run folders (docs/granular.md), used by `shockfield plot`.

  python3 -m shockfield_plot.granular_plots chain RUN_DIR [--out FILE]
      the dynamic contact force F_g - F0_g of every written contact against time
      (spacetime_force.csv, when [output] field_interval > 0), the depth of the leading signal
      against time (series.csv) with the chain's length 2 r N (from [chain]) dashed, and the
      energies of series.csv (kinetic, potential, total, the impulse's external work) against
      time -> RUN_DIR/chain.png

Reads the tables through shockfield.run.Run. Uses only numpy and matplotlib from Debian (run with
/usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402


def chain(run, out):
    run = Run.open(run)
    s = run.series
    c = run.config["chain"]
    has_spacetime = (run.folder / "spacetime_force.csv").is_file()
    fig, axes = plt.subplots(1, 3 if has_spacetime else 2, figsize=(15 if has_spacetime else 10, 4.2))
    if has_spacetime:
        f = run.table("spacetime_force")
        columns = [n for n in f.dtype.names if n.startswith("force_")]
        grains = [int(n.removeprefix("force_").removesuffix("_N")) for n in columns]
        force = np.column_stack([f[n] for n in columns])
        image = axes[0].imshow(force.T, origin="lower", aspect="auto", cmap="inferno",
                               extent=[f["time_s"][0] * 1e3, f["time_s"][-1] * 1e3, grains[0], grains[-1]])
        fig.colorbar(image, ax=axes[0], label="dynamic contact force F_g − F⁰_g (N)")
        axes[0].set(xlabel="time (ms)", ylabel="contact below grain g", title="space–time force")
    depth_ax, energy_ax = axes[-2], axes[-1]
    depth_ax.plot(s["time_s"] * 1e3, s["signal_depth_m"] * 1e3)
    length = 2 * c["radius"] * c["grains"]
    depth_ax.axhline(length * 1e3, color="grey", ls="--", lw=0.8)
    depth_ax.annotate(f"chain length {length * 1e3:.4g} mm", (0.01, length * 1e3), xycoords=("axes fraction", "data"),
                      fontsize="x-small", va="bottom")
    depth_ax.set(xlabel="time (ms)", ylabel="depth of the leading signal (mm)", title="signal depth")
    for column, label in (("kinetic_J", "kinetic"), ("potential_J", "potential"), ("total_J", "total"),
                          ("external_work_J", "external work")):
        energy_ax.plot(s["time_s"] * 1e3, s[column], label=label)
    energy_ax.set(xlabel="time (ms)", ylabel="energy above the initial equilibrium (J)", title="energies")
    energy_ax.legend(fontsize="x-small")
    impulse = run.config.get("impulse", {})
    fig.suptitle(run.title(f"{c['grains']} grains of radius {c['radius'] * 1e3:g} mm, impulse "
                           f"{impulse.get('kind', '')} {impulse.get('velocity', '')} m/s on {impulse.get('grains', '')} "
                           f"grain(s)"))
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["chain"])
    ap.add_argument("run")
    ap.add_argument("--out")
    a = ap.parse_args()
    out = a.out or os.path.join(a.run, "chain.png")
    chain(a.run, out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
