#!/usr/bin/env bash
# Builds shockfield and runs the main example: porous aluminium hitting a rigid wall at 1000 m/s
# (material point method, Xu et al. (2015) §4.1.1, Fig 19). Leaves the run folder runs/mpm_porous_al/
# (log, resolved configuration, window time series, VTK fields and particles for ParaView,
# checkpoint) and the picture runs/mpm_porous_al/porous.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target shockfield
./build/release/shockfield run examples/mpm_porous_al/case.toml --output runs/mpm_porous_al --overwrite
./build/release/shockfield plot porous runs/mpm_porous_al
