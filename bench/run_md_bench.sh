#!/usr/bin/env bash
# shockfield MD against LAMMPS on LAMMPS's own benchmark work, in one run (issue 2):
#   bench/lammps/in.eam  vs  bench/cases/eam.toml   (32,000 Cu atoms, EAM, 100 steps)
#   bench/lammps/in.lj   vs  bench/cases/lj.toml    (32,000 LJ atoms, 100 steps)
# For each case the programs run alternately, RUNS times each (LAMMPS serial, shockfield on 1 and
# 2 threads), and the medians of the loop times are compared: LAMMPS's "Loop time", shockfield's
# run-stage rate ("N steps/s" in log.txt; both exclude setup). Peak RSS comes from
# /usr/bin/time -v. Because the machine is shared, the instructions the loop executes are
# counted too (perf stat, user space), as I(100 steps) - I(0 steps) so setup cancels: a
# load-independent ratio.
# Usage: bench/run_md_bench.sh [RUNS=5]    (repository root; Release build in build/release)
# Prints a Markdown section for bench/RESULTS.md.
bench_name=md_bench
source "$(dirname "$0")/md_bench_lib.bash" "$@"
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-/usr/share/lammps/potentials}
# Peak RSS (kB) of the command in "$work/time.txt" (written by /usr/bin/time -v).
peak_kb() { awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt"; }

# run_lmp CASE -> loop seconds; appends peak RSS to $work/CASE.lmp.rss
run_lmp() {
  (cd "$work" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt \
     lmp -nocite -screen none -log "log.$1" -in "$root/bench/lammps/in.$1" > /dev/null)
  peak_kb >> "$work/$1.lmp.rss"
  grep -h "Neighbor list builds" "$work/log.$1" | awk '{print $NF}' > "$work/$1.lmp.builds"
  awk '/^Loop time of/ {print $4}' "$work/log.$1"
}
# run_sf CASE THREADS -> loop seconds; appends peak RSS to $work/CASE.sfTHREADS.rss
run_sf() {
  local out="$work/sf_$1_$2"
  rm -rf "$out"
  OMP_NUM_THREADS=$2 /usr/bin/time -v -o "$work/time.txt" \
    "$sf" run "$root/bench/cases/$1.toml" --output "$out" -q -j "$2" > /dev/null
  peak_kb >> "$work/$1.sf$2.rss"
  # "[run] done at step 100 (34.1 steps/s, 15 neighbour rebuilds)"; the count includes setup's.
  sed -n 's/.*done at step .* (\([0-9.]*\) steps\/s, \([0-9]*\) neighbour rebuilds).*/\2/p' "$out/log.txt" \
    | awk '{print $1 - 1}' > "$work/$1.sf.builds"
  sed -n 's/.*done at step .* (\([0-9.]*\) steps\/s.*/\1/p' "$out/log.txt" | awk -v s=$steps '{print s / $1}'
}

# Loop counts: perf stat of the full run minus that of a 0-step run. On a machine without
# hardware counters (perf missing, or its events "<not supported>", as in most VMs) the columns
# say n/a and a line under the table says why, instead of printing 0 and NaN.
counters_note() {  # -> empty when perf counts user-space instructions and cycles, else the reason
  if ! command -v perf > /dev/null; then echo "perf is not installed (Debian: linux-perf)"; return; fi
  local out
  out=$(perf stat -x, -e instructions:u,cycles:u true 2>&1 || true)
  if ! awk -F, '/instructions/ && $1 ~ /^[0-9]+$/ {i = 1} /cycles/ && $1 ~ /^[0-9]+$/ {c = 1} END {exit !(i && c)}' <<< "$out"; then
    echo "perf cannot count instructions:u and cycles:u here ($(grep -m1 -o '<not [a-z ]*>' <<< "$out" || echo 'no count'): no hardware counters, e.g. a VM)"
  fi
}
no_counters=$(counters_note)
counts() {  # CMD... -> "instructions cycles" (user space)
  perf stat -x, -e instructions:u,cycles:u -o "$work/perf.txt" "$@" > /dev/null 2>&1
  awk -F, '/instructions/ {i = $1} /cycles/ {c = $1} END {print i, c}' "$work/perf.txt"
}
difference() { awk -v a="$1" -v b="$2" 'BEGIN {split(a, x, " "); split(b, y, " "); printf "%.0f %.0f\n", x[1] - y[1], x[2] - y[2]}'; }
loop_instructions_lmp() {
  sed "s/^run[[:space:]].*/run 0/" "$root/bench/lammps/in.$1" > "$work/in0.$1"
  local full zero
  full=$(cd "$work" && counts lmp -nocite -screen none -log none -in "$root/bench/lammps/in.$1")
  zero=$(cd "$work" && counts lmp -nocite -screen none -log none -in "in0.$1")
  difference "$full" "$zero"
}
loop_instructions_sf() {
  sed "s/^steps = .*/steps = 0/" "$root/bench/cases/$1.toml" > "$work/zero_$1.toml"
  local full zero
  rm -rf "$work/i_full" "$work/i_zero"
  full=$(OMP_NUM_THREADS=1 counts "$sf" run "$root/bench/cases/$1.toml" --output "$work/i_full" -q -j 1)
  zero=$(OMP_NUM_THREADS=1 counts "$sf" run "$work/zero_$1.toml" --output "$work/i_zero" -q -j 1)
  difference "$full" "$zero"
}

per_atom_step() { awk -v t="$1" -v n=$atoms -v s=$steps 'BEGIN {printf "%.3g", t / (n * s)}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }

echo "## MD vs LAMMPS"
echo
echo "Command: \`bench/run_md_bench.sh $runs\` ($(date -u +%Y-%m-%d), $(nproc) cores, $(lmp -h | sed -n 's/^Large-scale.*Simulator - \(.*\)$/LAMMPS \1/p' | head -1);"
echo "OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-unset}; load average before: $(cut -d' ' -f1-3 /proc/loadavg))."
echo
echo "| case | LAMMPS 1 proc | shockfield 1 thread | ratio sf/LAMMPS | shockfield 2 threads | 2-thread speed-up | neighbour builds LAMMPS / sf | loop instructions LAMMPS / sf (ratio) | loop cycles LAMMPS / sf 1 t (ratio) | peak RSS per atom LAMMPS / sf 1 t / sf 2 t |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for case in eam lj; do
  : > "$work/$case.lmp"; : > "$work/$case.sf1"; : > "$work/$case.sf2"
  for ((r = 0; r < runs; ++r)); do
    run_lmp $case >> "$work/$case.lmp"
    run_sf $case 1 >> "$work/$case.sf1"
    run_sf $case 2 >> "$work/$case.sf2"
  done
  lmp_t=$(median < "$work/$case.lmp"); sf1=$(median < "$work/$case.sf1"); sf2=$(median < "$work/$case.sf2")
  if [ -z "$no_counters" ]; then
    read -r il cl < <(loop_instructions_lmp $case)
    read -r is cs < <(loop_instructions_sf $case)
    loop_columns="$(awk -v a="$il" -v b="$is" 'BEGIN {printf "%.3g / %.3g (%.2f)", a, b, b / a}') | $(awk -v a="$cl" -v b="$cs" 'BEGIN {printf "%.3g / %.3g (%.2f)", a, b, b / a}')"
  else
    loop_columns="n/a | n/a"
  fi
  rss() { median < "$work/$case.$1.rss" | awk -v n=$atoms '{printf "%.0f", $1 * 1024 / n}'; }
  echo "| $case | $(per_atom_step "$lmp_t") s/atom-step ($lmp_t s) | $(per_atom_step "$sf1") s/atom-step ($sf1 s) |" \
       "$(ratio "$sf1" "$lmp_t") | $(per_atom_step "$sf2") s/atom-step ($sf2 s) | $(ratio "$sf1" "$sf2")× |" \
       "$(cat "$work/$case.lmp.builds") / $(cat "$work/$case.sf.builds") |" \
       "$loop_columns |" \
       "$(rss lmp) B / $(rss sf1) B / $(rss sf2) B |"
  echo "$case raw loop seconds: LAMMPS $(tr '\n' ' ' < "$work/$case.lmp")| sf 1t $(tr '\n' ' ' < "$work/$case.sf1")| sf 2t $(tr '\n' ' ' < "$work/$case.sf2")" >&2
done
echo
[ -z "$no_counters" ] || echo "Loop instructions and cycles: n/a — $no_counters."
echo "Load average after: $(cut -d' ' -f1-3 /proc/loadavg)."
