#!/usr/bin/env bash
# Runs that go wrong stop with a diagnosis (exit code 3) and keep the output written so far:
# a time step far too large for the velocities, and atoms leaving a fixed boundary.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")
# The run stops with exit code 3, the log has the diagnosis, thermo.csv keeps its rows.
expect_run_error() {
  run_expecting 3 "$@"
  grep -qF "run stopped" "$WORK/out/log.txt" || fail "log.txt lacks the diagnosis"
  [ "$(wc -l < "$WORK/out/thermo.csv")" -ge 2 ] || fail "thermo.csv lost its rows"
}
# 0.05 ps steps at 20000 K: atoms jump further than half the skin per step.
hot=${base/temperature = 600.0/temperature = 20000.0}
expect_run_error "${hot/timestep = 0.002/timestep = 0.05}" "time step" "too large"
# A crystal in a fixed box, thrown at +x at 50 Å/ps: atoms cross the fixed face.
lost=${base/boundary = \"ppp\"/boundary = \"fpp\"}
lost=${lost/\[output\]/[[velocity.add]]
group = \"all\"
velocity = [50.0, 0.0, 0.0]

[output]}
expect_run_error "$lost" "lost atom" "fixed x boundary"
echo "run_errors: ok"
