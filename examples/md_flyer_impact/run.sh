#!/bin/sh
# Symmetric flyer-plate impact in EAM copper (two plates at ±0.5 km/s): the run and profiles.png, the two fronts moving apart.
#   examples/md_flyer_impact/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot profiles "$runs/run" -o "$here/profiles.png"
