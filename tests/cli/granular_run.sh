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
for f in log.txt config.resolved.toml thermo.csv series.csv energy_above.csv probes.csv spacetime_force.csv spacetime_velocity.csv \
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

# summary.json: valid, with granular's results. The energy error without damping is Verlet's at
# 0.05 of the stable step (measured 4.2e-6; < 1e-5); damping (1e-3 N·s/m) removes more (2.5e-4).
CHECK="/usr/bin/python3 $ROOT/tests/cli/check_summary.py"
$CHECK "$WORK/run/summary.json" --method granular --status finished > /dev/null ||
  fail "summary.json: $($CHECK "$WORK/run/summary.json")"
"$SF" run "$case" --output "$WORK/undamped" -q --set chain.damping=0.0 > /dev/null
/usr/bin/python3 - "$WORK/run/summary.json" "$WORK/undamped/summary.json" <<'PY' || fail "summary.json results"
import json, sys
damped, undamped = (json.load(open(f))["results"] for f in sys.argv[1:])
keys = ["time_s", "steps", "kinetic_J", "potential_J", "total_J", "energy_error", "signal_depth_m",
        "max_speed_m_s", "max_contact_force_N"]
assert list(damped) == keys, list(damped)
assert damped["steps"] == 617 and abs(damped["time_s"] - 617 * 1.622912869456014e-07) < 1e-15, damped
assert undamped["energy_error"] < 1e-5, undamped["energy_error"]
assert damped["energy_error"] > 10 * undamped["energy_error"], (damped["energy_error"], undamped["energy_error"])
assert 0 < damped["signal_depth_m"] < 200 * 4e-3 and damped["max_speed_m_s"] > 0
PY

# --resume: a stopped run's summary says so; a changed chain is refused with the key listed, a
# later end time continues the run.
set +e
"$SF" run "$case" --output "$WORK/split" -q --stop-after 100 > /dev/null 2>&1
set -e
$CHECK "$WORK/split/summary.json" --method granular --status stopped > /dev/null || fail "no valid stopped summary"
run_resume() { "$SF" run "$case" --output "$WORK/split" -q --resume "$@" > /dev/null 2> "$WORK/resume.txt"; }
set +e
run_resume --set chain.grains=201
code=$?
set -e
[ $code -eq 2 ] && grep -q "chain.grains: 200 -> 201" "$WORK/resume.txt" || fail "unsafe resume edit: $(cat "$WORK/resume.txt")"
run_resume --set run.end_time=1.2e-4 || fail "a later end time refused: $(cat "$WORK/resume.txt")"
grep -q "finished: t = .* after 740 steps" "$WORK/split/log.txt" || fail "the extended run did not reach 740 steps"

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
