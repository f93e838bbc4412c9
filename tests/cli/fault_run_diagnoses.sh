#!/usr/bin/env bash
# Regressions of issue 14 (each failed before its fix): run-time blow-ups the atoms' checks miss,
# output schedules that would write without bound, and documented values that were refused.
#  - MD nvt / npt at dt = 0.1 ps: the thermostat absorbs the blow-up (conserved energy 3e22 /
#    9e26 eV) and the run exited 0; now exit 3 with the diagnosis.
#  - MPM end_time = 1e300 wrote step-0 series rows forever; DBM field_interval = 1e-300 rewrote
#    one frame forever; DBM series_interval below dt wrote identical rows: now refused before the
#    run (exit 2) with the key and the number of rows or frames; PD without a given time step
#    writes at most one row per step.
#  - a shock front that reaches the free end wrote nan into hugoniot_<stage>.toml with no reason
#    and `shockfield hugoniot` then stopped reading its own file (exit 2); now the file has no
#    nan and says why, and the sweep stops with that reason (exit 3).
#  - DBM courant = 1.0 (documented valid) was refused by round-off with no file or key; GLS
#    noise = 0 stopped the run after its folder was created: now refused by key, no folder.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
md=$(sed -n '/^method/,/^\[\[stage\]\]$/p' "$ROOT/tests/cli/cases/tiny_cu.toml" | sed 's/^timestep = 0.002/timestep = 0.1/')
nvt="$md
name = \"warm\"
ensemble = \"nvt\"
temperature = 600.0
steps = 100"
run_expecting 3 "$nvt" "step 1: the nvt thermostat ran away" "time step (0.1 ps)"
run_expecting 3 "${nvt/ensemble = \"nvt\"/ensemble = \"npt\"
pressure = 0.0
pressure_damping = 1.0}" "the npt thermostat ran away"

mpm=$(cat "$ROOT/tests/cli/cases/mpm_tiny.toml")
printf '%s\n' "${mpm/end_time = 40e-9/end_time = 1e300}" > "$WORK/case.toml"
rm -rf "$WORK/out"
set +e
timeout -s KILL 20 "$SF" run "$WORK/case.toml" --output "$WORK/out" -q 2> "$WORK/stderr"
code=$?
set -e
[ $code -eq 2 ] || fail "mpm end_time = 1e300: exit $code, expected 2 (refused): $(head -c 300 "$WORK/stderr")"
grep -q "output.series_interval.*would write over 1e308 series rows" "$WORK/stderr" || fail "no count: $(cat "$WORK/stderr")"
[ ! -e "$WORK/out" ] || fail "mpm end_time = 1e300 left a run folder"
echo "ok: $(head -c 200 "$WORK/stderr")"

sod=$(cat "$ROOT/examples/dbm_sod/case.toml")
expect_error "${sod/profile_interval = 0.05/field_interval = 1e-300}" "output.field_interval" "field frames"
expect_error "${sod/series_interval = 0.01/series_interval = 1e-5}" "output.series_interval" \
  "shorter than the time step dt = 0.00025"
# courant = 1.0 is valid (the stability check, off here, is a separate question).
printf '%s\n' "${sod/courant = 0.4/courant = 1.0}" | sed 's/^eta0 = 2.0/eta0 = 2.0\nstability_check = "off"/' \
  > "$WORK/courant.toml"
"$SF" run "$WORK/courant.toml" --check | grep -q "valid dbm case" || fail "courant = 1.0 is refused"
echo "ok: dbm courant = 1.0 is valid"

gls=$(cat "$ROOT/examples/dbm_phase_separation/case.toml")
expect_error "${gls/noise = 0.05/noise = 0.0}" "initial.noise" "expected"

pd=$(cat "$ROOT/tests/cli/cases/pd_tiny.toml")
fine=${pd/series_interval = 1e-8/series_interval = 1e-10}
expect_error "${fine/end_time = 2e-7/end_time = 2e-7
time_step = 1e-9}" "output.series_interval" "shorter than the time step dt = 1e-09"
# Without a given time step (dt = 1.46e-9 s, 138 steps) an interval of 1e-10 s writes one row per
# step, not 2,000 rows of which 14 in 15 repeat the previous one.
run_expecting 0 "$fine"
rows=$(($(wc -l < "$WORK/out/series.csv") - 1))
[ "$rows" -le 139 ] || fail "pd series_interval below dt wrote $rows rows for 138 steps"
echo "ok: pd series_interval below dt wrote $rows rows for 138 steps"
# A 43 Å sample the 5 km/s front crosses in 0.8 ps, driven for 1.2 ps.
sed -e 's/^repeat = \[8, 8, 50\]/repeat = [3, 3, 12]/' -e 's/^steps = 1000/steps = 100/' -e 's/^steps = 2500/steps = 1200/' \
  -e 's/^profile_every = 100/profile_every = 50/' -e '/^dump_/d' -e 's/^checkpoint_every = 1000/checkpoint_every = 0/' \
  "$ROOT/examples/md_shock_piston/case.toml" > "$WORK/piston.toml"
set +e
"$SF" hugoniot "$WORK/piston.toml" --speeds 1.0 --output "$WORK/sweep" -q > /dev/null 2> "$WORK/stderr"
code=$?
set -e
[ $code -eq 3 ] || fail "hugoniot with the front at the free end: exit $code, expected 3: $(cat "$WORK/stderr")"
grep -q "reached the free end of the sample.*make the sample longer or the stage shorter" "$WORK/stderr" ||
  fail "the sweep does not say why: $(cat "$WORK/stderr")"
toml="$WORK/sweep/up_1.00/hugoniot_shock.toml"
! grep -qi "nan" "$toml" || fail "$toml holds nan: $(cat "$toml")"
grep -q "^complete = false" "$toml" || fail "$toml does not say it is incomplete"
echo "ok: $(head -c 200 "$WORK/stderr")"
# `shockfield hugoniot` reusing a finished run reads its shock_front_<stage>.csv back (found by the
# fuzzer, this session): a front at 1e300 Å gave an inf standard error in hugoniot_sweep.csv and
# exit 0; a file cut after its header gave "shock front fit: 0 times" naming no file.
H="$ROOT/tests/fixtures/fuzz/inputs/hugoniot"
for bad in far truncated; do
  mkdir -p "$WORK/reuse_$bad/up_1.00"
  cp "$H/hugoniot_shock.toml" "$WORK/reuse_$bad/up_1.00/"
  if [ $bad = far ]; then sed '5s/,[^,]*,\([^,]*\)$/,1e300,\1/' "$H/shock_front_shock.csv"; else head -1 "$H/shock_front_shock.csv"; fi \
    > "$WORK/reuse_$bad/up_1.00/shock_front_shock.csv"
  set +e
  "$SF" hugoniot "$ROOT/examples/md_shock_piston/case.toml" --speeds 1.0 --output "$WORK/reuse_$bad" -q > /dev/null 2> "$WORK/stderr"
  code=$?
  set -e
  [ $code -eq 2 ] || fail "hugoniot reusing a $bad shock_front_shock.csv: exit $code, expected 2: $(cat "$WORK/stderr")"
  grep -q "up_1.00/shock_front_shock.csv" "$WORK/stderr" || fail "the message does not name the file: $(cat "$WORK/stderr")"
  [ ! -e "$WORK/reuse_$bad/hugoniot_sweep.csv" ] || fail "hugoniot_sweep.csv written from a $bad front file"
  echo "ok: $(head -c 200 "$WORK/stderr")"
done
echo "fault_run_diagnoses: blow-ups diagnosed, output bounded, documented values valid"
