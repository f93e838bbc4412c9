#!/usr/bin/env bash
# `shockfield hugoniot --method nphug|msst`: a sweep over an nphug stage's pressure and an msst
# stage's shock speed on the tiny Cu case (short stages), each writing hugoniot_<stage>.toml per
# run, hugoniot_sweep.csv with the swept value and the fit, and the nphug sweep folder read by
# `bridge hugoniot-to-eos`; wrong combinations of options and a case without the method's stage
# are refused naming what is missing.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")
hug=${base/name = \"run\"/name = \"hug\"
ensemble = \"nphug\"}
hug=${hug/steps = 200/steps = 100
[stage.nphug]
pressure = 100000.0
pressure_damping = 0.5}
msst=${base/name = \"run\"/name = \"shock\"
ensemble = \"msst\"}
msst=${msst/steps = 200/steps = 100
[stage.msst]
shock_speed = 60.0
q = 500.0
mu = 500.0}
printf '%s\n' "$hug" > "$WORK/hug.toml"
printf '%s\n' "$msst" > "$WORK/msst.toml"

"$SF" hugoniot "$WORK/hug.toml" --method nphug --speeds 1,2 -o "$WORK/bad" > "$WORK/err" 2>&1 && fail "nphug with --speeds accepted"
grep -q "give --pressures" "$WORK/err" || fail "no --pressures hint: $(cat "$WORK/err")"
"$SF" hugoniot "$WORK/msst.toml" --method nphug --pressures 10,20 -o "$WORK/bad" > "$WORK/err" 2>&1 && fail "a case without nphug accepted"
grep -q 'exactly one \[\[stage\]\] with ensemble = "nphug", found 0' "$WORK/err" || fail "no missing-stage error: $(cat "$WORK/err")"

"$SF" hugoniot "$WORK/hug.toml" --method nphug --pressures 10,30,50 -o "$WORK/hug" -j1 -q > "$WORK/hug.out"
for p in 10.00 30.00 50.00; do
  [ -f "$WORK/hug/p_$p/hugoniot_hug.toml" ] || fail "no hugoniot_hug.toml in p_$p"
  grep -q "complete = true" "$WORK/hug/p_$p/hugoniot_hug.toml" || fail "p_$p: incomplete state"
done
head -1 "$WORK/hug/hugoniot_sweep.csv" | grep -q "^target_pressure_GPa,up_km_s,us_km_s" || fail "sweep csv header"
[ -f "$WORK/hug/hugoniot_fit.toml" ] || fail "no fit"
# The higher pressure gives the faster particle.
awk -F, 'NR == 2 { a = $2 } NR == 3 { b = $2 } END { if (!(b > a && a > 0)) exit 1 }' "$WORK/hug/hugoniot_sweep.csv" ||
  fail "Up does not grow with pressure: $(cat "$WORK/hug/hugoniot_sweep.csv")"
"$SF" bridge hugoniot-to-eos "$WORK/hug" -o "$WORK/eos.toml" > "$WORK/bridge.out" 2>&1 ||
  fail "the bridge refused the nphug sweep: $(cat "$WORK/bridge.out")"
grep -q "^c0 = " "$WORK/eos.toml" || fail "no c0 in the bridged EOS"

"$SF" hugoniot "$WORK/msst.toml" --method msst --speeds 5.5,6.0 -o "$WORK/msst" -j1 -q > "$WORK/msst.out"
head -1 "$WORK/msst/hugoniot_sweep.csv" | grep -q "^shock_speed_set_km_s" || fail "msst sweep csv header"
awk -F, 'NR == 2 && ($3 < 5.49 || $3 > 5.51) { exit 1 }' "$WORK/msst/hugoniot_sweep.csv" ||
  fail "msst Us is not the imposed 5.5 km/s: $(cat "$WORK/msst/hugoniot_sweep.csv")"
echo "ok: hugoniot --method nphug and msst sweeps"
