#!/usr/bin/env bash
# No C++ test names a fixed file in the system's temporary folder: ctest -j runs tests side by side
# in separate processes, and two that write /tmp/bad.data at once read each other's file (a clean
# CI run failed that way). Tests take tests/support/scratch_path.hpp's per-process path instead.
# The check itself is shown to fail on a file that breaks the rule.
source "$(dirname "$0")/lib.bash"
set -e
shared_scratch() {  # prints the offending lines of the C++ files under $1
  grep -rnE 'TempDir\(\)|temp_directory_path\(\) */' --include='*.cpp' --include='*.hpp' "$1" |
    grep -v 'tests/support/scratch_path.hpp' || true
}
found=$(shared_scratch "$ROOT/tests")
[ -z "$found" ] || { echo "tests writing a shared temporary path (use scratch_path):"; echo "$found"; exit 1; }
mkdir -p "$WORK/bad"
printf 'const auto p = std::filesystem::temp_directory_path() / "x.data";\n' > "$WORK/bad/a_test.cpp"
[ -n "$(shared_scratch "$WORK/bad")" ] || { echo "the check misses a fixed temporary path"; exit 1; }
echo "ok: no shared temporary paths in the C++ tests"
