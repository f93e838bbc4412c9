#!/bin/sh
# Riemann-corrected elastic and elastic-plastic waves in a PD bar (Liu et al. 2025, Figs 2-4): three runs, then bar.png.
#   examples/pd_bar_elastic_plastic/run.sh [RUNS_DIR]     (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
for c in bar_30 bar_30_plain bar_300; do
  rm -rf "$runs/$c"
  "$bin" run "$here/$c.toml" -o "$runs/$c" -j1 | tail -1
done
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.pd_plots bar "$runs/bar_30" "$runs/bar_30_plain" "$runs/bar_300" \
  --labels "30 m/s, Riemann-corrected" "30 m/s, uncorrected (eq. 11)" "300 m/s, Riemann-corrected" \
  --out "$here/bar.png"
