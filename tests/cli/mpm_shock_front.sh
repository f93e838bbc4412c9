#!/usr/bin/env bash
# The MPM shock-front tool ([shock_front], docs/mpm.md "Shock front and Hugoniot") in a run: a solid
# aluminium strip on a rigid wall at 1000 m/s writes shock_front.csv and hugoniot_al.toml, whose
# Us, up, ρ and −σ_yy meet the linear Rankine–Hugoniot values of [derived] within 2 % (the
# tolerance of the MPM Rankine–Hugoniot tests: the strength's ⅔σ_Y is 0.5 % of σ_yy, the shock is
# smeared); stopped and resumed it writes the same files; the tool off leaves every other output
# byte-identical; bad keys exit 2.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
case="$ROOT/tests/cli/cases/mpm_shock_front.toml"
"$SF" run "$case" --output "$WORK/on" -q > /dev/null
toml="$WORK/on/hugoniot_al.toml"
[ -s "$toml" ] && [ -s "$WORK/on/shock_front.csv" ] || fail "no hugoniot_al.toml or shock_front.csv"
grep -q "^complete = true" "$toml" || fail "incomplete Hugoniot state: $(grep note "$toml")"
grep -q "^two_wave = false" "$toml" || fail "an overdriven shock read as two waves"
grep -q "shock front: Us = " "$WORK/on/log.txt" || fail "the log lacks the shock front"
grep -q '"hugoniot_al.toml"' "$WORK/on/summary.json" || fail "summary.json lacks the Hugoniot state"
value() { awk -F' = ' -v k="$1" '$1 == k { print $2; exit }' "$2"; }
derived="$WORK/on/config.resolved.toml"
within() {  # within NAME MEASURED REFERENCE TOLERANCE
  awk -v m="$2" -v r="$3" -v t="$4" 'BEGIN { d = (m - r) / r; exit !(d < t && -d < t) }' \
    || fail "$1 = $2, expected $3 within $4"
}
within us "$(value us_m_s "$toml")" "$(value hugoniot_shock_speed_m_s "$derived")" 0.02
within up "$(value up_m_s "$toml")" 1000 0.02
within density "$(value density_kg_m3 "$toml")" "$(value hugoniot_density_kg_m3 "$derived")" 0.02
within stress "$(value longitudinal_stress_Pa "$toml")" "-$(value hugoniot_pressure_Pa "$derived")" 0.02
/usr/bin/python3 "$ROOT/tests/cli/conventions.py" "$WORK/on" > /dev/null || fail "shock_front.csv breaks the unit rule"

# Stopped and resumed: the same rows and the same state.
stop_then_resume "$case" "$WORK/split" 150
same_files "$WORK/on" "$WORK/split" shock_front.csv hugoniot_al.toml series.csv

# Off (no table, or enabled = false): every other file as with it on.
grep -v -e '^\[shock_front\]' -e '^enabled = true' "$case" > "$WORK/off.toml"
"$SF" run "$WORK/off.toml" --output "$WORK/off" -q > /dev/null
[ ! -e "$WORK/off/shock_front.csv" ] && ! ls "$WORK/off"/hugoniot_*.toml 2> /dev/null || fail "the tool wrote without [shock_front]"
same_files "$WORK/on" "$WORK/off" series.csv thermo.csv
grep -q '"hugoniot"' "$WORK/off/summary.json" && fail "summary.json has a Hugoniot state without [shock_front]"
sed 's/^enabled = true/enabled = false\nmargin_bins = 4/' "$case" > "$WORK/disabled.toml"
"$SF" run "$WORK/disabled.toml" --output "$WORK/disabled" -q > /dev/null || fail "enabled = false with other keys refused"
[ ! -e "$WORK/disabled/shock_front.csv" ] || fail "the tool wrote with enabled = false"
same_files "$WORK/on" "$WORK/disabled" series.csv

# Bad keys: exit 2 naming the key, no run folder.
tiny=$(sed '/^\[loading\]/,$d' "$ROOT/tests/cli/cases/mpm_tiny.toml")
expect_error "$tiny
[shock_front]
enabled = true" "direction" "\"up\" or \"down\""
expect_error "$(cat "$case")
body = 3" "body"
expect_error "$(cat "$case")
window_fraction = 0.0" "window_fraction"
expect_error "$(cat "$case")
direction = \"sideways\"" "direction"
# The sweep (`shockfield hugoniot --method mpm`): three loading speeds on the same strip give back
# the material's linear Hugoniot, c0 = 5350 m/s and s = 1.34 (measured 5368 and 1.3415): bounds
# 1 % on c0 and 2 % on s (the strength adds ⅔σ_Y to the stress and a little to U_s).
"$SF" hugoniot "$case" --method mpm --speeds 0.5,1.0,1.5 -o "$WORK/sweep" -q > "$WORK/sweep.txt"
fit="$WORK/sweep/hugoniot_fit.toml"
[ "$(wc -l < "$WORK/sweep/hugoniot_sweep.csv")" -eq 4 ] || fail "hugoniot_sweep.csv should have 3 rows"
within c0 "$(value c0_m_s "$fit")" 5350 0.01
within s "$(value s "$fit")" 1.34 0.02
grep -q "c0 (km/s)" "$WORK/sweep.txt" || fail "the sweep printed no fit"
# Refused with exit 2: an MPM case without [shock_front], an MD case.
grep -v -e '^\[shock_front\]' -e '^enabled = true' "$case" > "$WORK/no_front.toml"
set +e
"$SF" hugoniot "$WORK/no_front.toml" --method mpm --speeds 1 -o "$WORK/bad1" -q > /dev/null 2> "$WORK/err1"
code1=$?
"$SF" hugoniot "$ROOT/examples/md_shock_piston/case.toml" --method mpm --speeds 1 -o "$WORK/bad2" -q > /dev/null 2> "$WORK/err2"
code2=$?
set -e
[ $code1 -eq 2 ] && grep -q "shock_front" "$WORK/err1" || fail "no [shock_front]: exit $code1, $(cat "$WORK/err1")"
[ $code2 -eq 2 ] && grep -q "MPM case" "$WORK/err2" || fail "an MD case: exit $code2, $(cat "$WORK/err2")"
echo "mpm_shock_front: ok"
