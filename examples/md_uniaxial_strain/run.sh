#!/bin/sh
# Uniaxial strain at a constant rate in EAM copper: the run and thermo.png (stress and energy against time).
#   examples/md_uniaxial_strain/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
here=$(dirname "$0")
runs=${1:-runs/md_uniaxial_strain}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot thermo "$runs/run" -o "$here/thermo.png"
