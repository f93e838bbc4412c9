#!/usr/bin/python3
"""shear.png: shear stress sigma_xy = -pxy against the shear strain gamma of the runs of run.sh,
with the small-strain slope C44 fitted on |gamma| <= 0.005 and LAMMPS's C44 of Cu_u3
(tests/fixtures/lammps_elastic/results.toml). Usage: plot.py RUNS_DIR OUT_PNG GAMMA..."""
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python"))
from shockfield.run import Run, read_toml  # noqa: E402  (the shared run-folder readers)

runs, out = pathlib.Path(sys.argv[1]), sys.argv[2]
gammas = [float(g) for g in sys.argv[3:]]
sigma = []  # GPa
for g in sys.argv[3:]:
    thermo = Run.open(runs / ("run_%s" % g)).thermo
    sigma.append(-float(thermo["pxy_bar"][0]) * 1e-4)
gammas, sigma = np.array(gammas), np.array(sigma)
small = np.abs(gammas) <= 0.005
c44 = np.polyfit(gammas[small], sigma[small], 1)[0]
root = pathlib.Path(__file__).resolve().parents[2]
c44_lammps = read_toml(root / "tests/fixtures/lammps_elastic/results.toml")["c44_GPa"]
print("C44 from the tilted cells: %.2f GPa; LAMMPS (strain 1e-3, fixtures/lammps_elastic): %.2f GPa" % (c44, c44_lammps))
fig, ax = plt.subplots(figsize=(5.5, 4))
ax.plot(gammas, sigma, "o", label="shockfield, triclinic cells")
g = np.linspace(gammas.min(), gammas.max(), 50)
ax.plot(g, c44_lammps * g, "-", label="C44 γ, C44 = %.1f GPa (LAMMPS)" % c44_lammps)
ax.set_xlabel("shear strain γ = xy / ly")
ax.set_ylabel("shear stress σxy = −pxy (GPa)")
ax.set_title("fcc Cu (Cu_u3 EAM) under simple shear\nfitted C44 = %.1f GPa" % c44)
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=110)
