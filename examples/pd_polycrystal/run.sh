#!/bin/sh
# A shocked Cu polycrystal beside the [100] and [111] single crystals (Liu et al. 2025, Figs 9-12), then polycrystal.png.
#   examples/pd_polycrystal/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
for c in c100 c111; do
  rm -rf "$runs/$c"
  "$bin" run "$here/../pd_single_crystal/$c.toml" -o "$runs/$c" -j1 | tail -1
done
rm -rf "$runs/polycrystal"
"$bin" run "$here/polycrystal.toml" -o "$runs/polycrystal" -j1 | tail -1
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.pd_plots crystal "$runs/c100" "$runs/c111" "$runs/polycrystal" \
  --labels "[100] single crystal" "[111] single crystal" "polycrystal" --out "$here/polycrystal.png"
