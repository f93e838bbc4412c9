#!/bin/sh
# Piston shock at 1 km/s in EAM copper: the run, its Hugoniot state (hugoniot_shock.toml) and profiles.png (about a minute on two cores).
#   examples/md_shock_piston/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot profiles "$runs/run" -o "$here/profiles.png"
cat "$runs/run/hugoniot_shock.toml"
