#!/bin/sh
# Crack branching in a pre-notched soda-lime glass plate (2D PMB, ΔX = 0.5 mm, about 13 s on one
# core): the run, then branching.png (damage and the crack tip against time) and the crack speed
# against the Rayleigh speed (analyze.py). CHECK=1: fail unless the crack runs below the Rayleigh
# speed, branches, and the damage and velocities stay mirror-symmetric about the notch line.
# COARSE=1: case_coarse.toml (ΔX = 1 mm, about 1.5 s) instead, checked for a crack running below
# the Rayleigh speed and for the symmetry (the default suite's stand-in).
#   examples/pd_crack_branching/run.sh [RUNS_DIR]   (from the repository root; SHOCKFIELD=path/to/shockfield)
set -eu
. "$(dirname "$0")/../run_common.sh"
if [ "${COARSE:-0}" = 1 ]; then
  case_file="$here/case_coarse.toml" run="$runs/branching_coarse" horizon=3e-3 check="--check --check-symmetry"
else
  case_file="$here/case.toml" run="$runs/branching" horizon=1.5e-3 check="--check-branching --check-symmetry"
fi
rm -rf "$run"
"$bin" run "$case_file" -o "$run" -j1 | tail -1
if [ "${CHECK:-0}" != 1 ]; then check=""; fi
status=0
/usr/bin/python3 "$here/analyze.py" "$run" --notch 0.05 --horizon "$horizon" --plot "${PLOT:-$run/branching.png}" \
  $check >"$run/crack.txt" || status=$?
cat "$run/crack.txt"
exit "$status"
