#!/usr/bin/python3
"""Plots of PD run folders written by `shockfield run` (method = "pd").

  pd_plots.py bar RUN_DIR [RUN_DIR ...] [--labels L ...] [--out FILE]
      axial compression -sigma_xx and plastic measure against x at every profile time, one
      column per run (seed 004 Fig. 3), with the run's derived HEL and impact stress as dashed
      lines.

Reads profiles/index.csv, profiles/profile_<k>.csv and config.resolved.toml. Uses only numpy
and matplotlib from Debian (run with /usr/bin/python3).
"""
import argparse
import csv
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    data = np.array([[float(x) for x in r] for r in rows[1:] if r], dtype=float)
    return {name: data[:, k] for k, name in enumerate(rows[0])}


def derived(run, key):
    with open(os.path.join(run, "config.resolved.toml")) as f:
        m = re.search(rf"^{key} = (\S+)", f.read(), re.M)
    return float(m.group(1)) if m else None


def bar(runs, labels, out):
    fig, axes = plt.subplots(2, len(runs), figsize=(5.5 * len(runs), 6), sharex="col", squeeze=False)
    for col, (run, label) in enumerate(zip(runs, labels)):
        index = read_csv(os.path.join(run, "profiles", "index.csv"))
        top, bottom = axes[0][col], axes[1][col]
        for k, t in zip(index["profile"].astype(int), index["time_s"]):
            if t <= 0.0:
                continue
            p = read_csv(os.path.join(run, "profiles", f"profile_{k}.csv"))
            top.plot(p["x_m"] * 1e3, -p["sxx_Pa"] / 1e6, label=f"{t * 1e9:.0f} ns")
            bottom.plot(p["x_m"] * 1e3, p["plastic"], label=f"{t * 1e9:.0f} ns")
        for key, name in (("hel_Pa", "HEL"), ("impact_axial_stress_Pa", "impact state")):
            v = derived(run, key)
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


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["bar"])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--labels", nargs="*")
    ap.add_argument("--out", default="bar.png")
    a = ap.parse_args()
    bar(a.runs, a.labels or [os.path.basename(os.path.normpath(r)) for r in a.runs], a.out)


if __name__ == "__main__":
    main()
