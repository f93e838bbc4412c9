#!/bin/sh
# Uniaxial strain at a constant rate in EAM copper: the run and thermo.png (stress and energy against time).
#   examples/md_uniaxial_strain/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot thermo "$runs/run" -o "$here/thermo.png"
