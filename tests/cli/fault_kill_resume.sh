#!/usr/bin/env bash
# Fault: SIGKILL at random steps (bash RANDOM with a fixed seed picks the row of the time series
# at which the run is killed), then --resume from the last periodic checkpoint: the outputs are
# byte for byte those of an uninterrupted run (same thread count), for MD and MPM. A kill can
# land in the middle of a checkpoint write: the previous checkpoint is then still whole (the new
# one is written to checkpoint.h5.tmp, verified and only then renamed).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
RANDOM=2026

# kill_then_resume CASE OUT SERIES ROWS: runs CASE into OUT, sends SIGKILL once SERIES has ROWS
# lines and a checkpoint exists, then resumes to the end.
kill_then_resume() {
  local case_file="$1" out="$2" series="$3" rows="$4"
  "$SF" run "$case_file" --output "$out" -q > /dev/null 2>&1 &
  local pid=$!
  while kill -0 $pid 2>/dev/null; do
    if [ -f "$out/checkpoint.h5" ] && [ "$(wc -l < "$out/$series" 2>/dev/null || echo 0)" -ge "$rows" ]; then
      kill -KILL $pid 2>/dev/null || true  # the run may end between the test and the kill
      break
    fi
    sleep 0.01
  done
  set +e
  wait $pid
  local code=$?
  set -e
  [ $code -eq 137 ] || fail "$case_file: the run ended (exit $code) before the kill at row $rows; lengthen the case"
  "$SF" run "$case_file" --output "$out" -q --resume > /dev/null 2> "$WORK/resume.txt" ||
    fail "resume after SIGKILL at row $rows failed: $(cat "$WORK/resume.txt")"
}

# MD: tiny_cu with a checkpoint every 20 steps and a thermo row every 10, run to step 2,100 so
# that the kill (rows 5 to 64, step 640 at most) lands well before the end on a fast host.
sed -e 's/^checkpoint_every = 50/checkpoint_every = 20/' -e 's/^steps = 200/steps = 2000/' \
  "$ROOT/tests/cli/cases/tiny_cu.toml" > "$WORK/md.toml"
"$SF" run "$WORK/md.toml" --output "$WORK/md_straight" -q > /dev/null
for trial in 1 2 3; do
  rows=$((RANDOM % 60 + 5))
  rm -rf "$WORK/md_killed"
  kill_then_resume "$WORK/md.toml" "$WORK/md_killed" thermo.csv $rows
  same_files "$WORK/md_straight" "$WORK/md_killed" thermo.csv final.data dumps/dump.1000.lammpstrj dumps/dump.2100.lammpstrj
  echo "ok: md killed at thermo row $rows, resumed bitwise"
done

# MPM: mpm_tiny run 4x longer, a checkpoint every 5 steps, a series row every ns (161 rows; the
# kill lands at rows 10 to 69).
sed -e 's/^end_time = 40e-9/end_time = 160e-9/' -e 's/^checkpoint_every = 20/checkpoint_every = 5/' \
  -e 's/^series_interval = 2e-9/series_interval = 1e-9/' "$ROOT/tests/cli/cases/mpm_tiny.toml" > "$WORK/mpm.toml"
"$SF" run "$WORK/mpm.toml" --output "$WORK/mpm_straight" -q > /dev/null
for trial in 1 2 3; do
  rows=$((RANDOM % 60 + 10))
  rm -rf "$WORK/mpm_killed"
  kill_then_resume "$WORK/mpm.toml" "$WORK/mpm_killed" series.csv $rows
  same_files "$WORK/mpm_straight" "$WORK/mpm_killed" series.csv grid.pvd particles.pvd histograms/hist_0.csv
  echo "ok: mpm killed at series row $rows, resumed bitwise"
done
echo "fault_kill_resume: SIGKILL then --resume is bitwise the uninterrupted run (md, mpm)"
