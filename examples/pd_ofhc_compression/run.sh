#!/bin/sh
# OFHC copper simple compression (seed 004 §4.1, Fig. 5): 50 random grains under the Taylor
# assumption along eq. 44, then compression.png, orientations.png and the numbers quoted in README.md.
#   examples/pd_ofhc_compression/run.sh [RUNS_DIR]     (from the repository root)
# About 6 s on two threads.
set -eu
here=$(dirname "$0")
runs=${1:-runs}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
"$bin" run "$here/ofhc_compression.toml" -o "$runs/ofhc_compression" --overwrite -j2 | tail -1
/usr/bin/python3 python/shockfield_plot/pd_plots.py compression "$runs/ofhc_compression" \
    --out "$here/compression.png"
/usr/bin/python3 python/shockfield_plot/pd_plots.py orientations "$runs/ofhc_compression" \
    --out "$here/orientations.png"
