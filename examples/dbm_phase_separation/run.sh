#!/usr/bin/env bash
# Thermal phase separation for several surface-tension coefficients K (Xu et al. 2015, §4.3, Figs. 63-64):
# one run of case.toml per K, then plot.py (pictures, curves, table). 64 x 64 cells, t = 4 each;
# about 60-90 s of CPU per run on this machine (runs go two at a time).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exe=${SHOCKFIELD:-$here/../../build/release/shockfield}
out=${1:-runs/$(basename "$here")}   # beside the other examples' runs, not in the source tree
mkdir -p "$out"
Ks=(2e-5 4e-5 6e-5 9e-5 1.2e-4 1.8e-4 3e-4)
for K in "${Ks[@]}"; do
  sed "s/^K = .*/K = $K/" "$here/case.toml" > "$out/case_K$K.toml"
  OMP_NUM_THREADS=1 "$exe" run "$out/case_K$K.toml" --output "$out/K$K" --overwrite --quiet &
  if (( $(jobs -r | wc -l) >= 2 )); then wait -n || true; fi  # a run that blows up keeps its output
done
wait || true
/usr/bin/python3 "$here/plot.py" "$out" "${Ks[@]}"
