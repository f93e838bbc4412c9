#!/bin/sh
# The Hugoniostat for [100] EAM copper at four pressures: the pressures ρ0·Us·Up of the piston
# sweep of docs/md-validation.md (piston 0.5, 1.0, 1.5 km/s: 22.37, 48.10, 79.93 GPa) and the
# MSST state of examples/md_msst_cu (82.55 GPa at Us = 5.964 km/s, relaxed start); prints each
# run's Hugoniot state and draws nphug.png. About 6 minutes on two cores (four runs of 2160 atoms,
# two at a time).
#   examples/md_nphug_cu/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
pressures="223700 481000 799300 825500"   # bar
for p in $pressures; do rm -rf "$runs/p$p"; done
run_one() { "$bin" run "$here/case.toml" -o "$runs/p$1" -j1 -q --set "stage[1].nphug.pressure=$1" > /dev/null; }
run_one 223700 & run_one 481000 & wait
run_one 799300 & run_one 825500 & wait
for p in $pressures; do grep "Hugoniostat" "$runs/p$p/log.txt"; done
/usr/bin/python3 "$here/plot_nphug.py" "$here/nphug.png" $(for p in $pressures; do echo "$runs/p$p"; done)
