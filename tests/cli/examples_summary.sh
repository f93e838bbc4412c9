#!/usr/bin/env bash
# Every example's case file runs through the driver and leaves a summary.json that passes the
# schema (tests/cli/check_summary.py): each case is run for two steps (--stop-after 2: exit 130,
# status "stopped"); a pd [homogeneous] case keeps no checkpoint, so it runs whole (seconds).
# An example whose inputs are generated (a prepare.sh beside its cases) is copied and prepared
# first, so the source tree is left as it is. A case that reads another run's output (a line
# "# needs: ..." saying which) is left to the test named there. Every run folder is then checked
# against the output conventions (tests/cli/conventions.py).
source "$(dirname "$0")/lib.bash"
set -e
count=0
runs=()
for example in "$ROOT"/examples/*/; do
  [ -f "$example/prepare.sh" ] || continue
  copy="$WORK/prepared/$(basename "$example")"
  mkdir -p "$copy" && cp -r "$example"/. "$copy"/
  sh "$copy/prepare.sh" > /dev/null || fail "$example/prepare.sh failed"
done
for case_file in "$ROOT"/examples/*/*.toml; do
  grep -q '^# needs: ' "$case_file" && continue
  prepared="$WORK/prepared/$(basename "$(dirname "$case_file")")"
  [ -d "$prepared" ] && case_file="$prepared/$(basename "$case_file")"
  out="$WORK/$(basename "$(dirname "$case_file")")_$(basename "$case_file" .toml)"
  limit=(--stop-after 2)
  grep -q '^\[homogeneous\]' "$case_file" && limit=()
  set +e
  "$SF" run "$case_file" --output "$out" -q "${limit[@]}" > "$WORK/stdout" 2> "$WORK/stderr"
  code=$?
  set -e
  [ $code -eq 130 ] || [ $code -eq 0 ] || fail "$case_file: exit $code: $(tail -c 400 "$WORK/stderr")"
  status=stopped
  [ $code -eq 0 ] && status=finished
  /usr/bin/python3 "$ROOT/tests/cli/check_summary.py" "$out/summary.json" --status "$status" \
    || fail "$case_file: summary.json does not pass the schema"
  runs+=("$out")
  count=$((count + 1))
done
[ $count -ge 20 ] || fail "only $count example case files found"
# The output conventions (docs/conventions.md) on every example's first steps: units in every
# CSV column and summary.json key, one time column, units on every VTK array (one python process).
/usr/bin/python3 "$ROOT/tests/cli/conventions.py" "${runs[@]}" || fail "an example's run folder breaks the output conventions (above)"
echo "examples_summary: $count example case files, each summary.json valid, each folder following the conventions"
