# Helpers for the command-line tests: $SF is the shockfield binary, $ROOT the source tree.
set -u
SF="$1"
ROOT="$2"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# reports_planted REPORT COUNT PATTERN...: a checker's REPORT on planted problems names each
# PATTERN and has COUNT lines (nothing else reported).
reports_planted() {
  local report="$1" count="$2" p
  shift 2
  for p in "$@"; do
    grep -qF -- "$p" "$report" || fail "not reported: $p ($(cat "$report"))"
  done
  [ "$(wc -l < "$report")" -eq "$count" ] || fail "other than the $count planted problems: $(cat "$report")"
}
# run_expecting CODE CASE_TEXT PATTERN...: runs the case into $WORK/out; the exit code must be
# CODE and stderr must contain every pattern.
run_expecting() {
  local expected="$1" text="$2"; shift 2
  printf '%s\n' "$text" > "$WORK/case.toml"
  rm -rf "$WORK/out"
  set +e
  "$SF" run "$WORK/case.toml" --output "$WORK/out" -q > "$WORK/stdout" 2> "$WORK/stderr"
  local code=$?
  set -e
  [ $code -eq "$expected" ] || fail "exit code $code (expected $expected) for: $text; stderr: $(cat "$WORK/stderr")"
  for p in "$@"; do
    grep -qF -- "$p" "$WORK/stderr" || fail "message lacks '$p': $(cat "$WORK/stderr")"
  done
  echo "ok: $(head -c 160 "$WORK/stderr")"
}
# expect_error CASE_TEXT PATTERN...: the case is rejected before running (exit 2) and no run
# folder is left behind.
expect_error() {
  run_expecting 2 "$@"
  [ ! -e "$WORK/out" ] || fail "a run folder was left behind for: $1"
}
# stop_then_resume CASE_FILE RUN_DIR STEPS: runs the case with --stop-after STEPS (exit 130, a
# message saying how to resume and a checkpoint expected), then resumes it to the end in the same
# folder.
stop_then_resume() {
  local case_file="$1" out="$2" steps="$3"
  set +e
  "$SF" run "$case_file" --output "$out" -q --stop-after "$steps" > /dev/null 2> "$WORK/stop.txt"
  local code=$?
  set -e
  [ $code -eq 130 ] || fail "stopped run exit code $code, expected 130: $(cat "$WORK/stop.txt")"
  grep -q -- "--resume" "$WORK/stop.txt" || fail "the stop message does not say how to resume"
  [ -s "$out/checkpoint.h5" ] || fail "a stopped run wrote no checkpoint in $out"
  "$SF" run "$case_file" --output "$out" -q --resume > /dev/null
}
# same_files DIR_A DIR_B FILE...: each FILE (relative) is byte-identical in both folders.
same_files() {
  local a="$1" b="$2" f
  shift 2
  for f in "$@"; do
    cmp "$a/$f" "$b/$f" || fail "resumed $f differs ($a vs $b)"
  done
}
# analyze_rejected PATTERN -- ARGS...: `$SF analyze ARGS -o $WORK/bad` must exit 2 with PATTERN in
# its message and leave no output folder.
analyze_rejected() {
  local pattern="$1"; shift 2
  set +e
  "$SF" analyze "$@" -o "$WORK/bad" > "$WORK/stdout" 2> "$WORK/stderr"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "exit code $code (expected 2) for: $*; stderr: $(cat "$WORK/stderr")"
  grep -qF -- "$pattern" "$WORK/stderr" || fail "message lacks '$pattern': $(cat "$WORK/stderr")"
  [ ! -e "$WORK/bad" ] || fail "an output folder was left behind for: $*"
  echo "ok: $(head -c 160 "$WORK/stderr")"
}
# lammps_reads_data FILE NATOMS [BOUNDARY]: LAMMPS `read_data` (metal, atomic, boundary BOUNDARY,
# default ppp) reads FILE and assigns NATOMS atoms; the caller checks `command -v lmp` first.
lammps_reads_data() {
  local data="$1" natoms="$2" boundary="${3:-ppp}"
  printf 'units metal\natom_style atomic\nboundary %s %s %s\nread_data %s\n' \
    "${boundary:0:1}" "${boundary:1:1}" "${boundary:2:1}" "$data" > "$WORK/in.read"
  (cd "$WORK" && lmp -in in.read -log none > lmp.out 2>&1) || fail "$data: LAMMPS read_data failed: $(grep -m1 ERROR "$WORK/lmp.out")"
  grep -qE "^ +$natoms atoms$" "$WORK/lmp.out" || fail "$data: LAMMPS did not read $natoms atoms: $(cat "$WORK/lmp.out")"
}
