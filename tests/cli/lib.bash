# Helpers for the command-line tests: $SF is the shockfield binary, $ROOT the source tree.
set -u
SF="$1"
ROOT="$2"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# expect_error CASE_TEXT PATTERN...: the case must be rejected (exit 2), the message must contain
# every pattern, and no run folder may be left behind.
expect_error() {
  local text="$1"; shift
  printf '%s\n' "$text" > "$WORK/bad.toml"
  set +e
  "$SF" run "$WORK/bad.toml" --output "$WORK/out" > "$WORK/stdout" 2> "$WORK/stderr"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "exit code $code (expected 2) for: $text; stderr: $(cat "$WORK/stderr")"
  for p in "$@"; do
    grep -qF -- "$p" "$WORK/stderr" || fail "message lacks '$p': $(cat "$WORK/stderr")"
  done
  [ ! -e "$WORK/out" ] || fail "a run folder was left behind for: $text"
  echo "ok: $(head -c 150 "$WORK/stderr")"
}
