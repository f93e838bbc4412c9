#!/usr/bin/python3
"""Sweeps from Python: MPM wall-impact speeds and PD bar-impact speeds, their shocked states
against the Hugoniot each run derives, and Minkowski functionals of a field on a numpy array.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python_sweep/sweep.py [--small] [-o DIR]

Writes DIR/sweep.png, DIR/mpm/sweep.csv, DIR/pd/sweep.csv (default DIR: runs/python_sweep).
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import shockfield  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]

parser = argparse.ArgumentParser()
parser.add_argument("--small", action="store_true", help="two speeds per method and a short bar (CI)")
parser.add_argument("-o", "--output", default="runs/python_sweep")
parser.add_argument("-j", "--jobs", type=int, default=2)
args = parser.parse_args()
out = pathlib.Path(args.output)

# MPM: a solid Al strip on a rigid wall (mpm_wall.toml). Behind the shock the material is at rest,
# so its particle velocity jump is the impact speed; the run derives the Hugoniot state at that
# speed from its Mie-Grüneisen Us = c0 + s up ([derived] hugoniot_pressure_Pa).
mpm_speeds = [300.0, 900.0] if args.small else [200.0, 400.0, 600.0, 800.0, 1000.0]
shockfield.sweep.run_sweep(HERE / "mpm_wall.toml", {"loading.speed": mpm_speeds}, out / "mpm",
                           jobs=args.jobs, overwrite=True)
mpm = []
for v in mpm_speeds:
    run = shockfield.Run.open(out / "mpm" / f"loading.speed={shockfield.case.toml_value(v)}")
    s = run.series
    late = s["time_s"] >= 30e-9  # the 75 µm window above the wall is shocked from ~17 ns on
    mpm.append((v, s["bottom_h75um_pressure_mean_Pa"][late].mean(), run.derived["hugoniot_pressure_Pa"]))
    print(f"mpm {v:6.0f} m/s: window pressure {mpm[-1][1] / 1e9:.3f} GPa, Hugoniot {mpm[-1][2] / 1e9:.3f} GPa")

# PD: the aluminium bar of examples/pd_bar_elastic_plastic (Liu et al. (2025) §3.1), its halves
# meeting at v: below the HEL one elastic wave at sigma = rho c_L v / 2 ([derived]
# impact_axial_stress_Pa), compared with the largest axial compression in the bar at the end.
pd_speeds = [10.0, 40.0] if args.small else [10.0, 20.0, 30.0, 40.0, 50.0]
pd_case = ROOT / "examples" / "pd_bar_elastic_plastic" / "bar_30.toml"
pd_values = {"loading.speed": pd_speeds}
if args.small:
    pd_values.update({"body.counts": ["[600]"], "solver.end_time": ["3.75e-7"]})
shockfield.sweep.run_sweep(pd_case, pd_values, out / "pd", jobs=args.jobs, overwrite=True)
pd = []
for folder in sorted((out / "pd").iterdir()):
    if folder.is_dir():
        run = shockfield.Run.open(folder)
        pd.append((run.config["loading"]["speed"], run.series["max_axial_compression_Pa"][-1],
                   run.derived["impact_axial_stress_Pa"], run.derived["hel_Pa"]))
pd.sort()
for v, measured, reference, _ in pd:
    print(f"pd  {v:6.0f} m/s: max axial compression {measured / 1e6:.2f} MPa, rho c v/2 {reference / 1e6:.2f} MPa")

# Minkowski functionals on a numpy array: the density field of the fastest MPM impact at its
# last frame (shocked above the wall, unshocked above the front), all thresholds in one pass.
fast = shockfield.Run.open(out / "mpm" / f"loading.speed={shockfield.case.toml_value(mpm_speeds[-1])}")
frame = list(fast.frames(array="density"))[-1]
density = np.ascontiguousarray(frame.data)
m = shockfield.analysis.minkowski(density, count=24, boundary="open", void=np.isnan(density))

fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
ax = axes[0]
v = np.array([r[0] for r in mpm])
ax.plot(v, [r[2] / 1e9 for r in mpm], "k-", label="Hugoniot of the run's EOS ([derived])")
ax.plot(v, [r[1] / 1e9 for r in mpm], "o", label="MPM: window mean, t ≥ 30 ns")
ax.set(xlabel="impact speed = particle velocity (m/s)", ylabel="pressure (GPa)",
       title=f"MPM Al on a rigid wall ({fast.config['material'][0]['library']})")
ax.legend()
ax = axes[1]
v = np.array([r[0] for r in pd])
ax.plot(v / 2, [r[2] / 1e6 for r in pd], "k-", label="ρ c_L v/2 ([derived])")
ax.plot(v / 2, [r[1] / 1e6 for r in pd], "s", label="PD: max axial compression")
ax.axhline(pd[0][3] / 1e6, color="grey", ls=":", label="HEL ([derived])")
ax.set(xlabel="particle velocity v/2 (m/s)", ylabel="axial stress (MPa)", title="PD Al bar impact (Liu et al. 2025)")
ax.legend()
ax = axes[2]
ax.plot(m["threshold"], m["A"], label="A (area fraction)")
ax.plot(m["threshold"], m["L"] / m["L"].max(), label="L / max L")
ax.plot(m["threshold"], m["chi"] / max(1, np.abs(m["chi"]).max()), label="χ / max |χ|")
ax.set(xlabel="density threshold (kg/m³)", title=f"Minkowski of MPM density, t = {frame.time * 1e9:.0f} ns")
ax.legend()
fig.tight_layout()
fig.savefig(out / "sweep.png", dpi=110)
print("wrote", out / "sweep.png")
