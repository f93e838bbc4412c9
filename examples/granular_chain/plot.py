#!/usr/bin/python3
"""Pictures of the granular chain examples from the run folders that run.sh writes with
`shockfield run` (outputs: docs/granular.md).
Usage: /usr/bin/python3 plot.py RUNS  -> writes the PNG files next to this script."""
import os
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
runs = sys.argv[1] if len(sys.argv) > 1 else "runs/granular_chain"


def read(run, name):
    return np.genfromtxt(os.path.join(runs, run, name), delimiter=",", names=True)


def table(run, name):
    """The columns of a space-time file: time, and a (rows x grains) array."""
    raw = np.loadtxt(os.path.join(runs, run, name), delimiter=",", skiprows=1, ndmin=2)
    return raw[:, 0], raw[:, 1:]


def resolved(run):
    with open(os.path.join(runs, run, "config.resolved.toml"), "rb") as f:
        return tomllib.load(f)


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


def depth_laws():
    fig, axes = plt.subplots(1, 4, figsize=(14, 3.6))
    derived = {"speed": 1 / 6, "velocity": -1 / 4, "force": -1 / 12, "width": 1 / 3}
    labels = {"speed": "signal speed [m/s]", "velocity": "peak grain velocity [m/s]",
              "force": "peak dynamic force [N]", "width": "width (FWHM) [grains]"}
    slopes = {}
    for name, style, regime in (("column_weak", "o", "weak, v0 = 1e-4 m/s"),
                                ("column_strong", "s", "strong, v0 = 1 m/s")):
        d = read(name, "signal.csv")
        speed = central_speed(d["time_s"], d["depth"])
        keep = (d["position"] > 100) & (d["position"] < 2400)
        z = d["depth"][keep]
        for ax, q in zip(axes, derived):
            y = (speed if q == "speed" else d[q])[keep]
            p, c = np.polyfit(np.log(z), np.log(y), 1)
            slopes[(name, q)] = p
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
    for (name, q), p in slopes.items():
        print(f"{name}: {q} slope {p:.3f}")


def backscatter():
    """Kinetic energy of the grains above the impurity (0 .. impurity - 6, as docs/granular.md's
    reflected energy leaves the impurity's neighbours out) beyond that of the same column without
    the impurity, and the impurity's own kinetic energy, over the impulse's energy."""
    config = resolved("column_no_impurity")
    impurity = config["impurity"][0]["index"]
    mass = config["derived"]["grain_mass"]
    impulse_energy = 0.5 * mass * config["impulse"]["velocity"] ** 2
    t, v_ref = table("column_no_impurity", "spacetime_velocity.csv")
    above = slice(0, impurity - 5)
    ref_kinetic = 0.5 * mass * (v_ref[:, above] ** 2).sum(axis=1)
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.8))
    for run, label in (("column_light_impurity", "light impurity (m/10)"),
                       ("column_heavy_impurity", "heavy impurity (10 m)")):
        t_run, v = table(run, "spacetime_velocity.csv")
        assert np.array_equal(t_run, t), "the impurity runs must share the time step of the reference"
        reflected = (0.5 * mass * (v[:, above] ** 2).sum(axis=1) - ref_kinetic) / impulse_energy
        a.plot(t * 1e3, reflected, label=label)
        p = read(run, "probes.csv")
        ratio = resolved(run)["impurity"][0]["mass_ratio"]
        kinetic = 0.5 * ratio * mass * p[f"velocity_{impurity}"] ** 2 / impulse_energy
        b.semilogy(p["time_s"] * 1e3, kinetic + 1e-12, label=label)
        late = t > 0.6 * t[-1]
        print(f"{run}: kinetic energy above the impurity, last 40% of the run: {reflected[late].mean():.3f}"
              " of the impulse")
    a.set_xlabel("time [ms]")
    a.set_ylabel("kinetic energy above the impurity\n(beyond the pure column) / impulse energy")
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
backscatter()
