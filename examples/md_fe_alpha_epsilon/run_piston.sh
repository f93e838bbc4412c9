#!/bin/sh
# The [001] piston shock in bcc Fe (piston.toml, 1.2 km/s): the run, then a-CNA profiles along z of
# every dump (profiles.csv) and piston_profile.png (structure fractions along z at the last dump).
#   examples/md_fe_alpha_epsilon/run_piston.sh [RUNS_DIR]   (from the repository root)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/piston" "$runs/piston_analysis"
OMP_WAIT_POLICY=passive "$bin" run "$here/piston.toml" -o "$runs/piston" -j2 -q
"$bin" analyze atoms "$runs/piston" --adaptive-cna --profile z:11.4212 -o "$runs/piston_analysis" -j2 | tail -1
/usr/bin/python3 "$here/plot_piston.py" "$runs/piston_analysis/profiles.csv" "$runs/piston" "$here/piston_profile.png"
