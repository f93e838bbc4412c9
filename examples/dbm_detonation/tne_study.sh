#!/bin/sh
# The detonation TNE study: local and global TNE against the relaxation time τ (μ = pτ and the heat
# conductivity ∝ pτ together: the BGK model has one relaxation time, Pr = 1), and the sign change of
# Δ*_2xx across the von Neumann peak at three grids; then tne_table.md and tne_viscosity.png.
#   examples/dbm_detonation/tne_study.sh [RUNS_DIR]     (from the repository root)
# 7 runs, 1 thread each, 2 at a time: 238 s wall measured (the τ runs 52–61 s each); up to 15–20
# min when the 2 cores are shared with other work.
set -eu
here=$(dirname "$0")
runs=${1:-runs/dbm_detonation_tne}
bin=${SHOCKFIELD:-./build/release/shockfield}
sweep() { nice -n 10 "$bin" sweep "$here/tne.toml" -j 2 --threads 1 --overwrite "$@" > /dev/null; }
sweep -o "$runs/tau" --set model.tau=2.5e-3,5e-3,1e-2,2e-2
sweep -o "$runs/dx0.005" --set model.tau=5e-3,1e-2 --set grid.nx=1000 --set grid.dx=0.005
sweep -o "$runs/dx0.00125" --set model.tau=5e-3 --set grid.nx=4000 --set grid.dx=0.00125
PYTHONPATH=python /usr/bin/python3 "$here/tne_study.py" "$runs" --table "$here/tne_table.md" \
    --out "$here/tne_viscosity.png"
