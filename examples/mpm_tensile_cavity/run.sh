#!/bin/sh
# Tensile loading of a single cavity (Xu et al. 2015, §4.2.2): case.toml at 100 m/s and a copy at
# 400 m/s, then cavity.png (existing helper: temperature snapshot and Φ against time) and
# pressure.png (this folder: particle pressure at chosen times, where the tension is highest).
#   examples/mpm_tensile_cavity/run.sh [RUNS_DIR]     (from the repository root)
# Each run is a few seconds on one core.
set -eu
here=$(dirname "$0")
runs=${1:-runs/mpm_tensile_cavity}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}

for v in 100 400; do
    sed -e "s/^speed = .*/speed = ${v}.0/" "$here/case.toml" > "$runs/v$v.toml"
    grep -q "^speed = ${v}.0" "$runs/v$v.toml"
    rm -rf "${runs:?}/v$v"
    "$bin" run "$runs/v$v.toml" -o "$runs/v$v" -j1 | tail -1
done

PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.mpm_plots cavity "$runs/v100" "$runs/v400" --out "$here/cavity.png"
/usr/bin/python3 "$here/tension.py" "$runs/v100" "$runs/v400" --times 4e-9 8e-9 --out "$here/pressure.png" \
    --csv "$here/cavity_area.csv"
# The README's table, one line per run and time (tests/cli/docs_values.sh checks it): "v100 t = 14 ns: A_um2 = 128.61, Phi = -0.6280"
awk -F, 'NR > 1 { printf "%s t = %g ns: A_um2 = %.2f, Phi = %s\n", $1, $2 * 1e9, $3 * 1e12, $4 }' "$here/cavity_area.csv"
