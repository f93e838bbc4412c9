#!/usr/bin/env bash
# Runs the granular chain examples with `shockfield run` and redraws the pictures of this folder
# from the run folders (about a minute on one core). Usage: examples/granular_chain/run.sh [RUNS]
# with RUNS the folder for the run folders (default: runs/granular_chain); SHOCKFIELD may name the
# binary (default: build/release/shockfield).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
sf="${SHOCKFIELD:-$root/build/release/shockfield}"
runs="${1:-runs/granular_chain}"
run() {  # run NAME CASE [--set KEY=VALUE ...]
  local name="$1" case_file="$2"; shift 2
  "$sf" run "$here/$case_file" --output "$runs/$name" --overwrite -q -j 1 "$@"
}
run horizontal_soliton horizontal_soliton.toml
run horizontal_train horizontal_train.toml
run column_weak column_weak.toml
# The strongly nonlinear regime: a 10^4 times stronger impulse, sampled 200 times over 12 ms.
run column_strong column_weak.toml --set impulse.velocity=1.0 --set run.end_time=0.012 \
  --set output.signal_interval=6e-5 --set output.field_interval=6e-5
# The drift of the depth exponents with the impulse (exponent_drift.png): the same column at
# 1e-3 ... 5 m/s over 12 ms.
for v in 0.001 0.01 0.1 5; do
  run "column_v$v" column_weak.toml --set "impulse.velocity=$v" --set run.end_time=0.012 \
    --set output.signal_interval=6e-5 --set output.field_interval=6e-5
done
run column_light_impurity column_light_impurity.toml
run column_heavy_impurity column_light_impurity.toml --set 'impurity[0].mass_ratio=10.0'
# The same column without the impurity: what the impurity runs are compared against.
run column_no_impurity column_light_impurity.toml --set 'impurity[0].mass_ratio=1.0'
PYTHONPATH="$root/python" /usr/bin/python3 "$here/plot.py" "$runs"
