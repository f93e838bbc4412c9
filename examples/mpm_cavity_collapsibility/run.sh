#!/bin/sh
# Collapsibility study (Xu et al. 2015, §4.2.1, Fig 53): the weak-shock single-cavity case (case.toml)
# for six cavity radii 3.5–8 µm at σ_Y0 = 120 MPa and four initial yield stresses at r = 6.2 µm,
# twice: glued (the two bodies share one grid field, as in case.toml) and with [contact] (each
# body its own field, so the impact plane parts in tension). Then collapsibility.png/.csv and
# collapsibility_contact.png/.csv (Φ at 10 ns, at the end (20 ns) and averaged over 18–20 ns).
#   examples/mpm_cavity_collapsibility/run.sh [RUNS_DIR]     (from the repository root)
# Each run is about 10 s on one core. Generated case files go next to their run folders
# (RUNS_DIR/glued/..., RUNS_DIR/contact/...).
set -eu
here=$(dirname "$0")
runs=${1:-runs/mpm_cavity_collapsibility}
bin=${SHOCKFIELD:-./build/release/shockfield}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}

run_one() {  # variant (glued|contact) radius_um yield_MPa
    dir="$runs/$1"
    name="r${2}um_Y${3}MPa"
    mkdir -p "$dir"
    sed -e "s/^cavity_radius = .*/cavity_radius = ${2}e-6/" \
        -e "s/^yield_stress = .*/yield_stress = ${3}e6/" "$here/case.toml" > "$dir/$name.toml"
    grep -q "^cavity_radius = ${2}e-6" "$dir/$name.toml"
    grep -q "^yield_stress = ${3}e6" "$dir/$name.toml"
    if [ "$1" = contact ]; then printf '\n[contact]\nenabled = true\n' >> "$dir/$name.toml"; fi
    if [ -f "$dir/$name/series.csv" ] && grep -q '^finished' "$dir/$name/log.txt" 2>/dev/null; then
        echo "$1/$name: done already"; return
    fi
    rm -rf "${dir:?}/$name"
    "$bin" run "$dir/$name.toml" -o "$dir/$name" -j1 | tail -1
}

for variant in glued contact; do
    for r in 3.5 4.4 5.3 6.2 7.1 8; do run_one "$variant" "$r" 120; done  # radius series at σ_Y0 = 120 MPa
    for y in 40 240 360; do run_one "$variant" 6.2 "$y"; done             # yield series at r = 6.2 µm
done

PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.mpm_study collapsibility "$runs"/glued/r*um_Y*MPa \
    --late 18e-9 --at 10e-9 --out "$here/collapsibility.png" --csv "$here/collapsibility.csv"
PYTHONPATH=python /usr/bin/python3 -m shockfield_plot.mpm_study collapsibility "$runs"/contact/r*um_Y*MPa \
    --late 18e-9 --at 10e-9 --out "$here/collapsibility_contact.png" --csv "$here/collapsibility_contact.csv"
