#!/usr/bin/env bash
# An MD run writes its folder; one stopped by SIGTERM writes a checkpoint and, resumed, the same
# trajectory as an uninterrupted run, bitwise (same thread count): the final full-precision dumps
# are identical files. (Stopped with --stop-after and resumed: stop_resume.sh, as for every method.)
source "$(dirname "$0")/lib.bash"
set -e
case="$ROOT/tests/cli/cases/tiny_cu.toml"
export OMP_NUM_THREADS=2
"$SF" run "$case" --output "$WORK/straight" -q > /dev/null
for f in log.txt config.resolved.toml thermo.csv final.data; do
  [ -s "$WORK/straight/$f" ] || fail "run folder lacks $f"
done
# SIGTERM writes a checkpoint too.
"$SF" run "$case" --output "$WORK/term" -q > /dev/null 2>&1 &
pid=$!
sleep 1.5
kill -TERM $pid 2>/dev/null || true
set +e
wait $pid
code=$?
set -e
if [ $code -eq 130 ]; then
  [ -f "$WORK/term/checkpoint.h5" ] || fail "SIGTERM left no checkpoint"
  "$SF" run "$case" --output "$WORK/term" -q --resume > /dev/null
  cmp "$WORK/straight/dumps/dump.300.lammpstrj" "$WORK/term/dumps/dump.300.lammpstrj" || fail "SIGTERM-resumed trajectory differs"
  echo "ok: SIGTERM checkpoint and resume"
else
  echo "note: the run finished before SIGTERM arrived (exit $code)"
fi
echo "run_restart: run folder, SIGTERM-resumed run bitwise identical"
