#!/usr/bin/env bash
# --help of the program and of every subcommand is complete and exits 0.
source "$(dirname "$0")/lib.bash"
set -e
"$SF" --help | grep -q "run" || fail "--help does not list run"
for sub in run plot convert; do
  "$SF" $sub --help > "$WORK/help.txt" || fail "$sub --help failed"
  [ "$(wc -l < "$WORK/help.txt")" -gt 5 ] || fail "$sub --help is too short"
done
"$SF" run --help | grep -q -- "--resume" || fail "run --help lacks --resume"
"$SF" --version | grep -q "shockfield" || fail "--version"
"$SF" run "$ROOT/tests/cli/cases/tiny_cu.toml" --check | grep -q "valid md case" || fail "--check"

# Usage errors exit 2, like every other input error (CLI11's own codes were 105, 106, 109, ...),
# with a message; --help and --version exit 0.
usage_error() {  # usage_error ARGS...: exit code 2 and a message on stderr
  set +e
  "$SF" "$@" > /dev/null 2> "$WORK/usage.txt"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "'$*' exited $code, expected 2: $(cat "$WORK/usage.txt")"
  [ -s "$WORK/usage.txt" ] || fail "'$*' said nothing"
}
usage_error run --no-such-option "$ROOT/tests/cli/cases/tiny_cu.toml"
usage_error run "$WORK/does_not_exist.toml"
usage_error run
usage_error run "$ROOT/tests/cli/cases/tiny_cu.toml" -j minus-one
usage_error analyze minkowski
usage_error convert
usage_error convert "$ROOT/tests/cli/cases/tiny_cu.toml" --format no-such-format
usage_error no-such-subcommand
usage_error
"$SF" analyze --help > /dev/null || fail "analyze --help did not exit 0"

# The default run folder: runs/<case name>, and a case.toml is named by its folder, so two
# examples run from one place do not collide in runs/case.
mkdir -p "$WORK/cwd" "$WORK/first_example" "$WORK/second_example"
cp "$ROOT/tests/cli/cases/tiny_cu.toml" "$WORK/first_example/case.toml"
cp "$ROOT/tests/cli/cases/tiny_cu.toml" "$WORK/second_example/case.toml"
cp "$ROOT/tests/cli/cases/tiny_cu.toml" "$WORK/named.toml"
sf=$(cd "$(dirname "$SF")" && pwd)/$(basename "$SF")
(cd "$WORK/cwd" && for c in ../first_example/case.toml ../second_example/case.toml ../named.toml; do
   "$sf" run "$c" --set stage[0].steps=2 --set stage[1].steps=2 -q > /dev/null || exit 1
 done) || fail "a run into the default folder failed"
for d in first_example second_example named; do
  [ -s "$WORK/cwd/runs/$d/log.txt" ] || fail "no default run folder runs/$d: $(ls "$WORK/cwd/runs")"
done
echo "help: ok"
