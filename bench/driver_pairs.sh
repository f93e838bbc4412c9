#!/usr/bin/env bash
# Paired runs of the previous binary (OLD) and this one (NEW) on one short run per method,
# alternated, three pairs each; prints the medians of the CPU time (user + system, both threads:
# less sensitive than wall time to other jobs on a shared machine) and the ratio NEW/OLD.
# Usage: bench/driver_pairs.sh OLD NEW   (from the source tree; OMP_NUM_THREADS=2)
set -eu
old="$1" new="$2"
export OMP_NUM_THREADS=2 OMP_WAIT_POLICY=passive
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# name | case | extra arguments (a step limit keeps each run to seconds)
runs=("md|bench/cases/eam.toml|"
      "mpm|examples/mpm_spall/case.toml|--stop-after 1200"
      "pd|examples/pd_bar_elastic_plastic/bar_300.toml|--stop-after 1200"
      "dbm|examples/dbm_sod/case.toml|--stop-after 3000")
seconds() {  # seconds BINARY CASE ARGS...: CPU seconds (user + system) of one run
  local bin="$1" case_file="$2"; shift 2
  /usr/bin/time -f "%U %S" -o "$work/time" "$bin" run "$case_file" --output "$work/out" --overwrite -q "$@" \
    > /dev/null 2>&1 || true
  tail -1 "$work/time" | awk '{ print $1 + $2 }'
}
median() { printf '%s\n' "$@" | sort -g | sed -n 2p; }
printf '%-4s %10s %10s %8s\n' method old_cpu_s new_cpu_s new/old
for r in "${runs[@]}"; do
  IFS='|' read -r name case_file extra <<< "$r"
  o=() n=()
  for _ in 1 2 3; do
    o+=("$(seconds "$old" "$case_file" $extra)")
    n+=("$(seconds "$new" "$case_file" $extra)")
  done
  mo=$(median "${o[@]}") mn=$(median "${n[@]}")
  printf '%-4s %10.3f %10.3f %8.3f\n' "$name" "$mo" "$mn" "$(echo "$mn / $mo" | bc -l)"
done
