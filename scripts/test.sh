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
# (-LE replaces the preset's exclusion of the "slow" label, so both are named here.)
ctest --preset release -j "$(nproc)" -LE 'slow|sanitizer|mpi'
# The MPI tests (a build with SHOCKFIELD_MPI; docs/parallel.md), one at a time: each starts up to
# 4 ranks on the 2 cores (mpirun --oversubscribe). Their slow 2D rank grids included.
if grep -q '^SHOCKFIELD_MPI:BOOL=ON' build/release/CMakeCache.txt; then
  ctest --preset release -L mpi -LE sanitizer
fi
# The fuzzers' parsers under AddressSanitizer + UBSan (issue 14; docs/robustness.md, "In CI"):
# shockfield_fuzz_parsers, built above, puts mutants of every parser's inputs and the whole fuzz
# corpus through the parsers in-process; any crash, hang, leak or sanitizer report fails.
echo "sanitizer replay: the parsers under ASan + UBSan (shockfield_fuzz_parsers: mutants of every parser, then the fuzz corpus)"
ctest --preset release -L sanitizer -j "$(nproc)" -V 2>&1 | grep -E "^[0-9]+: (fuzz |FAIL)|tests passed|tests failed"
