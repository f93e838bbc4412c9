#!/usr/bin/env bash
# A short reactive DBM run ([reaction], docs/dbm.md) writes the CJ theory under [derived], the
# reactive series and profile columns, conserves E + Q·Σρλ (closed ends); a run stopped and
# resumed (the reactant restored from checkpoint.h5) writes the same output bitwise; bad
# [reaction] input is refused with the key named (exit 2, no run folder).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
det='method = "dbm"
[grid]
nx = 150
dx = 0.01
[model]
tau = 2e-3
[initial]
type = "uniform"
state = { rho = 1.0, p = 0.6 }
[reaction]
kind = "arrhenius"
heat_release = 0.6
rate = 20.0
ignition_temperature = 0.7
ignition_x = 0.3
ignition_width = 0.1
[boundary]
x_low = "reflecting"
x_high = "reflecting"
[run]
end_time = 0.4
courant = 0.4
[output]
series_interval = 0.1
profile_interval = 0.2
checkpoint_every = 50'
printf '%s\n' "$det" > "$WORK/det.toml"
"$SF" run "$WORK/det.toml" --output "$WORK/det" -q > /dev/null
grep -q "cj_speed = 1.59872" "$WORK/det/config.resolved.toml" || fail "derived cj_speed missing or wrong"
grep -q "von_neumann_p = 2.0299" "$WORK/det/config.resolved.toml" || fail "derived von_neumann_p missing or wrong"
head -1 "$WORK/det/series.csv" | grep -q "lambda,chemical_energy_per_length,total_energy_per_length,front_x" || fail "series columns"
head -1 "$WORK/det/profiles/profile_2.csv" | grep -q "D31x,lambda,omega" || fail "profile columns"
# E + Q·Σρλ is conserved while the chemical energy falls and the front advances.
awk -F, 'NR == 2 {e0 = $10; c0 = $9; x0 = $11} END {
  if (($10 - e0)^2 > (1e-9 * e0)^2) { print "E + chemical energy drifts: " e0 " -> " $10; exit 1 }
  if ($9 > 0.9 * c0) { print "chemical energy did not fall: " c0 " -> " $9; exit 1 }
  if ($11 - x0 < 0.5) { print "front did not advance: " x0 " -> " $11; exit 1 } }' "$WORK/det/series.csv" ||
  fail "reactive series"

stop_then_resume "$WORK/det.toml" "$WORK/split" 70
same_files "$WORK/det" "$WORK/split" series.csv profiles/profile_1.csv profiles/profile_2.csv

expect_error "${det/rate = 20.0/rate = 20.0
omega1 = 1.0}" "case.toml" "reaction.omega1"
expect_error "${det/rate = 20.0/}" "reaction.rate"
expect_error "${det/heat_release = 0.6/heat_release = -1}" "reaction.heat_release"
expect_error "${det/kind = \"arrhenius\"/kind = \"cochran\"}" "reaction.omega1" "omega2"
periodic=${det//\"reflecting\"/\"periodic\"}
expect_error "${periodic/tau = 2e-3/tau = 2e-3
convection = \"spectral\"}" "reaction.kind" "nnd"
expect_error "${det/ignition_width = 0.1/ignition_width = 5.0}" "reaction.ignition_width"
echo "dbm_detonation: derived CJ state, reactive columns, E + chemical energy conserved, bitwise resume, refused input"
