#!/bin/sh
# Collapsibility study (Xu et al. 2015, §4.2.1, Fig 53): the weak-shock single-cavity case (case.toml)
# for six cavity radii 3.5–8 µm at σ_Y0 = 120 MPa and four initial yield stresses at r = 6.2 µm,
# then collapsibility.png and collapsibility.csv (Φ at 10 ns, at the end (20 ns) and averaged
# over 18–20 ns).
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

for r in 3.5 4.4 5.3 6.2 7.1 8; do run_one "$r" 120; done  # radius series at σ_Y0 = 120 MPa
for y in 40 240 360; do run_one 6.2 "$y"; done             # yield series at r = 6.2 µm (and 120 MPa)

PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.mpm_study collapsibility "$runs"/r*um_Y*MPa \
    --late 18e-9 --at 10e-9 --out "$here/collapsibility.png" --csv "$here/collapsibility.csv"
