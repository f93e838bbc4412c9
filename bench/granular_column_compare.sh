#!/bin/sh
# The 2D column of spheres on 2 threads beside LAMMPS on the same spheres, alternated run by run:
# bench/granular_column_bench (OMP_NUM_THREADS=2) and LAMMPS gran/hertz/history
# (bench/lammps/in.granular_column, `mpirun -np 2`: Debian's lmp has no OPENMP package), each
# timing STEPS velocity-Verlet steps after one warm-up step on PER_ROW x ROWS spheres, with the
# load average before each run; medians of the loop times at the end.
#   sh bench/granular_column_compare.sh [BUILD_DIR] [ROUNDS (3)] [PER_ROW (1000)] [ROWS (1000)] [STEPS (30)]
# (from the repository root). The machine is shared: read the load averages beside the times.
set -eu
build=${1:-build/release}
rounds=${2:-3}
per_row=${3:-1000}
rows=${4:-1000}
steps=${5:-30}
out=${OUT:-runs/bench_granular_column}
mkdir -p "$out"
log="$out/rounds.txt"
: > "$log"
export OMP_WAIT_POLICY=passive
for r in $(seq 1 "$rounds"); do
  echo "round $r load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$log"
  OMP_NUM_THREADS=2 "$build/bench/granular_column_bench" "$per_row" "$rows" "$steps" | sed "s/^/round $r ours: /" >> "$log"
  echo "round $r load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$log"
  OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np 2 lmp -nocite -var nx "$per_row" -var ny "$rows" \
    -var steps "$steps" -in bench/lammps/in.granular_column -log none -screen "$out/screen.lammps" > /dev/null 2>&1
  grep "Loop time .* for $steps steps" "$out/screen.lammps" | sed "s/^/round $r lammps: /" >> "$log"
done
cat "$log"
awk -v n="$((per_row * rows))" -v steps="$steps" '
  / ours: / { for (i = 1; i <= NF; ++i) if ($i == "loop_s") ours[++no] = $(i + 1) }
  / lammps: / { for (i = 1; i <= NF; ++i) if ($i == "of" && $(i - 1) == "time") lmp[++nl] = $(i + 1) }
  function median(a, k,   i, j, t) {
    for (i = 1; i <= k; ++i) for (j = i + 1; j <= k; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
    return k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2
  }
  END {
    o = median(ours, no); l = median(lmp, nl)
    printf "median loop time over %d rounds: ours %.3f s (%.3g sphere-steps/s), LAMMPS %.3f s (%.3g sphere-steps/s), ratio %.1f\n",
      no, o, n * steps / o, l, n * steps / l, l / o
  }' "$log"
