#!/usr/bin/env bash
# `shockfield sweep`: two MPM impact speeds side by side into one folder, the table of their
# summaries, each run equal to the same `shockfield run --set`; a bad key, a bad value and a
# malformed --set stop the sweep before anything runs (exit 2 naming them). About 3 s.
set -euo pipefail
source "$(dirname "$0")/lib.bash"
CASE="$ROOT/tests/cli/cases/mpm_tiny.toml"
"$SF" sweep "$CASE" --set loading.speed=200,400 -j 2 -o "$WORK/sweep" > "$WORK/out.txt" 2>&1 \
  || fail "sweep failed: $(cat "$WORK/out.txt")"
csv="$WORK/sweep/sweep.csv"
[ "$(wc -l < "$csv")" -eq 3 ] || fail "sweep.csv should have a header and 2 rows: $(cat "$csv")"
head -1 "$csv" | grep -q "^loading.speed,folder,status,steps,wall_seconds,.*bottom_windows.0.means.pressure_Pa" \
  || fail "sweep.csv header: $(head -1 "$csv")"
[ "$(grep -c ",finished," "$csv")" -eq 2 ] || fail "both runs should have finished: $(cat "$csv")"
grep -q "wrote .*sweep.csv (2 runs)" "$WORK/out.txt" || fail "no table/summary line: $(cat "$WORK/out.txt")"
grep -q "^400 " "$WORK/out.txt" || fail "the printed table lacks the 400 m/s row: $(cat "$WORK/out.txt")"
"$SF" run "$CASE" --set loading.speed=400 -o "$WORK/direct" -q -j 1 > /dev/null
cmp "$WORK/direct/series.csv" "$WORK/sweep/loading.speed=400/series.csv" || fail "the swept run differs from run --set"
echo "ok: $(sed -n 3p "$csv" | cut -c1-100)..."

sweep_refused() {  # sweep_refused PATTERN ARGS...: exit 2, stderr names PATTERN, no folder made
  local pattern="$1"; shift
  rm -rf "$WORK/bad"
  set +e
  "$SF" sweep "$CASE" "$@" -o "$WORK/bad" > /dev/null 2> "$WORK/err.txt"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "sweep $*: exit $code, expected 2: $(cat "$WORK/err.txt")"
  grep -qF -- "$pattern" "$WORK/err.txt" || fail "sweep $*: message lacks '$pattern': $(cat "$WORK/err.txt")"
  [ ! -e "$WORK/bad" ] || fail "sweep $*: a folder was made before the check"
  echo "ok: $(head -c 150 "$WORK/err.txt")"
}
sweep_refused "unknown key 'loading.sped'" --set loading.sped=200,400
sweep_refused "loading.speed=-5" --set loading.speed=200,-5
sweep_refused "expected KEY=V1,V2" --set loading.speed
