#!/usr/bin/env bash
# Two pd_bench binaries (a baseline and a candidate) and LAMMPS peri/<style> on the same work,
# alternated round by round so that all three see the same machine load:
#   bench/pd_alternate.sh BASE_PD_BENCH NEW_PD_BENCH [style (pmb)] [rounds (5)] [n (30)] [steps (30)]
# Per round: the one-thread CPU seconds of the loop for both binaries (pd_bench's "cpu s" column,
# contact on) and LAMMPS's (loop time × "% CPU use", contact always on), then the medians and the
# ratios LAMMPS/candidate and baseline/candidate, with the load average before and after.
set -eu
base="$1"; new="$2"; style="${3:-pmb}"; rounds="${4:-5}"; n="${5:-30}"; steps="${6:-30}"
root="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cpu_of() { "$1" "$n" "$steps" "$style" | awk -F'|' -v s="$style" '$2 ~ " "s" " && $3+0 == 1 {print $7+0}'; }
uptime
for r in $(seq "$rounds"); do
  b=$(cpu_of "$base"); c=$(cpu_of "$new")
  (cd "$work" && lmp -in "$root/bench/lammps/in.peri_bench" -var n "$n" -var style "$style" -var steps "$steps" \
    -log "$work/log" -screen none)
  loop=$(sed -n 's/^Loop time of \([0-9.e+-]*\) on 1 procs for '"$steps"' steps.*/\1/p' "$work/log")
  use=$(sed -n 's/^\([0-9.]*\)% CPU use with 1 MPI tasks.*/\1/p' "$work/log" | tail -1)
  l=$(awk -v l="$loop" -v u="$use" 'BEGIN {printf "%.3f", l * u / 100}')
  echo "round $r: base $b s, new $c s, LAMMPS $l s: LAMMPS/new $(awk -v l="$l" -v c="$c" 'BEGIN {printf "%.2f", l / c}')x" | tee -a "$work/rounds"
done
median() { awk -v f="$1" '{print $f}' "$work/rounds" | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
mb=$(median 4); mc=$(median 7); ml=$(median 10)
awk -v b="$mb" -v c="$mc" -v l="$ml" 'BEGIN {
  printf "medians: base %.3f s, new %.3f s, LAMMPS %.3f s; LAMMPS/new %.2fx, base/new %.2fx\n", b, c, l, l / c, b / c }'
uptime
