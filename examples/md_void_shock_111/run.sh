#!/bin/sh
# A 1.5 km/s piston shock along [111] over a 1 nm void in copper: the run, profiles.png, the void followed by analyze atoms --voids (voids.csv) and void_volume.png (its volume against time).
#   examples/md_void_shock_111/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run" "$runs/voids"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -3
"$bin" plot profiles "$runs/run" -o "$here/profiles.png"
"$bin" analyze atoms "$runs/run" --voids 2.17 --voids-min-volume 50 -o "$runs/voids" | tail -1
/usr/bin/python3 "$here/plot_void.py" "$runs/voids" "$runs/run" "$here/void_volume.png"
