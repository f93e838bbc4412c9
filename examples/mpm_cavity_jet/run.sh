#!/bin/sh
# Single-cavity collapse: jetting at 1500 m/s and the slow partial collapse at 200 m/s, then cavity.png (about a minute of CPU each).
#   examples/mpm_cavity_jet/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/jet1500" "$runs/jet200"
"$bin" run "$here/case.toml" -o "$runs/jet1500" -j2 | tail -1
sed "s/speed = 1500.0/speed = 200.0/; s/end_time = 8e-9/end_time = 20e-9/" "$here/case.toml" > "$runs/jet200.toml"
grep -q "speed = 200.0" "$runs/jet200.toml"
"$bin" run "$runs/jet200.toml" -o "$runs/jet200" -j2 | tail -1
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.mpm_plots cavity "$runs/jet1500" "$runs/jet200" --out "$here/cavity.png"
