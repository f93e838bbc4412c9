#!/usr/bin/env bash
# From atoms to a plate: Cu EAM (Cu_u3.eam) → MD elastic constants, an MD Hugoniot sweep, an MD
# tension run (spall) and an MD [111] compression (yield) → one material file with provenance
# (shockfield bridge) → MPM symmetric plate impacts at the swept particle velocities, an MPM
# flyer-plate spall run and PD [100], [110], [111] crystal bars on that file → bridge_cu.png.
# Usage: run.sh [OUT] (default runs/bridge_cu); SF=path/to/shockfield, SPEEDS=0.5,0.8,1.1,1.4 (km/s),
# PLOT=where the picture goes, CHECK=1 to fail unless the round-trip bounds hold (plot.py --check).
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
SF=${SF:-shockfield}
OUT=${1:-runs/bridge_cu}
SPEEDS=${SPEEDS:-0.5,0.8,1.1,1.4}
PY=/usr/bin/python3
export OMP_WAIT_POLICY=passive
mkdir -p "$OUT"
now() { date +%s.%N; }

t0=$(now)
# MD: the Hugoniot sweep and the zero-temperature elastic constants of the same potential.
"$SF" hugoniot "$HERE/md_piston.toml" --speeds "$SPEEDS" -o "$OUT/md_sweep" -q --overwrite
"$SF" bridge elastic --potential Cu_u3.eam --a0 3.615 --name cu_md -o "$OUT/cu_md.toml"
# ... a uniaxial-strain tension past void nucleation and a [111] compression past yield.
"$SF" run "$HERE/md_tension.toml" -o "$OUT/md_tension" -q --overwrite
"$SF" run "$HERE/md_compression_111.toml" -o "$OUT/md_compression_111" -q --overwrite
t1=$(now)
# The bridge: the sweep's Us-Up fit and Gamma0 from two constant-volume MD runs into the same file
# (linear: MPM's EOS is linear in Up).
"$SF" bridge hugoniot-to-eos "$OUT/md_sweep" --quadratic no --gamma0-md --update --name cu_md -o "$OUT/cu_md.toml"
# The spall strength and the yield ([spall], [strength]) into the same file.
"$SF" bridge spall "$OUT/md_tension" --update --name cu_md -o "$OUT/cu_md.toml" > "$OUT/bridge_spall.txt"
"$SF" bridge yield "$OUT/md_compression_111" --update --name cu_md -o "$OUT/cu_md.toml" > "$OUT/bridge_yield.txt"
t2=$(now)
# MPM: symmetric impacts at the MD particle velocities (strength from the case: MD gives none).
ups=$($PY -c "import csv, sys; print(' '.join(r['up_km_s'] for r in csv.DictReader(open(sys.argv[1]))))" \
  "$OUT/md_sweep/hugoniot_sweep.csv")
$PY "$HERE/mpm_hugoniot.py" "$SF" "$OUT/cu_md.toml" "$OUT/mpm" $ups --yield 120e6 > "$OUT/mpm_states.txt"
# MPM spall: a flyer-plate impact on the bridged spall strength, and the same without failure.
mpm_spall() {
  "$SF" run "$HERE/mpm_spall.toml" -o "$OUT/$1" -q --overwrite --set "material[0].file=\"$(realpath "$OUT/cu_md.toml")\"" "${@:2}"
}
mpm_spall mpm_spall_bridged
mpm_spall mpm_spall_none --set "material[0].spall_strength=0.0"
t3=$(now)
# PD: elastic waves along three crystal directions.
: > "$OUT/pd_speeds.txt"
for dir in 100 110 111; do
  "$SF" run "$HERE/pd_bar.toml" -o "$OUT/pd_$dir" -q --overwrite --set "material.file=\"$(realpath "$OUT/cu_md.toml")\"" \
    --set "material.direction=[${dir:0:1}, ${dir:1:1}, ${dir:2:1}]"
  echo "$dir $($PY "$HERE/pd_front_speed.py" "$OUT/pd_$dir" 2.0)" >> "$OUT/pd_speeds.txt"
done
t4=$(now)
$PY -c "import sys; t = list(map(float, sys.argv[1:])); print(f'md {t[1]-t[0]:.1f}\nbridge+gamma0_md {t[2]-t[1]:.1f}\nmpm {t[3]-t[2]:.1f}\npd {t[4]-t[3]:.1f}')" \
  "$t0" "$t1" "$t2" "$t3" "$t4" > "$OUT/timings.txt"
$PY "$HERE/plot.py" "$OUT" "${PLOT:-$HERE/bridge_cu.png}" ${CHECK:+--check}
