#!/bin/sh
# Cu under uniaxial tension along [110] at 1e10 /s (Xu et al. 2015, Fig 65): the run, the structure
# analysis of every dump (adaptive and conventional CNA, coordination), Burgers circuits around the
# defect clusters (burgers_frames.sh) and around the partials that bound the stacking faults
# (burgers_partials.py), tension.png, and the voids that open at the end (voids.png). About 6 minutes on two idle cores.
#   examples/md_cu_tension_partials/run.sh [RUNS_DIR]   (from the repository root; SHOCKFIELD=path/to/shockfield to choose the binary)
set -eu
. "$(dirname "$0")/../run_common.sh"
rm -rf "$runs/run" "$runs/analysis" "$runs/burgers" "$runs/sf"
export OMP_WAIT_POLICY=passive
"$bin" run "$here/case.toml" -o "$runs/run" -j2 -q
# Every frame: a-CNA (1 fcc, 2 hcp, 3 bcc, 5 other), CNA at 3.0858 Å (Xu et al.'s codes), coordination
# within 3.0858 Å (their 12 and 13), the defect clusters.
"$bin" analyze atoms "$runs/run" --adaptive-cna --cna 3.0858 --coordination 3.0858 \
  --clusters 3.0 --cluster-select 'acna:!fcc,hcp' --cluster-min-size 10 -o "$runs/analysis" -j2 | tail -1
# The stacking faults: clusters of hcp atoms.
"$bin" analyze atoms "$runs/run" --clusters 3.0 --cluster-select 'acna:hcp' --cluster-min-size 40 -o "$runs/sf" -j2 | tail -1
# Burgers circuits: around each elongated core cluster (frame by frame) and around the edges of each
# stacking fault, from just before the first stacking faults (strain 0.11) to strain 0.14.
frames=$(ls "$runs"/run/dumps/dump.*.lammpstrj | awk -F. '{ s = $(NF-1) + 0; if (s >= 6500 && s <= 8000) print }')
sh "$here/burgers_frames.sh" "$bin" "$runs/burgers" $frames
for f in $frames; do /usr/bin/python3 "$here/burgers_partials.py" "$bin" "$f" "$runs/sf/clusters.csv" "$runs/burgers/partials.csv"; done
/usr/bin/python3 "$here/plot.py" "$runs/run" "$runs/analysis" "$runs/burgers" "$here/tension.png"
# The voids that open at the end (rolling ball R = 0.6 a; margin 28 Å, half the box, so that a large
# void across a periodic face is found whole), their volume against time: voids.png.
late=$(ls "$runs"/run/dumps/dump.*.lammpstrj | awk -F. '{ s = $(NF-1) + 0; if (s >= 7000) print }')
"$bin" analyze atoms $late --voids 2.17 --voids-min-volume 20 --voids-margin 28 -o "$runs/voids" -j2 | tail -1
/usr/bin/python3 "$here/plot_voids.py" "$runs/run" "$runs/voids" "$here/voids.png"
