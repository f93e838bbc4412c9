#!/usr/bin/env bash
# `shockfield run` of a granular case through the run driver: --check of the examples (with the
# --set variants examples/granular_chain/run.sh uses), the run folder with the thermo table in the
# log and thermo.csv, --set equal to editing the file (bitwise), bad input refused before a run
# (exit 2, key named, no folder), and `run --help` naming the docs page. Stop and resume of
# this case: stop_resume.sh (cli.stop_resume.granular).
source "$(dirname "$0")/lib.bash"
set -e
case="$ROOT/tests/cli/cases/granular_tiny.toml"
examples="$ROOT/examples/granular_chain"
export OMP_NUM_THREADS=2
for f in "$examples"/*.toml; do
  "$SF" run "$f" --check | grep -q "valid granular case" || fail "--check does not accept $f"
done
"$SF" run "$examples/column_weak.toml" --check --set impulse.velocity=1.0 --set run.end_time=0.012 \
  --set output.signal_interval=6e-5 --set output.field_interval=6e-5 > /dev/null || fail "strong column refused"
for ratio in 10.0 1.0; do
  "$SF" run "$examples/column_light_impurity.toml" --check --set "impurity[0].mass_ratio=$ratio" > /dev/null ||
    fail "impurity mass_ratio $ratio refused"
done
"$SF" run "$case" --check | grep -q "valid granular case (200 grains, 617 steps" || fail "--check does not report the case"

"$SF" run "$case" --output "$WORK/run" -q > /dev/null
for f in log.txt config.resolved.toml thermo.csv series.csv probes.csv spacetime_force.csv spacetime_velocity.csv \
         signal.csv checkpoint.h5; do
  [ -s "$WORK/run/$f" ] || fail "run folder lacks $f"
done
columns="Step,Time,KinEng,PotEng,TotEng,ExtWork,SigDepth,SigSpeed"
[ "$(head -1 "$WORK/run/thermo.csv")" = "$columns" ] || fail "thermo.csv header: $(head -1 "$WORK/run/thermo.csv")"
# thermo_every = 50 over 617 steps: rows 0, 50, ..., 600 and the last step.
[ "$(tail -n +2 "$WORK/run/thermo.csv" | cut -d, -f1 | tr '\n' ' ')" = "0 50 100 150 200 250 300 350 400 450 500 550 600 617 " ] ||
  fail "thermo.csv steps: $(cut -d, -f1 "$WORK/run/thermo.csv" | tr '\n' ' ')"
grep -Eq "^ +Step +Time +KinEng +PotEng +TotEng +ExtWork +SigDepth +SigSpeed$" "$WORK/run/log.txt" ||
  fail "log.txt has no thermo table header"
grep -q "^time_step = " "$WORK/run/config.resolved.toml" || fail "derived time step missing"
grep -q "finished: t = .* after 617 steps" "$WORK/run/log.txt" || fail "log.txt has no closing line"

# --set is the same as editing the file: bitwise identical outputs.
sed 's/^velocity = 0.05$/velocity = 0.06/' "$case" > "$WORK/edited.toml"
grep -q "velocity = 0.06" "$WORK/edited.toml" || fail "the edit did not apply"
"$SF" run "$WORK/edited.toml" --output "$WORK/edited" -q > /dev/null
"$SF" run "$case" --output "$WORK/set" -q --set impulse.velocity=0.06 > /dev/null
same_files "$WORK/edited" "$WORK/set" series.csv probes.csv signal.csv thermo.csv

# Bad input: refused before a run with the key named.
base=$(cat "$case")
expect_error "${base/radius = 2e-3/radius = 0.0}" "radius" "expected a radius > 0"
expect_error "$(printf '%s\n' "${base/gravity = 9.81/gravity = 0.0}" | sed '/^\[wall\]/,/^poisson_ratio = 0.33/d;s/^damping = 1e-3/gap = -1e-6/')" \
  "gap" "overlapping beyond the static"
expect_error "${base/end_time = 1e-4/end_time = 1e-4
time_step = 1e-3}" "time_step" "above the stable step"
expect_error "${base/grains = 200/grains = 200
grain_count = 3}" "grain_count"
"$SF" run --help | grep -q "docs/granular.md" || fail "run --help does not name docs/granular.md"
echo "granular_run: ok"
