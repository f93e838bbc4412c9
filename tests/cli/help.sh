#!/usr/bin/env bash
# --help of the program and of every subcommand is complete and exits 0.
source "$(dirname "$0")/lib.bash"
set -e
"$SF" --help | grep -q "run" || fail "--help does not list run"
for sub in run plot; do
  "$SF" $sub --help > "$WORK/help.txt" || fail "$sub --help failed"
  [ "$(wc -l < "$WORK/help.txt")" -gt 5 ] || fail "$sub --help is too short"
done
"$SF" run --help | grep -q -- "--resume" || fail "run --help lacks --resume"
"$SF" --version | grep -q "shockfield" || fail "--version"
"$SF" run "$ROOT/tests/cli/cases/tiny_cu.toml" --check | grep -q "valid md case" || fail "--check"
echo "help: ok"
