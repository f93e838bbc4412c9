#!/bin/sh
# Kalthoff–Winkler edge-notched plate impact (2D PMB, ΔX = 1 mm): one run, then damage.png with the
# crack angle measured at both notch tips. CHECK=1: fail unless both cracks grew, symmetric within
# 1°, forward and outward (45°–90°; the experiment's ~70° is not reached at this resolution: README).
# FINE=1: also the runs at ΔX = 0.5 and 0.25 mm (about 70 s and 10 min) and convergence.png.
#   examples/pd_kalthoff_winkler/run.sh [RUNS_DIR]   (from the repository root; SHOCKFIELD=path/to/shockfield)
set -eu
. "$(dirname "$0")/../run_common.sh"
export PYTHONPATH=python
plot="/usr/bin/python3 -m shockfield_plot.pd_plots damage"
rm -rf "$runs/kw"
"$bin" run "$here/case.toml" -o "$runs/kw" -j1 | tail -1
$plot "$runs/kw" --labels "PMB, ΔX = 1 mm, δ = 3.015ΔX" --out "${PLOT:-$here/damage.png}" | tee "$runs/kw/angles.txt"
if [ "${CHECK:-0}" = 1 ]; then
  sed -n 's/.* at \([0-9.]*\) deg .*/\1/p' "$runs/kw/angles.txt" |
    awk '{ a[n++] = $1 } END { if (n != 2 || a[0] - a[1] > 1 || a[1] - a[0] > 1 || a[0] < 45 || a[0] > 90) {
                                 print "crack angles off: " a[0] ", " a[1]; exit 1 } }'
fi
if [ "${FINE:-0}" = 1 ]; then
  for dx in 0.5mm 0.25mm; do
    rm -rf "$runs/kw_$dx"
    "$bin" run "$here/case_$dx.toml" -o "$runs/kw_$dx" -j1 | tail -1
  done
  $plot "$runs/kw" "$runs/kw_0.5mm" "$runs/kw_0.25mm" --labels "ΔX = 1 mm" "ΔX = 0.5 mm" "ΔX = 0.25 mm" \
    --out "$here/convergence.png"
fi
