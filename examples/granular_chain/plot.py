#!/usr/bin/python3
"""Pictures of the granular chain examples from the CSV files that
`build/release/bench/granular_bench --examples DIR` writes (see README.md).
Usage: /usr/bin/python3 plot.py DIR  -> writes the PNG files next to this script."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
data = sys.argv[1] if len(sys.argv) > 1 else "."


def read(name):
    return np.genfromtxt(os.path.join(data, name), delimiter=",", names=True)


def spacetime():
    raw = np.loadtxt(os.path.join(data, "train", "spacetime_force.csv"), delimiter=",", skiprows=1)
    t, force = raw[:, 0], raw[:, 1:]
    fig, ax = plt.subplots(figsize=(7, 4))
    im = ax.imshow(force.T, origin="lower", aspect="auto", cmap="inferno",
                   extent=[t[0] * 1e3, t[-1] * 1e3, 0, force.shape[1]])
    fig.colorbar(im, ax=ax, label="contact force F_k [N]")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("contact k (grain index)")
    ax.set_title("5 grains at 0.5 m/s hit a horizontal chain: a train of solitary waves")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "spacetime_force.png"), dpi=120)


def depth_laws():
    fig, axes = plt.subplots(1, 4, figsize=(14, 3.6))
    derived = {"speed": 1 / 6, "velocity": -1 / 4, "force": -1 / 12, "width": 1 / 3}
    labels = {"speed": "signal speed [m/s]", "velocity": "peak grain velocity [m/s]",
              "force": "peak dynamic force [N]", "width": "width (FWHM) [grains]"}
    for name, style, regime in (("column_weak", "o", "weak, v0 = 1e-4 m/s"),
                                ("column_strong", "s", "strong, v0 = 1 m/s")):
        d = read(name + ".csv")
        keep = (d["position"] > 100) & (d["position"] < 2400)
        z = d["depth"][keep]
        for ax, q in zip(axes, derived):
            y = d[q][keep]
            p, c = np.polyfit(np.log(z), np.log(y), 1)
            ax.loglog(z, y, style, ms=3, label=f"{regime}: slope {p:.3f}")
            if name == "column_weak":
                ax.loglog(z, np.exp(c) * z ** derived[q] * (z[0] ** p / z[0] ** derived[q]), "k--", lw=1,
                          label=f"derived slope {derived[q]:.3f}")
    for ax, q in zip(axes, derived):
        ax.set_xlabel("depth [m]")
        ax.set_ylabel(labels[q])
        ax.legend(fontsize=7)
    fig.suptitle("Vertical chain under gravity (3000 steel spheres, R = 2 mm): power laws in depth")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "depth_power_laws.png"), dpi=120)


def backscatter():
    d = read("backscatter.csv")
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.8))
    a.plot(d["time"] * 1e3, d["light_reflected"], label="light impurity (m/10)")
    a.plot(d["time"] * 1e3, d["heavy_reflected"], label="heavy impurity (10 m)")
    a.set_xlabel("time [ms]")
    a.set_ylabel("energy reflected above the impurity / impulse energy")
    a.legend()
    b.semilogy(d["time"] * 1e3, d["light_impurity_kinetic"] + 1e-12, label="light impurity")
    b.semilogy(d["time"] * 1e3, d["heavy_impurity_kinetic"] + 1e-12, label="heavy impurity")
    b.set_xlabel("time [ms]")
    b.set_ylabel("impurity kinetic energy / impulse energy")
    b.set_ylim(1e-9, 1)
    b.legend()
    fig.suptitle("Impurity at grain 200 of an 800-grain column, 1 m/s impulse on top")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "backscatter.png"), dpi=120)


spacetime()
depth_laws()
backscatter()
