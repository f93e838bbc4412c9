#!/bin/sh
# OFHC copper simple compression (Liu et al. 2025, §4.1, Fig. 5): 50 random grains under the Taylor
# assumption along eq. 44 with the paper's sech² hardening (eq. 40) and again with Kalidindi et al.'s
# power-law hardening (--set material.hardening_law="power"), then compression.png, orientations.png and the
# numbers quoted in README.md.
#   examples/pd_ofhc_compression/run.sh [RUNS_DIR]     (from the repository root)
# About 12 s on two threads.
set -eu
here=$(dirname "$0")
runs=${1:-runs}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
"$bin" run "$here/ofhc_compression.toml" -o "$runs/ofhc_compression" --overwrite -j2 | tail -1
"$bin" run "$here/ofhc_compression.toml" --set 'material.hardening_law="power"' -o "$runs/ofhc_compression_power" \
    --overwrite -j2 | tail -1
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.pd_plots compression "$runs/ofhc_compression" \
    "$runs/ofhc_compression_power" --labels "sech² hardening (eq. 40)" "power-law hardening (Kalidindi 1992)" \
    --johnson-cook 90,292,0.31,0.025 --reference-label "OFHC Cu, Johnson & Cook 1983 fit to experiment" \
    --out "$here/compression.png"
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.pd_plots orientations "$runs/ofhc_compression" \
    --out "$here/orientations.png"
