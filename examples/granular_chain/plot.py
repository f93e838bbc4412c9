#!/usr/bin/python3
"""Pictures of the granular chain examples from the run folders that run.sh writes with
`shockfield run` (outputs: docs/granular.md).
Usage: /usr/bin/python3 plot.py RUNS  -> writes the PNG files next to this script."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from shockfield.run import Run  # noqa: E402  (the run-folder reader every plot uses; PYTHONPATH=python)

here = os.path.dirname(os.path.abspath(__file__))
runs = sys.argv[1] if len(sys.argv) > 1 else "runs/granular_chain"


def read(run, name):
    return Run.open(os.path.join(runs, run)).table(name)


def table(run, name):
    """The columns of a space-time file: time, and a (rows x grains) array."""
    columns = read(run, name)
    time, *grains = columns.dtype.names
    return columns[time], np.column_stack([columns[g] for g in grains])


def resolved(run):
    return Run.open(os.path.join(runs, run)).config


def central_speed(t, z):
    """The signal speed as docs/granular.md defines it: the central difference of the peak's
    depth between neighbouring samples (one-sided at the ends)."""
    v = np.empty_like(z)
    v[1:-1] = (z[2:] - z[:-2]) / (t[2:] - t[:-2])
    v[0] = (z[1] - z[0]) / (t[1] - t[0])
    v[-1] = (z[-1] - z[-2]) / (t[-1] - t[-2])
    return v


def spacetime():
    t, force = table("horizontal_train", "spacetime_force.csv")
    fig, ax = plt.subplots(figsize=(7, 4))
    im = ax.imshow(force.T, origin="lower", aspect="auto", cmap="inferno",
                   extent=[t[0] * 1e3, t[-1] * 1e3, 0, force.shape[1]])
    fig.colorbar(im, ax=ax, label="contact force F_k [N]")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("contact k (grain index)")
    ax.set_title("5 grains at 0.5 m/s hit a horizontal chain: a train of solitary waves")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "spacetime_force.png"), dpi=120)


DERIVED = {"speed": 1 / 6, "velocity": -1 / 4, "force": -1 / 12, "width": 1 / 3}
COLUMN = {"velocity": "velocity_m_s", "force": "force_N", "width": "width_grains"}  # signal.csv
# The column runs of run.sh, by impulse v0 [m/s]: the weakly nonlinear one and the sweep.
SWEEP = {1e-4: "column_weak", 1e-3: "column_v0.001", 1e-2: "column_v0.01", 0.1: "column_v0.1",
         1.0: "column_strong", 5.0: "column_v5"}


def depth_fits(name):
    """The leading peak's depth, speed, velocity, force and width (signal.csv, peaks between grains
    100 and 2400 as the C++ test fits them), and the fitted exponent and its standard error of
    each quantity against depth (least squares on the logarithms, docs/granular.md)."""
    d = read(name, "signal.csv")
    speed = central_speed(d["time_s"], d["depth_m"])
    keep = (d["grain"] > 100) & (d["grain"] < 2400)
    z = d["depth_m"][keep]
    data, fits = {}, {}
    for q in DERIVED:
        y = (speed if q == "speed" else d[COLUMN[q]])[keep]
        (p, c), cov = np.polyfit(np.log(z), np.log(y), 1, cov=True)
        data[q], fits[q] = y, (p, np.sqrt(cov[0, 0]), c)
    return z, data, fits


def depth_laws():
    fig, axes = plt.subplots(1, 4, figsize=(14, 3.6))
    labels = {"speed": "signal speed [m/s]", "velocity": "peak grain velocity [m/s]",
              "force": "peak dynamic force [N]", "width": "width (FWHM) [grains]"}
    for name, style, regime in (("column_weak", "o", "weak, v0 = 1e-4 m/s"),
                                ("column_strong", "s", "strong, v0 = 1 m/s")):
        z, data, fits = depth_fits(name)
        for ax, q in zip(axes, DERIVED):
            p, _, c = fits[q]
            ax.loglog(z, data[q], style, ms=3, label=f"{regime}: slope {p:.3f}")
            if name == "column_weak":
                ax.loglog(z, np.exp(c) * z ** DERIVED[q] * (z[0] ** p / z[0] ** DERIVED[q]), "k--", lw=1,
                          label=f"derived slope {DERIVED[q]:.3f}")
    for ax, q in zip(axes, DERIVED):
        ax.set_xlabel("depth [m]")
        ax.set_ylabel(labels[q])
        ax.legend(fontsize=7)
    fig.suptitle("Vertical chain under gravity (3000 steel spheres, R = 2 mm): power laws in depth")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "depth_power_laws.png"), dpi=120)


def exponent_drift():
    """The four depth exponents against the impulse v0: fixed at the derived values in the weakly
    nonlinear regime, drifting toward 0 in the strongly nonlinear one. Prints the table of
    docs/granular.md."""
    fig, ax = plt.subplots(figsize=(7, 4.2))
    v0 = np.array(sorted(SWEEP))
    rows = {v: depth_fits(SWEEP[v])[2] for v in v0}
    print("| v0 [m/s] | speed | grain velocity | force | width |")
    for v in v0:
        print(f"| {v:g} | " + " | ".join(f"{rows[v][q][0]:.3f} ± {rows[v][q][1]:.4f}" for q in DERIVED) + " |")
    for q, colour in zip(DERIVED, ("C0", "C1", "C2", "C3")):
        p = np.array([rows[v][q][0] for v in v0])
        err = np.array([rows[v][q][1] for v in v0])
        ax.errorbar(v0, p, yerr=err, fmt="o-", color=colour, ms=4, label=q)
        ax.axhline(DERIVED[q], color=colour, ls="--", lw=0.8)
    ax.plot([1e-4], [-0.250], "k*", ms=9, label="Hong & Xu: leading peak α = 0.250 (weak)")
    ax.set_xscale("log")
    ax.set_xlabel("impulse v0 on the top grain [m/s]")
    ax.set_ylabel("exponent p of quantity ∝ depth^p")
    ax.set_title("Depth exponents against the impulse (dashed: derived weakly nonlinear values)", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "exponent_drift.png"), dpi=120)


def backscatter():
    """The energy reflected above the impurity against time, as docs/granular.md defines it: the
    energy above the equilibrium (kinetic + contact + gravity) of grains 0 .. impurity - 6
    (energy_above.csv) beyond that of the same column without the impurity, over the impulse's
    energy; and the impurity's own kinetic energy (probes.csv)."""
    config = resolved("column_no_impurity")
    impurity = config["impurity"][0]["index"]
    mass = config["derived"]["grain_mass"]
    impulse_energy = 0.5 * mass * config["impulse"]["velocity"] ** 2
    column = f"energy_above_{impurity - 5}_J"
    ref = read("column_no_impurity", "energy_above.csv")
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.8))
    for run, label in (("column_light_impurity", "light impurity (m/10)"),
                       ("column_heavy_impurity", "heavy impurity (10 m)")):
        d = read(run, "energy_above.csv")
        assert np.array_equal(d["time_s"], ref["time_s"]), "the impurity runs must share the time step of the reference"
        reflected = (d[column] - ref[column]) / impulse_energy
        a.plot(d["time_s"] * 1e3, reflected, label=label)
        p = read(run, "probes.csv")
        ratio = resolved(run)["impurity"][0]["mass_ratio"]
        kinetic = 0.5 * ratio * mass * p[f"velocity_{impurity}_m_s"] ** 2 / impulse_energy
        b.semilogy(p["time_s"] * 1e3, kinetic + 1e-12, label=label)
        after = d["time_s"] > 1.3e-3
        print(f"{run}: reflected energy after the echo {reflected[after].min():.4f} .. {reflected[after].max():.4f}"
              " of the impulse")
    a.set_xlabel("time [ms]")
    a.set_ylabel(f"energy of grains 0-{impurity - 6} beyond the\npure column's / impulse energy")
    a.set_title("reflected energy (kinetic + contact + gravity)", fontsize=9)
    a.legend()
    b.set_xlabel("time [ms]")
    b.set_ylabel("impurity kinetic energy / impulse energy")
    b.set_ylim(1e-9, 1)
    b.legend()
    fig.suptitle(f"Impurity at grain {impurity} of an 800-grain column, 1 m/s impulse on top")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "backscatter.png"), dpi=120)

spacetime()
depth_laws()
exponent_drift()
backscatter()
