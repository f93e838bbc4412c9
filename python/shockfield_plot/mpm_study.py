#!/usr/bin/python3
"""Parameter studies over MPM run folders written by `shockfield run` (method = "mpm").

  mpm_study.py collapsibility RUN_DIR [RUN_DIR ...] [--late T] [--at T] [--out FILE] [--csv FILE]
      Cavity collapsibility Φ = (A0 − A)/A0 (series.csv column `collapsibility`) of single-cavity
      runs against the initial cavity radius and against the initial yield stress (Xu et al. 2015, Fig 53 (b), (d)). The radius and yield stress of each run are read from its
      config.resolved.toml. The radius panel takes the runs at the most common yield stress, the
      yield panel the runs at the most common radius. Φ is shown at the last row and averaged
      over t ≥ T (default: the last quarter of the run), and with --at also at an earlier time
      (e.g. the first stall); a third panel shows Φ against time.

Reads the runs through shockfield.run.Run. Uses only numpy and matplotlib from Debian (run with
/usr/bin/python3).
"""
import argparse
import collections
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402


def resolved_value(run, key):
    value = run.value(key)
    if value is None:
        sys.exit(f"{run.folder}: no {key} in config.resolved.toml")
    return value


def collapsibility(runs, late, at, out, csv_out):
    recs = []
    for run in map(Run.open, runs):
        s = run.series
        if "collapsibility" not in s.dtype.names:
            sys.exit(f"{run.folder}: series.csv has no collapsibility column (no cavity?)")
        t, phi = s["time_s"], s["collapsibility"]
        t_late = late if late is not None else 0.75 * t[-1]
        sel = t >= t_late - 1e-15
        recs.append(dict(run=run, r=resolved_value(run, "cavity_radius"),
                         y=resolved_value(run, "yield_stress"), t=t, phi=phi,
                         t_end=t[-1], t_late=t_late, phi_end=phi[-1], phi_late=phi[sel].mean(),
                         phi_max=phi.max(),
                         phi_at=phi[np.argmin(np.abs(t - at))] if at is not None else None))
    y_ref = collections.Counter(round(r["y"]) for r in recs).most_common(1)[0][0]
    r_ref = collections.Counter(round(r["r"], 12) for r in recs).most_common(1)[0][0]
    by_r = sorted((r for r in recs if round(r["y"]) == y_ref), key=lambda r: r["r"])
    by_y = sorted((r for r in recs if round(r["r"], 12) == r_ref), key=lambda r: r["y"])

    if csv_out:
        with open(csv_out, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["radius_m", "yield_stress_Pa", "t_end_s", "phi_end", "t_late_s",
                        "phi_late_mean", "phi_max"] + (["t_at_s", "phi_at"] if at is not None else []))
            for r in sorted(recs, key=lambda r: (r["r"], r["y"])):
                w.writerow([f"{r['r']:.4g}", f"{r['y']:.4g}", f"{r['t_end']:.4g}",
                            f"{r['phi_end']:.4f}", f"{r['t_late']:.4g}", f"{r['phi_late']:.4f}",
                            f"{r['phi_max']:.4f}"] + ([f"{at:.4g}", f"{r['phi_at']:.4f}"] if at is not None else []))
    for r in sorted(recs, key=lambda r: (r["r"], r["y"])):
        print(f"r = {r['r'] * 1e6:5.2f} µm  σ_Y0 = {r['y'] / 1e6:6.1f} MPa  Φ_end = {r['phi_end']:.3f}"
              f"  Φ(t ≥ {r['t_late'] * 1e9:.1f} ns) = {r['phi_late']:.3f}  Φ_max = {r['phi_max']:.3f}"
              + (f"  Φ({at * 1e9:g} ns) = {r['phi_at']:.3f}" if at is not None else ""))

    fig, ax = plt.subplots(1, 3, figsize=(16, 4.2))
    for a, sel, key, scale, label, title in (
            (ax[0], by_r, "r", 1e6, "initial cavity radius [µm]", f"σ_Y0 = {y_ref / 1e6:g} MPa"),
            (ax[1], by_y, "y", 1e-6, "initial yield stress σ_Y0 [MPa]", f"r = {r_ref * 1e6:g} µm")):
        x = [r[key] * scale for r in sel]
        a.plot(x, [r["phi_end"] for r in sel], "o-", label="Φ at the end")
        a.plot(x, [r["phi_late"] for r in sel], "s--", label=f"Φ mean, t ≥ {sel[0]['t_late'] * 1e9:g} ns")
        a.plot(x, [r["phi_max"] for r in sel], "^:", label="Φ max")
        if at is not None:
            a.plot(x, [r["phi_at"] for r in sel], "v-.", label=f"Φ at {at * 1e9:g} ns")
        a.set_xlabel(label)
        a.set_ylabel("collapsibility Φ = (A0 − A)/A0")
        a.set_title(title)
        a.set_ylim(0, 1.05)
        a.grid(alpha=0.3)
        a.legend(fontsize="small")
    for r in sorted(recs, key=lambda r: (r["r"], r["y"])):
        ax[2].plot(r["t"] * 1e9, r["phi"], label=f"r = {r['r'] * 1e6:g} µm, σ_Y0 = {r['y'] / 1e6:g} MPa")
    ax[2].axvline(recs[0]["t_late"] * 1e9, color="0.6", lw=0.8)
    if at is not None:
        ax[2].axvline(at * 1e9, color="0.6", lw=0.8, ls="-.")
    ax[2].set_xlabel("t [ns]")
    ax[2].set_ylabel("Φ")
    ax[2].set_title("Φ against time")
    ax[2].grid(alpha=0.3)
    ax[2].legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.suptitle("Single-cavity collapsibility (Xu et al. 2015, Fig 53 (b), (d))")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="kind", required=True)
    c = sub.add_parser("collapsibility", help="Φ against cavity radius and yield stress")
    c.add_argument("runs", nargs="+")
    c.add_argument("--late", type=float, default=None, help="start of the late averaging window [s]")
    c.add_argument("--at", type=float, default=None, help="also show Φ at this time [s]")
    c.add_argument("--out", default="collapsibility.png")
    c.add_argument("--csv", default=None, help="also write the table as CSV")
    a = p.parse_args()
    collapsibility(a.runs, a.late, a.at, a.out, a.csv)


if __name__ == "__main__":
    main()
