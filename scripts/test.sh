#!/usr/bin/env bash
# Builds shockfield (release preset) and runs the test suite (unit, cli and validation tests;
# the studies labelled "slow" are left out — run them with: ctest --preset release -L slow).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
# Tests run side by side: idle OpenMP threads must sleep, not spin, or they starve each other.
export OMP_WAIT_POLICY=passive
ctest --preset release -j "$(nproc)"
