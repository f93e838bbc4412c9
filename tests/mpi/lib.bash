# Shared by the `shockfield run` tests under mpirun (dbm_ranks.sh, md_run.sh): tests/cli/lib.bash
# (SF, ROOT, WORK, fail) with MPIEXEC, `mpi NP ARGS...` and `refused NP PATTERN ARGS...`.
source "$(dirname "${BASH_SOURCE[0]}")/../cli/lib.bash"
MPIEXEC="$3"
mpi() { local np="$1"; shift; "$MPIEXEC" --oversubscribe --allow-run-as-root -np "$np" "$SF" "$@"; }
# Bad input: `shockfield run ARGS` on NP ranks exits 2 with PATTERN in one error line and leaves
# no run folder.
refused() {  # NP PATTERN ARGS...
  local np="$1" pattern="$2"; shift 2
  rm -rf "$WORK/bad"
  set +e
  mpi "$np" run "$@" --output "$WORK/bad" -q > "$WORK/stdout" 2> "$WORK/stderr"
  local code=$?
  set -e
  [ $code -eq 2 ] || fail "exit code $code (expected 2) for $*: $(cat "$WORK/stderr")"
  grep -qF -- "$pattern" "$WORK/stderr" || fail "message lacks '$pattern': $(cat "$WORK/stderr")"
  [ "$(grep -c '^error:' "$WORK/stderr")" -eq 1 ] || fail "the error is not printed once: $(cat "$WORK/stderr")"
  [ ! -e "$WORK/bad" ] || fail "a run folder was left behind for $*"
  echo "ok: $(grep '^error:' "$WORK/stderr" | head -c 200)"
}
