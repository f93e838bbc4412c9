#!/usr/bin/env bash
# `shockfield run CASE --check` validates a case whose arrays would take tens to ~100 GB without
# allocating them (issue 14; docs/robustness.md): every method's factory reads and validates the
# case and counts its cells, nodes, points, bonds or atoms, and the arrays are allocated when the
# run starts. Each check runs in 2 GB of address space (ulimit -v) and must finish within 10 s
# (they take ~1 s, most of it DBM's linear stability analysis); the sizes it prints are asserted.
# With main's binary before this change each of them stopped with exit 3, "out of memory".
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
# check_large NAME CASE_TEXT PATTERN...: --check of the case in 2 GB, exit 0 within 10 s, stdout
# holding every pattern.
check_large() {
  local name="$1" text="$2"; shift 2
  printf '%s\n' "$text" > "$WORK/$name.toml"
  set +e
  local start=$SECONDS
  (ulimit -v 2000000; timeout 20 "$SF" run "$WORK/$name.toml" --check > "$WORK/stdout" 2> "$WORK/stderr")
  local code=$? took=$((SECONDS - start))
  set -e
  [ $code -eq 0 ] || fail "$name: --check exit $code (expected 0): $(cat "$WORK/stderr")"
  [ $took -le 10 ] || fail "$name: --check took $took s (expected < 10 s)"
  for p in "$@"; do
    grep -qF -- "$p" "$WORK/stdout" || fail "$name: --check does not print '$p': $(cat "$WORK/stdout")"
  done
  echo "ok ($took s): $(cat "$WORK/stdout")"
}

# DBM: 16000 x 16000 cells of D2V16, three copies of the distributions with two ghost layers:
# 8 B x 16 x 3 x 16004^2 = 98.4 GB.
dbm=$(sed -e 's/nx = 100/nx = 16000\nny = 16000/' -e 's/tau = 1e-3/tau = 1e-3\nstability_check = "warn"/' \
  "$ROOT/tests/cli/cases/dbm_sod.toml")
check_large dbm "$dbm" "16000 x 16000 cells" "256000000 cells, 98.4 GB when it runs"

# Phase field: the largest grid allowed (10^9 nodes), spectral: xi and its work array (16 GB) and
# the half spectrum with its factors (12 GB).
check_large phasefield 'method = "phasefield"
[grid]
dimensions = 3
nodes = [1000, 1000, 1000]
spacing = 0.5
[model]
a = 0.4
D = 1.0
[time]
scheme = "spectral"
dt = 0.1
end_time = 6.0
[[initial.sphere]]
center = [8.0, 10.0, 10.0]
radius = 5.0
[output]
series_interval = 0.5' "1000000000 nodes" "28 GB when it runs"
