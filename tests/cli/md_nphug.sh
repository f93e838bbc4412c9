#!/usr/bin/env bash
# The nphug ensemble in a case file: bad [stage.nphug] input is rejected before the run naming the
# key (a missing table or pressure, a wrong style, a non-periodic barostatted dimension, a stray
# table, a piston with it, a stage key it does not read, a group other than all); a short
# Hugoniostat run writes the nphug thermo columns and summary results; stopped in the middle of the
# nphug stage and resumed, it writes the same thermo.csv and dump, bit for bit.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")
hug=${base/name = \"run\"/name = \"hug\"
ensemble = \"nphug\"}
nphug=${hug/steps = 200/steps = 200
[stage.nphug]
pressure = 200000.0
style = \"z\"
pressure_damping = 0.5}
surface=${nphug/boundary = \"ppp\"/boundary = \"pps\"}

expect_error "$hug" "stage[1].nphug" "pressure"
expect_error "${nphug/pressure = 200000.0/press = 200000.0}" "stage[1].nphug.pressure"
expect_error "${nphug/style = \"z\"/style = \"xy\"}" "stage[1].nphug.style"
expect_error "$surface" "stage[1].nphug.style" "z is not periodic"
expect_error "${nphug/pressure_damping = 0.5/pressure_damping = 0.0}" "stage[1].nphug.pressure_damping"
expect_error "${nphug/pressure_damping = 0.5/pressure_chain = -1}" "stage[1].nphug.pressure_chain"
expect_error "${base/steps = 200/steps = 200
[stage.nphug]
pressure = 1.0}" "stage[1].nphug" "only with ensemble = \"nphug\""
expect_error "${nphug/steps = 200/steps = 200
[stage.piston]
speed = 10.0}" "stage[1].ensemble" "cannot have a piston"
expect_error "${nphug/steps = 200/steps = 200
temperature = 300.0}" "temperature"
expect_error "${nphug/steps = 200/steps = 200
group = \"top\"}" "group"

run_expecting 0 "$nphug"
grep -q "ensemble nphug" "$WORK/out/log.txt" || fail "no nphug stage in the log"
grep -q "Hugoniostat (z, P = 20 GPa)" "$WORK/out/log.txt" || fail "no Hugoniostat summary line in the log"
head -1 "$WORK/out/thermo.csv" | grep -q "nphug_us_A_ps" || fail "no nphug columns in thermo.csv"
grep -q '"nphug"' "$WORK/out/summary.json" || fail "no nphug results in summary.json"
grep -q '"hugoniot_energy_eV_per_atom"' "$WORK/out/summary.json" || fail "no Hugoniot energy in summary.json"
# The cell shortened along z under 20 GPa.
awk -F, 'NR == 2 { l0 = $18 } END { if (!($18 < 0.97 * l0)) exit 1 }' "$WORK/out/thermo.csv" ||
  fail "the nphug cell did not compress along z"

# Stopped in the middle of the nphug stage (step 230 of 300) and resumed: bitwise the same.
printf '%s\n' "$nphug" > "$WORK/nphug.toml"
"$SF" run "$WORK/nphug.toml" --output "$WORK/straight" -q > /dev/null
stop_then_resume "$WORK/nphug.toml" "$WORK/resumed" 230
same_files "$WORK/straight" "$WORK/resumed" thermo.csv dumps/dump.300.lammpstrj final.data
echo "ok: nphug stop at 230 and resume is bitwise"
