#!/usr/bin/env bash
# PD benchmark beside LAMMPS (serial Debian lmp, no OPENMP package) on the same work:
#   bench/run_pd_bench.sh BUILD_DIR [n (30)] [steps (50)]
# prints LAMMPS's loop time and bond-updates/s for peri/pmb and peri/lps (bonds counted by
# pd_bench: the same lattice and horizon), then pd_bench's table, with the machine load.
set -eu
build="$1"; n="${2:-30}"; steps="${3:-50}"
root="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
uptime
"$build/bench/pd_bench" "$n" "$steps" | tee "$work/pd.txt"
bonds=$(sed -n 's/.* points, \([0-9]*\) bonds.*/\1/p' "$work/pd.txt")
for style in pmb lps; do
  (cd "$work" && lmp -in "$root/bench/lammps/in.peri_bench" -var n "$n" -var style "$style" -var steps "$steps" \
    -log "$work/log.$style" -screen none)
  loop=$(sed -n 's/^Loop time of \([0-9.e+-]*\) on 1 procs for '"$steps"' steps.*/\1/p' "$work/log.$style")
  ours=$(awk -F'|' -v s="$style" '$2 ~ " "s" " && $3+0 == 1 {print $4+0}' "$work/pd.txt")
  ours2=$(awk -F'|' -v s="$style" '$2 ~ " "s" " && $3+0 == 2 {print $4+0}' "$work/pd.txt")
  awk -v s="$style" -v l="$loop" -v b="$bonds" -v st="$steps" -v o="$ours" -v o2="$ours2" 'BEGIN {
    printf "LAMMPS peri/%s: loop %.3f s, %.3g bond-updates/s; shockfield/LAMMPS: %.2fx (1 thread), %.2fx (2 threads)\n",
      s, l, b * st / l, l / o, l / o2 }'
done
uptime
