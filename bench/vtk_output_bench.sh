#!/usr/bin/env bash
# VTK output per format on the porous MPM example (97,226 particles): the example cut to 2 ns with
# a grid and a particle frame every 0.5 ns (5 of each), one thread, each format run REPS times,
# formats alternated. Prints the size of one particle (.vtp) and one grid (.vti) frame and the
# median wall time of the run's output phase per frame (log.txt, "wall time: ... output").
#   bench/vtk_output_bench.sh [SHOCKFIELD] [REPS]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SF=${1:-$ROOT/build/release/shockfield}
REPS=${2:-3}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
formats="ascii:float64 base64:float64 raw:float64 raw:float32 zlib:float64 zlib:float32"
for f in $formats; do
  sed -e "s/^end_time = .*/end_time = 2e-9/" -e "s/^field_interval = .*/field_interval = 0.5e-9/" \
      -e "s/^series_interval = .*/series_interval = 1e-9/" -e "s/^histogram_times = .*/histogram_times = [1e-9]/" \
      -e "s/^\[output\]/[output]\nvtk_encoding = \"${f%:*}\"\nvtk_precision = \"${f#*:}\"/" \
      "$ROOT/examples/mpm_porous_al/case.toml" > "$WORK/${f/:/_}.toml"
done
for rep in $(seq "$REPS"); do
  for f in $formats; do
    name=${f/:/_}
    rm -rf "$WORK/$name"
    OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive "$SF" run "$WORK/$name.toml" -o "$WORK/$name" -q > /dev/null
    sed -n 's/.*, output \([0-9.e+-]*\) s,.*/\1/p' "$WORK/$name/log.txt" | tail -1 >> "$WORK/$name.times"
  done
done
printf "%-14s %12s %12s %16s\n" format "vtp bytes" "vti bytes" "output s/frame"
for f in $formats; do
  name=${f/:/_}
  vtp=$(stat -c %s "$(ls "$WORK/$name"/fields/particles_*.vtp | tail -1)")
  vti=$(stat -c %s "$(ls "$WORK/$name"/fields/grid_*.vti | tail -1)")
  frames=$(ls "$WORK/$name"/fields/particles_*.vtp | wc -l)
  median=$(sort -g "$WORK/$name.times" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  printf "%-14s %12d %12d %16.3f\n" "$f" "$vtp" "$vti" "$(echo "$median / $frames" | bc -l)"
done
