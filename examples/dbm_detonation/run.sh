#!/bin/sh
# One-dimensional detonation with the reactive DBM: case.toml (fast reaction, for the speed) and
# structure.toml (slow reaction, resolved zone, for the TNE around the von Neumann peak), then
# detonation.png and the measured numbers of README.md.
#   examples/dbm_detonation/run.sh [RUNS_DIR] [tne]     (from the repository root)
# With `tne`, also the TNE study against τ (tne_study.sh: `shockfield sweep`s, 4 min wall, longer under load).
# About 5-15 s per case (the DBM threads over 64-cell chunks of rows, so 1D runs use all cores).
set -eu
here=$(dirname "$0")
runs=${1:-runs/dbm_detonation}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"

for case in case structure; do
    "$bin" run "$here/$case.toml" --output "$runs/$case" --overwrite -q
done
PYTHONPATH=python /usr/bin/python3 "$here/detonation.py" "$runs/case" "$runs/structure" --out "$here/detonation.png"
if [ "${2:-}" = tne ]; then
    "$here/tne_study.sh" "$runs/tne"
fi
