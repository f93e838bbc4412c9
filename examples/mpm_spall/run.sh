#!/bin/sh
# Spall in a flyer-plate impact: case.toml (spall_strength = 1 GPa) and a copy without the spall
# model, then spall.png (free-surface velocity against time for both, damage and density of the
# target at the end) and spall.csv (the pull-back and the spall strength it gives).
#   examples/mpm_spall/run.sh [RUNS_DIR]     (from the repository root)
set -eu
here=$(dirname "$0")
runs=${1:-runs/mpm_spall}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}

cp "$here/case.toml" "$runs/spall.toml"
sed -e "s/^spall_strength = .*/spall_strength = 0.0/" "$here/case.toml" > "$runs/no_spall.toml"
grep -q "^spall_strength = 0.0" "$runs/no_spall.toml"
for name in spall no_spall; do
    rm -rf "${runs:?}/$name"
    "$bin" run "$runs/$name.toml" -o "$runs/$name" -j1 | tail -1
done

/usr/bin/python3 "$here/spall.py" "$runs/spall" "$runs/no_spall" --out "$here/spall.png" --csv "$here/spall.csv"
