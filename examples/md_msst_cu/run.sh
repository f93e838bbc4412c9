#!/bin/sh
# MSST shock in EAM copper at Us = 5.964 km/s from two initial states (case.toml,
# case_unrelaxed.toml) and, for comparison, the piston run that drives a
# shock of that speed (examples/md_shock_piston at 1.5 km/s); prints both Hugoniot states and draws
# msst.png; piston_scatter.py gives the frame-to-frame scatter of the piston's state. About 15
# minutes on two cores (two MSST runs, one piston run).
#   examples/md_msst_cu/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/msst" "$runs/msst_unrelaxed" "$runs/piston"
"$bin" run "$here/case.toml" -o "$runs/msst" -j2 | tail -3
"$bin" run "$here/case_unrelaxed.toml" -o "$runs/msst_unrelaxed" -j2 | tail -3
"$bin" run "$here/../md_shock_piston/case.toml" -o "$runs/piston" -j2 --set 'stage[1].piston.speed=15.0' | tail -3
grep "MSST at" "$runs/msst/log.txt" "$runs/msst_unrelaxed/log.txt"
cat "$runs/piston/hugoniot_shock.toml"
/usr/bin/python3 "$here/piston_scatter.py" "$runs/piston"
/usr/bin/python3 "$here/plot_msst.py" "$here/msst.png" "$runs/piston/hugoniot_shock.toml" \
  "$runs/msst=relaxed start (rho0 8.83)" "$runs/msst_unrelaxed=unrelaxed start (rho0 8.94)"
