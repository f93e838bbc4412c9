#!/bin/sh
# The whole study: the Hugoniostat scan of the four Fe potentials (scan.sh -> nphug_scan.csv,
# nphug_scan.png) and the 1.2 km/s [001] piston shock in Fe_mm (run_piston.sh -> piston_profile.png).
#   examples/md_fe_alpha_epsilon/run.sh [RUNS_DIR]   (from the repository root)
set -eu
here=$(dirname "$0")
sh "$here/scan.sh" "$@"
sh "$here/run_piston.sh" "$@"
