#!/bin/sh
# Porous aluminium on a rigid wall at 1000 m/s (the main example): the run and porous.png, window means beside Xu et al. (2015) Figs 18-19,
# and front.png, the shock front and plateau window of the shock-front tool.
#   examples/mpm_porous_al/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run"
"$bin" run "$here/case.toml" -o "$runs/run" -j2 | tail -1
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.mpm_plots porous "$runs/run" --out "$here/porous.png"
PYTHONPATH=python /usr/bin/python3 "$here/front.py" "$runs/run" "$here/front.png"
