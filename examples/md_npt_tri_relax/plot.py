"""Plots the run of examples/md_npt_tri_relax (thermo.csv, one row every 10 steps): the tilt
factors, the shear stress sigma_xy = -pxy and the lattice parameter (4V/N)^(1/3) against time, with
C44 * gamma of the sheared crystal and LAMMPS's 300 K, 0 bar lattice parameter of the same potential
(tests/fixtures/lammps_npt/cu_300K_0bar.ref: `fix npt iso`, 200 ps); prints the means over the
last 4 ps with their standard errors (8 block averages).
Usage: plot.py RUN_DIR OUT.png REPO_ROOT"""
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python"))
from shockfield.run import Run, read_toml  # noqa: E402  (the shared run-folder readers)

run, out, root = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
t = Run.open(run).thermo
natoms = 864
a = (4 * t["volume_A3"] / natoms) ** (1 / 3)
ref = dict(line.split()[:2] for line in (root / "tests/fixtures/lammps_npt/cu_300K_0bar.ref").read_text().splitlines())
a_lammps = (4 * float(ref["volume"]) / 500) ** (1 / 3)
c44 = read_toml(root / "tests/fixtures/lammps_elastic/results.toml")["c44_GPa"]
shear_end = 2.0  # ps: stage "shear", 1000 steps of 2 fs
late = t["time_ps"] >= t["time_ps"][-1] - 4.0


def mean_error(v):
    blocks = v[: len(v) // 8 * 8].reshape(8, -1).mean(axis=1)
    return v.mean(), blocks.std(ddof=1) / np.sqrt(8)


fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
for name, style in (("xy_A", "-"), ("xz_A", "--"), ("yz_A", ":")):
    ax[0].plot(t["time_ps"], t[name], style, label=name[:2])
ax[0].set_ylabel("tilt (Å)")
ax[0].legend()
ax[1].plot(t["time_ps"], -t["pxy_bar"] * 1e-4, label="σxy = −pxy")
gamma = t["xy_A"] / t["ly_A"]
shear = t["time_ps"] <= shear_end
ax[1].plot(t["time_ps"][shear], c44 * gamma[shear], "k--", label=f"C44 γ (LAMMPS C44 = {c44:.1f} GPa)")
ax[1].set_ylabel("shear stress (GPa)")
ax[1].legend()
ax[2].plot(t["time_ps"], a, label="(4V/N)^(1/3)")
ax[2].axhline(a_lammps, color="k", ls="--", label=f"LAMMPS fix npt, 300 K, 0 bar: {a_lammps:.5f} Å")
ax[2].set_ylabel("lattice parameter (Å)")
ax[2].set_xlabel("time (ps)")
ax[2].legend()
for axis in ax:
    axis.axvline(shear_end, color="grey", lw=0.5)
fig.suptitle("Cu sheared to γ = 0.02, then npt tri at 300 K, 0 bar")
fig.tight_layout()
fig.savefig(out, dpi=100)
end = t["time_ps"] <= shear_end
print(f"end of shear: xy = {t['xy_A'][end][-1]:.4f} A (gamma {gamma[end][-1]:.4f}), sigma_xy = "
      f"{-t['pxy_bar'][end][-1] * 1e-4:.3f} GPa, C44 gamma = {c44 * gamma[end][-1]:.3f} GPa")
for name, values, unit in (("xy", t["xy_A"][late], "A"), ("sigma_xy", -t["pxy_bar"][late] * 1e-4, "GPa"),
                           ("a", a[late], "A")):
    m, e = mean_error(values)
    print(f"last 4 ps: {name} = {m:.5f} +- {e:.5f} {unit}")
print(f"LAMMPS 300 K, 0 bar: a = {a_lammps:.5f} A")
