#!/usr/bin/env bash
# The npt ensemble in a case file: a barostatted dimension that is not periodic is rejected
# before the run naming the key; by default only the periodic dimensions are barostatted; a short
# npt run (iso, then z only) completes.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")
npt=${base/ensemble = \"nvt\"/ensemble = \"npt\"
pressure = 1000.0
pressure_damping = 0.5}
surface=${npt/boundary = \"ppp\"/boundary = \"pps\"}

expect_error "${surface/pressure = 1000.0/pressure = 1000.0
pressure_dims = [\"x\", \"z\"]}" "stage[0].pressure_dims" "z is not periodic"
expect_error "${npt/pressure = 1000.0/pressure = 1000.0
pressure_dims = [\"w\"]}" "stage[0].pressure_dims" "\"x\", \"y\", \"z\""
expect_error "${npt/pressure = 1000.0/pressure = 1000.0
couple = \"xy\"}" "stage[0].couple" "expected one of"
expect_error "${npt/pressure = 1000.0/pressure = \"high\"}" "stage[0].pressure" "expected a number"
expect_error "${npt/pressure_damping = 0.5/pressure_damping = 0.0}" "stage[0].pressure_damping"

run_expecting 0 "${npt/pressure = 1000.0/pressure = 1000.0
couple = \"iso\"}"
grep -q "ensemble npt" "$WORK/out/log.txt" || fail "no npt stage in the log"
# Free (shrink-wrapped) z surface: x and y are barostatted by default and the run completes.
run_expecting 0 "$surface"
run_expecting 0 "${npt/pressure = 1000.0/pressure = 1000.0
pressure_dims = [\"z\"]}"
