#!/usr/bin/env bash
# PD benchmark beside LAMMPS (serial Debian lmp, no OPENMP package) on the same work:
#   bench/run_pd_bench.sh BUILD_DIR [n (30)] [steps (50)] [pd_bench models (all)]
# prints LAMMPS's loop time and bond-updates/s for peri/pmb and peri/lps (bonds counted by
# pd_bench: the same lattice and horizon), then pd_bench's table, with the machine load. LAMMPS
# always applies its short-range contact force; pd_bench's "pmb" and "lps" rows do too (the ratio
# printed), "pmb-nocontact" and "lps-nocontact" do not.
set -eu
build="$1"; n="${2:-30}"; steps="${3:-50}"; models="${4:-pmb,pmb-nocontact,lps,lps-nocontact,crystal,crystal8}"
root="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
uptime
"$build/bench/pd_bench" "$n" "$steps" "$models" | tee "$work/pd.txt"
bonds=$(sed -n 's/.* points, \([0-9]*\) bonds.*/\1/p' "$work/pd.txt")
for style in pmb lps; do
  (cd "$work" && lmp -in "$root/bench/lammps/in.peri_bench" -var n "$n" -var style "$style" -var steps "$steps" \
    -log "$work/log.$style" -screen none)
  loop=$(sed -n 's/^Loop time of \([0-9.e+-]*\) on 1 procs for '"$steps"' steps.*/\1/p' "$work/log.$style")
  # LAMMPS's CPU time of the loop: its wall time times its "% CPU use" (the load-independent figure).
  cpu_use=$(sed -n 's/^\([0-9.]*\)% CPU use with 1 MPI tasks.*/\1/p' "$work/log.$style" | tail -1)
  ours_cpu=$(awk -F'|' -v s="$style" '$2 ~ " "s" " && $3+0 == 1 {print $7+0}' "$work/pd.txt")
  ours=$(awk -F'|' -v s="$style" '$2 ~ " "s" " && $3+0 == 1 {print $4+0}' "$work/pd.txt")
  ours2=$(awk -F'|' -v s="$style" '$2 ~ " "s" " && $3+0 == 2 {print $4+0}' "$work/pd.txt")
  awk -v s="$style" -v l="$loop" -v b="$bonds" -v st="$steps" -v o="$ours" -v o2="$ours2" -v u="$cpu_use" -v oc="$ours_cpu" 'BEGIN {
    printf "LAMMPS peri/%s: loop %.3f s, %.3g bond-updates/s; shockfield/LAMMPS: %.2fx (1 thread), %.2fx (2 threads); CPU time %.3f s against shockfield 1 thread %.3f s: %.2fx\n",
      s, l, b * st / l, l / o, l / o2, l * u / 100, oc, l * u / 100 / oc }'
done
uptime
