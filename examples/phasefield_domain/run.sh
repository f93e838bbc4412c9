#!/usr/bin/env bash
# The disc of case.toml at a = 0.45 (grows: R0 > R*) and a = 0.5 (shrinks), then plot.py draws
# R(t) beside the analytic laws (radius.png). About 15 s of CPU per run.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${SHOCKFIELD:-$here/../../build/release/shockfield}
out=${1:-runs/$(basename "$here")}   # beside the other examples' runs, not in the source tree
mkdir -p "$out"
for a in 0.45 0.5; do
  OMP_NUM_THREADS=1 "$exe" run "$here/case.toml" --set model.a=$a --output "$out/a$a" --overwrite --quiet
done
/usr/bin/python3 "$here/plot.py" "$out"
