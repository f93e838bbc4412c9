"""R(t) of the phasefield_domain runs against the sharp-interface law R' = c0 - D/R (2D).

a = 0.5: R^2 = R0^2 - 2 D t. a = 0.4: t(R) = [R - R0 + R* ln((R - R*)/(R0 - R*))]/c0,
R* = D/c0, c0 = sqrt(D/2)(1 - 2a) (docs/theory/phasefield.md). R0 is the run's own first value
(the equivalent radius of sum(xi) dA). For the a = 0.45 law the radius of the xi = 1/2 level is used:
the tanh profile (logistic length l = sqrt(2D)) adds pi^2 l^2 / 3 to the equivalent R^2
(docs/theory/phasefield.md); the a = 0.5 law is a difference of R^2, where it cancels.
Usage: plot.py RUNS_FOLDER
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

D = 0.25
runs = Path(sys.argv[1])
fig, ax = plt.subplots(figsize=(6, 4))
for a, colour in ((0.45, "C0"), (0.5, "C1")):
    data = Run.open(runs / f"a{a}").series
    t, R = data["time"], data["equivalent_radius"]
    if a != 0.5:
        R = np.sqrt(R**2 - np.pi**2 * 2 * D / 3)  # the xi = 1/2 level
    R0 = R[0]
    ax.plot(t, R, "o", ms=3, color=colour, label=f"phasefield, a = {a}")
    if a == 0.5:
        ax.plot(t, np.sqrt(np.maximum(R0**2 - 2 * D * t, 0)), "-", color=colour, label=r"$R^2 = R_0^2 - 2Dt$")
        err = np.max(np.abs(R / np.sqrt(R0**2 - 2 * D * t) - 1))
    else:
        c0 = np.sqrt(D / 2) * (1 - 2 * a)
        Rc = D / c0
        Rs = np.linspace(R0, R.max(), 200)
        ax.plot((Rs - R0 + Rc * np.log((Rs - Rc) / (R0 - Rc))) / c0, Rs, "-", color=colour,
                label=r"$\dot R = c_0 - D/R$" + f" ($R^* = {Rc:.2f}$)")
        t_law = (R - R0 + Rc * np.log((R - Rc) / (R0 - Rc))) / c0
        err = np.max(np.abs(t_law[1:] - t[1:]) / t[-1])
    print(f"a = {a}: max deviation from the law {err:.3%}")
ax.set_xlabel("t")
ax.set_ylabel("R (a = 0.45: xi = 1/2 level; a = 0.5: equivalent radius)")
ax.set_title("hcp disc, D = 0.25 (2D, 320² spectral)")
ax.legend()
fig.tight_layout()
fig.savefig(Path(__file__).with_name("radius.png"), dpi=120)
