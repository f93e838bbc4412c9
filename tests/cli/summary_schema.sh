#!/bin/bash
# tests/cli/check_summary.py, the summary.json checker the run tests use, against the schema in
# docs/summary.schema.json: it accepts a good summary (tests/fixtures/summary/good.json) and
# refuses broken ones (a missing key, a wrong type, an unknown status, an unknown key, NaN, a bad
# input-file checksum, a wrong method, text that is not JSON), each with a message naming the key.
source "$(dirname "$0")/lib.bash"
set -e
CHECK="/usr/bin/python3 $ROOT/tests/cli/check_summary.py"
GOOD="$ROOT/tests/fixtures/summary/good.json"
$CHECK "$GOOD" --method md --status finished > "$WORK/out.txt" || fail "good summary refused: $(cat "$WORK/out.txt")"
grep -q "valid summary.json" "$WORK/out.txt" || fail "no confirmation for the good summary"
# broken NAME PYTHON_EDIT PATTERN: the good summary edited by a Python statement on `s` is refused
# (exit 1) with PATTERN in the message.
broken() {
  local name="$1" edit="$2" pattern="$3"
  /usr/bin/python3 -c "import json,sys; s=json.load(open(sys.argv[1])); $edit; json.dump(s, open(sys.argv[2],'w'))" \
    "$GOOD" "$WORK/$name.json"
  set +e
  $CHECK "$WORK/$name.json" > "$WORK/out.txt"
  local code=$?
  set -e
  [ $code -eq 1 ] || fail "$name: exit code $code, expected 1: $(cat "$WORK/out.txt")"
  grep -qF -- "$pattern" "$WORK/out.txt" || fail "$name: message lacks '$pattern': $(cat "$WORK/out.txt")"
  echo "ok $name: $(head -c 150 "$WORK/out.txt")"
}
broken missing_steps "del s['steps']" "missing required key 'steps'"
broken string_steps "s['steps'] = '2000'" "\$.steps: expected integer"
broken negative_wall "s['wall_seconds'] = -1" "\$.wall_seconds: expected a number >= 0"
broken bad_status "s['status'] = 'done'" "\$.status: expected one of"
broken unknown_key "s['stpes'] = 1" "unknown key 'stpes'"
broken rate_text "s['rates']['ns_per_day'] = 'fast'" "\$.rates.ns_per_day: expected number or null"
broken bad_sha "s['provenance']['input_files'][0]['sha256'] = 'abc'" "\$.provenance.input_files[0].sha256"
broken relative_path "s['provenance']['input_files'][0]['path'] = 'Cu_u3.eam'" "input_files[0].path"
broken results_list "s['results'] = []" "\$.results: expected object"
broken bool_steps "s['steps'] = True" "\$.steps: expected integer"
broken version "s['schema_version'] = 2" "\$.schema_version: expected 1"
# NaN is not JSON: the writer puts null for non-finite numbers, so a NaN token is refused.
sed 's/"time": 2.0/"time": NaN/' "$GOOD" > "$WORK/nan.json"
set +e; $CHECK "$WORK/nan.json" > "$WORK/out.txt"; code=$?; set -e
[ $code -eq 1 ] && grep -q "NaN is not JSON" "$WORK/out.txt" || fail "NaN accepted: $(cat "$WORK/out.txt")"
printf '{"method": "md",' > "$WORK/cut.json"
set +e; $CHECK "$WORK/cut.json" > "$WORK/out.txt"; code=$?; set -e
[ $code -eq 1 ] && grep -q "cannot read it as JSON" "$WORK/out.txt" || fail "truncated file accepted: $(cat "$WORK/out.txt")"
set +e; $CHECK "$GOOD" --method mpm > "$WORK/out.txt"; code=$?; set -e
[ $code -eq 1 ] && grep -q "expected 'mpm', got \"md\"" "$WORK/out.txt" || fail "wrong method accepted: $(cat "$WORK/out.txt")"
echo "summary_schema: good summary accepted; 11 broken ones, NaN, a cut file and a wrong method refused"
