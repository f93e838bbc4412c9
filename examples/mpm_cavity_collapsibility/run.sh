#!/bin/sh
# Collapsibility study (seed 000 §4.2.1, Fig 53): the weak-shock single-cavity case (case.toml)
# for three cavity radii at σ_Y0 = 120 MPa and three initial yield stresses at r = 5 µm, then
# collapsibility.png and collapsibility.csv (Φ at the end and averaged over 12–16 ns).
#   examples/mpm_cavity_collapsibility/run.sh [RUNS_DIR]     (from the repository root)
# Each run is about 10 s on one core. Generated case files go next to their run folders.
set -eu
here=$(dirname "$0")
runs=${1:-runs/mpm_cavity_collapsibility}
bin=${SHOCKFIELD:-./build/release/shockfield}
mkdir -p "$runs"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}

run_one() {  # radius_um yield_MPa
    name="r${1}um_Y${2}MPa"
    sed -e "s/^cavity_radius = .*/cavity_radius = ${1}e-6/" \
        -e "s/^yield_stress = .*/yield_stress = ${2}e6/" "$here/case.toml" > "$runs/$name.toml"
    grep -q "^cavity_radius = ${1}e-6" "$runs/$name.toml"
    grep -q "^yield_stress = ${2}e6" "$runs/$name.toml"
    if [ -f "$runs/$name/series.csv" ] && grep -q '^finished' "$runs/$name/log.txt" 2>/dev/null; then
        echo "$name: done already"; return
    fi
    rm -rf "${runs:?}/$name"
    "$bin" run "$runs/$name.toml" -o "$runs/$name" -j1 | tail -1
}

for r in 2 3.5 5; do run_one "$r" 120; done     # radius series at σ_Y0 = 120 MPa
for y in 40 360; do run_one 5 "$y"; done        # yield series at r = 5 µm (120 MPa above)

/usr/bin/python3 python/shockfield_plot/mpm_study.py collapsibility "$runs"/r*um_Y*MPa \
    --late 12e-9 --out "$here/collapsibility.png" --csv "$here/collapsibility.csv"
