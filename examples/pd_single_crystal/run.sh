#!/bin/sh
# Cu single crystals shocked along [100] and [111] (Liu et al. 2025, Figs 6-8): two runs, then crystal.png; the 50 m/s [111] run and c111_evolution.png.
#   examples/pd_single_crystal/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
for c in c100 c111 c111_50; do
  rm -rf "$runs/$c"
  "$bin" run "$here/$c.toml" -o "$runs/$c" -j1 | tail -1
done
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.pd_plots crystal "$runs/c100" "$runs/c111" \
  --labels "[100] single crystal" "[111] single crystal" --out "$here/crystal.png"
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.pd_plots bar "$runs/c111_50" "$runs/c111" \
  --labels "[111], 50 m/s" "[111], 100 m/s" --out "$here/c111_evolution.png"
