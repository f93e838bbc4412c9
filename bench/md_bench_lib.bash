# Shared by the MD bench scripts (run_md_bench.sh, md_table_bench.sh, md_adp_bench.sh), sourced with the script's
# arguments: strict mode; runs = the first argument (default 5); root = the repository; sf = the
# shockfield binary ($SHOCKFIELD, else build/release/shockfield); work = a temporary folder
# /tmp/<bench_name>.XXXXXX removed on exit; the work of LAMMPS's in.lj/in.eam (32,000 atoms,
# 100 steps); median of the numbers on stdin.
set -euo pipefail
runs=${1:-5}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sf=${SHOCKFIELD:-$root/build/release/shockfield}
work=$(mktemp -d "/tmp/${bench_name}.XXXXXX")
trap 'rm -rf "$work"' EXIT
atoms=32000
steps=100
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
# run_sf CASE: runs $work/CASE.toml on one thread; prints seconds per atom-step (run-stage rate).
# (run_md_bench.sh defines its own run_sf and run_lmp: threads and peak memory too.)
run_sf() {
  rm -rf "$work/out"
  OMP_NUM_THREADS=1 "$sf" run "$work/$1.toml" --output "$work/out" -q -j 1 > /dev/null
  sed -n 's/.*done at step .* (\([0-9.]*\) steps\/s.*/\1/p' "$work/out/log.txt" |
    awk -v a=$atoms '{printf "%.4g\n", 1 / ($1 * a)}'
}
# run_lmp INPUT: runs LAMMPS on $work/in.INPUT, serial; prints seconds per atom-step (Loop time).
run_lmp() {
  (cd "$work" && OMP_NUM_THREADS=1 LAMMPS_POTENTIALS=/usr/share/lammps/potentials \
     lmp -nocite -screen none -log log.lmp -in "in.$1" > /dev/null)
  awk -v a=$atoms -v s=$steps '/^Loop time of/ {printf "%.4g\n", $4 / (a * s)}' "$work/log.lmp"
}
# ratio_table BASE CASE...: the medians of $work/sf_CASE and $work/lmp_CASE (one number a line)
# as a markdown table, each relative to BASE's in the same program and to LAMMPS; then the raw rows.
ratio_table() {
  local base="$1" c s l
  shift
  echo "| potential | shockfield s/atom-step (median of $runs) | vs its $base | LAMMPS s/atom-step | vs its $base | shockfield/LAMMPS |"
  echo "|---|---|---|---|---|---|"
  local s0 l0
  s0=$(median < "$work/sf_$base"); l0=$(median < "$work/lmp_$base")
  for c in "$@"; do
    s=$(median < "$work/sf_$c"); l=$(median < "$work/lmp_$c")
    awk -v c="$c" -v s="$s" -v l="$l" -v s0="$s0" -v l0="$l0" \
      'BEGIN {printf "| %s | %.3g | %.2f | %.3g | %.2f | %.2f |\n", c, s, s / s0, l, l / l0, s / l}'
  done
  echo
  for c in "$@"; do
    echo "raw $c: sf $(tr '\n' ' ' < "$work/sf_$c")| lmp $(tr '\n' ' ' < "$work/lmp_$c")"
  done
}
# alternate CASE...: RUNS rounds of run_sf and run_lmp on every CASE in turn, into $work/sf_CASE
# and $work/lmp_CASE; then the load average.
alternate() {
  local r c
  for r in $(seq "$runs"); do
    for c in "$@"; do
      run_sf "$c" >> "$work/sf_$c"
      run_lmp "$c" >> "$work/lmp_$c"
    done
  done
  echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
}
