# Shared by the `shockfield run` tests under mpirun (dbm_ranks.sh, md_run.sh, pd_ranks.sh):
# tests/cli/lib.bash (SF, ROOT, WORK, fail) with MPIEXEC, `mpi NP ARGS...`, `refused NP PATTERN
# ARGS...`, `same_outputs REFERENCE RUN WHAT`, `stop_then_resume STEPS NP FOLDER ARGS...` and
# `fails_alike PATTERN WHAT ARGS...`.
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

# Everything a run writes except what records the run itself (log, provenance, timings) and the
# checkpoint (checked through the resumed run; the DBM's ghost cells hold the last stage's halo).
outputs() { (cd "$1" && find . -type f ! -name log.txt ! -name summary.json ! -name config.resolved.toml \
             ! -name 'checkpoint*' | sort); }
# RUN's outputs are the same files as REFERENCE's, byte for byte.
same_outputs() {  # REFERENCE RUN WHAT
  local n=0
  [ "$(outputs "$1")" = "$(outputs "$2")" ] || fail "$3: the file lists differ: $(outputs "$2" | tr '\n' ' ')"
  for f in $(outputs "$1"); do
    cmp -s "$1/$f" "$2/$f" || fail "$3: $f differs from the serial run's"
    n=$((n + 1))
  done
  echo "ok: $3: $n files byte-identical to the serial run"
}
# `shockfield run ARGS` stopped after STEPS steps on 4 ranks (exit code 130) in FOLDER, then
# resumed there on NP ranks.
stop_then_resume() {  # STEPS NP FOLDER ARGS...
  local steps="$1" np="$2" folder="$3"; shift 3
  set +e
  mpi 4 run "$@" --output "$folder" -q --stop-after "$steps" > /dev/null 2> "$WORK/stop.txt"
  local code=$?
  set -e
  [ $code -eq 130 ] || fail "the stopped 4-rank run exited $code: $(cat "$WORK/stop.txt")"
  mpi "$np" run "$@" --output "$folder" -q --resume > /dev/null
}
# `shockfield run ARGS` blows up alike serially and on 2 ranks: exit code 3, the same error line
# (the one holding PATTERN) and the same output kept.
fails_alike() {  # PATTERN WHAT ARGS...
  local pattern="$1" what="$2"; shift 2
  set +e
  "$SF" run "$@" --output "$WORK/fail1" -q > /dev/null 2> "$WORK/fail1.txt"
  local code1=$?
  mpi 2 run "$@" --output "$WORK/fail2" -q > /dev/null 2> "$WORK/fail2.txt"
  local code2=$?
  set -e
  [ $code1 -eq 3 ] && [ $code2 -eq 3 ] || fail "$what: exit codes $code1 (serial), $code2 (2 ranks), expected 3"
  local serial_line
  serial_line=$(grep -F -- "$pattern" "$WORK/fail1.txt")
  [ -n "$serial_line" ] && [ "$(grep -F -- "$pattern" "$WORK/fail2.txt")" = "$serial_line" ] ||
    fail "$what: the 2-rank message differs: $(cat "$WORK/fail2.txt") vs $serial_line"
  same_outputs "$WORK/fail1" "$WORK/fail2" "$what on 2 ranks (output kept)"
}
