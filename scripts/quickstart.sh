#!/usr/bin/env bash
# Builds shockfield and runs the main example: a piston-driven shock in an EAM copper crystal.
# Leaves the run folder in runs/cu_shock/ (log, thermo, binned profiles, dumps, plot).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target shockfield
./build/release/shockfield run examples/md_shock_piston/case.toml --output runs/cu_shock --overwrite
./build/release/shockfield plot profiles runs/cu_shock
