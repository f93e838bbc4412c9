#!/bin/sh
# Piston shock at 1 km/s in EAM copper: the run, its Hugoniot state (hugoniot_shock.toml) and profiles.png (about a minute on two cores).
#   examples/md_shock_piston/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
here=$(dirname "$0")
runs=${1:-runs/md_shock_piston}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot profiles "$runs/run" -o "$here/profiles.png"
cat "$runs/run/hugoniot_shock.toml"
