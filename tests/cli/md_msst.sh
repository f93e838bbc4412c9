#!/usr/bin/env bash
# The msst ensemble in a case file: bad [stage.msst] input is rejected before the run naming the
# key (a non-periodic box, a missing shock speed, tscale = 1, a stray table, a piston with it); a
# short msst run writes the MSST thermo columns and summary results; stopped in the middle of the
# msst stage and resumed, it writes the same thermo.csv and dump, bit for bit.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")
shock=${base/name = \"run\"/name = \"shock\"
ensemble = \"msst\"}
msst=${shock/steps = 200/steps = 200
[stage.msst]
shock_speed = 60.0
q = 500.0
mu = 500.0}
surface=${msst/boundary = \"ppp\"/boundary = \"pps\"}

expect_error "$surface" "stage[1].ensemble" "z is not periodic"
expect_error "${msst/shock_speed = 60.0/speed = 60.0}" "stage[1].msst.shock_speed"
expect_error "${msst/mu = 500.0/mu = 500.0
tscale = 1.0}" "stage[1].msst.tscale"
expect_error "${msst/q = 500.0/q = -1.0}" "stage[1].msst.q"
expect_error "${msst/shock_speed = 60.0/shock_speed = 60.0
direction = \"z\"}" "direction"
expect_error "${base/steps = 200/steps = 200
[stage.msst]
shock_speed = 60.0}" "stage[1].msst" "only with ensemble = \"msst\""
expect_error "${msst/steps = 200/steps = 200
[stage.piston]
speed = 10.0}" "stage[1].ensemble" "cannot have a piston"
expect_error "$shock" "stage[1].msst" "shock_speed"

run_expecting 0 "$msst"
grep -q "ensemble msst" "$WORK/out/log.txt" || fail "no msst stage in the log"
grep -q "MSST at Us = 6 km/s" "$WORK/out/log.txt" || fail "no MSST summary line in the log"
head -1 "$WORK/out/thermo.csv" | grep -q "msst_lagrangian_speed_A_ps" || fail "no MSST columns in thermo.csv"
grep -q '"msst"' "$WORK/out/summary.json" || fail "no msst results in summary.json"
grep -q '"conserved_drift_eV_per_atom"' "$WORK/out/summary.json" || fail "no conserved-quantity drift in summary.json"
# The volume went down along z (a compressive solution at 6 km/s).
awk -F, 'NR == 2 { v0 = $15 } END { if (!($15 < 0.95 * v0)) exit 1 }' "$WORK/out/thermo.csv" ||
  fail "the msst cell did not compress"

# Stopped in the middle of the msst stage (step 230 of 300) and resumed: bitwise the same.
printf '%s\n' "$msst" > "$WORK/msst.toml"
"$SF" run "$WORK/msst.toml" --output "$WORK/straight" -q > /dev/null
stop_then_resume "$WORK/msst.toml" "$WORK/resumed" 230
same_files "$WORK/straight" "$WORK/resumed" thermo.csv dumps/dump.300.lammpstrj final.data
echo "ok: msst stop at 230 and resume is bitwise"
