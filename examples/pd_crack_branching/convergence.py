#!/usr/bin/python3
"""δ- and m-convergence of the crack-branching plate (README.md, "Convergence"), as Ha & Bobaru
(2010) study it: the crack speed and the first branching position under

  δ-convergence: m = δ/ΔX = 3 fixed, δ = 3, 1.5, 1 mm (ΔX = 1, 0.5, 1/3 mm);
  m-convergence: δ = 1 mm fixed (PDMATLAB2D's horizon), m = 2, 3, 4 (ΔX = 0.5, 1/3, 0.25 mm).

Each run is case.toml's set-up written for its ΔX and δ: the plate [0, 100] x [0, 40] mm with a
point at the centre of each ΔX cell ([body] origin = ΔX/2), the notch along the mid-line to
x = 50.1 mm (between the points where bonds cross it: multiples of ΔX/2 for these ΔX), the 2 MPa
traction as b = σ/ΔX on the outer rows, and the PMB constants of the horizon (PDMATLAB2D's
PDBondConstants.m, 2D plane stress, constant influence): c = 9E/(πδ³), s0 = √(4πG0/(9Eδ)).
analyze.Crack measures each run. Writes convergence.md (the table) and convergence.png (tip
against time) in RUNS_DIR; exits 1 unless every run's crack runs below the Rayleigh speed,
branches and stays mirror-symmetric (analyze.py's tolerances). About 6 minutes on one core.

    examples/pd_crack_branching/convergence.py [RUNS_DIR]   (from the repository root;
                                                             SHOCKFIELD=path/to/shockfield)
"""
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyze  # noqa: E402

E, G0, RHO, SIGMA = 72e9, 3.8, 2440.0, 2e6  # soda-lime glass, 2 MPa (Bobaru & Zhang 2015)
WIDTH, HEIGHT, NOTCH_END = 100e-3, 40e-3, 50.1e-3
# (study, ΔX [m], m); the δ = 1 mm, m = 3 run serves both studies.
RUNS = [("δ", 1e-3, 3), ("δ", 0.5e-3, 3), ("δ, m", 1e-3 / 3, 3), ("m", 0.5e-3, 2), ("m", 0.25e-3, 4)]


def case_text(dx, m):
    delta = m * dx
    c = 9.0 * E / (math.pi * delta ** 3)
    s0 = math.sqrt(4.0 * math.pi * G0 / (9.0 * E * delta))
    nx, ny = round(WIDTH / dx), round(HEIGHT / dx)
    return f"""# Crack branching, ΔX = {dx:.6g} m, m = {m}, δ = {delta:.6g} m (written by convergence.py)
method = "pd"

[body]
dim = 2
counts = [{nx}, {ny}]
origin = [{dx / 2!r}, {dx / 2!r}]
spacing = {dx!r}
horizon_factor = {m}

[material]
model = "pmb"
density = {RHO}
micromodulus = {c!r}
critical_stretch = {s0!r}
alpha = 0.0

[solver]
end_time = 43e-6

[[crack]]
from = [-1e-3, {HEIGHT / 2!r}]
to = [{NOTCH_END!r}, {HEIGHT / 2!r}]

[[region]]
shape = "block"
ylo = {HEIGHT - dx!r}
body_force = [0.0, {SIGMA / dx!r}]

[[region]]
shape = "block"
yhi = {dx!r}
body_force = [0.0, {-SIGMA / dx!r}]

[output]
series_interval = 1e-6
profile_interval = 1e-6
"""


def main():
    runs = sys.argv[1] if len(sys.argv) > 1 else "runs/pd_crack_branching_convergence"
    binary = os.environ.get("SHOCKFIELD", "./build/release/shockfield")
    os.makedirs(runs, exist_ok=True)
    rows, ok = [], True
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for study, dx, m in RUNS:
        name = f"dx{dx * 1e6:.0f}um_m{m}"
        case, out = os.path.join(runs, name + ".toml"), os.path.join(runs, name)
        with open(case, "w") as f:
            f.write(case_text(dx, m))
        subprocess.run(["rm", "-rf", out], check=True)
        done = subprocess.run([binary, "run", case, "-o", out, "-j1", "-q"], capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"{case}: shockfield exited {done.returncode}: {done.stderr}")
        wall = float(next(line.split("step")[1].split()[0] for line in open(os.path.join(out, "log.txt")) if "wall time: step" in line))
        c = analyze.Crack(out, 0.05, m * dx, symmetry=True)
        symmetric = c.asymmetry[0] <= analyze.SYMMETRY_DAMAGE and max(c.asymmetry[1:]) <= analyze.SYMMETRY_VELOCITY
        good = 0.0 < c.speed < analyze.C_R and not math.isnan(c.branch_x) and symmetric
        ok &= good
        rows.append(f"| {study} | {dx * 1e3:.3g} | {m} | {m * dx * 1e3:.3g} | {round(WIDTH / dx) * round(HEIGHT / dx)} "
                    f"| {c.speed:.0f} ({c.speed / analyze.C_R:.2f} c_R) | {c.branch_x * 1e3:.1f} "
                    f"| {c.tips[-1] * 1e3:.1f} | {c.asymmetry[0]:.2g} | {wall:.0f} |{'' if good else ' FAILED'}")
        print(rows[-1], flush=True)
        ax.plot(c.times * 1e6, c.tips * 1e3, "o-", ms=2, label=f"ΔX = {dx * 1e3:.3g} mm, m = {m}, δ = {m * dx * 1e3:.3g} mm")
    ax.set_xlabel("t (µs)"), ax.set_ylabel("crack tip x (mm)")
    ax.set_ylim(48, 102)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(runs, "convergence.png"), dpi=110)
    with open(os.path.join(runs, "convergence.md"), "w") as f:
        f.write("| study | ΔX (mm) | m | δ (mm) | points | crack speed (m/s) | first branching x (mm) "
                "| tip at 43 µs (mm) | mirror defect (damage) | step wall time (s) |\n|---|---|---|---|---|---|---|---|---|---|\n")
        f.write("\n".join(rows) + "\n")
    if not ok:
        sys.exit("check failed: some run's crack did not run below c_R, branch and stay mirror-symmetric")


if __name__ == "__main__":
    main()
