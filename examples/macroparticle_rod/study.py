#!/usr/bin/python3
"""Runs the elastic rod of rod_elastic.toml over division numbers and fits E and nu.

Usage: study.py SHOCKFIELD OUT_DIR RATIO N_PHI... : n_h = RATIO * n_phi; each run pulls the rod
to 0.1 % strain in STEPS steps and E, nu are least-squares slopes of stress and lateral strain
against strain over the second half of the run (the first half lets the start-up settle).
Writes OUT_DIR/study_<ratio>.csv (n_phi, n_h, particles, E_Pa, nu, E_eq15_Pa, E_lattice_Pa).
"""
import csv, os, re, subprocess, sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from shockfield.run import Run  # noqa: E402  (the shared run-folder reader)

STEPS = int(os.environ.get("STEPS", "4000"))


def run(sf, out, n_phi, n_h):
    case = os.path.join(os.path.dirname(os.path.abspath(__file__)), "rod_elastic.toml")
    sets = ["--set", f"specimen.n_phi={n_phi}", "--set", f"specimen.n_h={n_h}"]
    check = subprocess.run([sf, "run", case, "--check"] + sets, check=True, capture_output=True, text=True)
    dt = float(re.search(r"steps of ([0-9.e+-]+) s", check.stdout + check.stderr).group(1))
    rate = 0.001 / (STEPS * dt)
    folder = os.path.join(out, f"rod_{n_phi}_{n_h}")
    subprocess.run([sf, "run", case, "-q", "--overwrite", "--output", folder, "--set", f"loading.strain_rate={rate}",
                    "--set", f"output.thermo_every={max(STEPS // 200, 1)}"] + sets, check=True)
    result = Run.open(folder)
    strain, stress, lateral = (result.thermo[c] for c in ("Strain", "Stress", "LatStrain"))
    half = strain >= 0.5 * strain[-1]
    E = np.polyfit(strain[half], stress[half], 1)[0]
    nu = -np.polyfit(strain[half], lateral[half], 1)[0]
    get = result.value
    return [n_phi, n_h, int(get("particles")), E, nu, get("youngs_eq15"), get("youngs_lattice_001")]


def main():
    sf, out, ratio = sys.argv[1], sys.argv[2], float(sys.argv[3])
    os.makedirs(out, exist_ok=True)
    rows = []
    for n_phi in map(int, sys.argv[4:]):
        n_h = max(int(round(ratio * n_phi)), 1)
        rows.append(run(sf, out, n_phi, n_h))
        print("n_phi %d n_h %d N %d: E %.4g GPa (eq 15 %.4g, lattice %.4g), nu %.4f" %
              (rows[-1][0], rows[-1][1], rows[-1][2], rows[-1][3] / 1e9, rows[-1][5] / 1e9, rows[-1][6] / 1e9,
               rows[-1][4]), flush=True)
    with open(os.path.join(out, f"study_{sys.argv[3]}.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["n_phi", "n_h", "particles", "E_Pa", "nu", "E_eq15_Pa", "E_lattice_Pa"])
        w.writerows(rows)


if __name__ == "__main__":
    main()
