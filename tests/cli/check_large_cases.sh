#!/usr/bin/env bash
# `shockfield run CASE --check` validates a case whose arrays would take tens to ~100 GB without
# allocating them (issue 14; docs/robustness.md): every method's factory reads and validates the
# case and counts its cells, nodes, points, bonds or atoms, and the arrays are allocated when the
# run starts. Each check runs in 2 GB of address space (ulimit -v) and must finish within 10 s
# (they take 0.1-1 s, most of it DBM's linear stability analysis); the sizes it prints are asserted.
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

# PD: 250^3 points at horizon_factor 3, 1.88·10^9 bonds (within the 2·10^9 bound): ~91 GB. The
# model and the stable step are checked on a 13^3 sub-body; the whole body is counted.
pd="$ROOT/tests/cli/cases/pd_tiny.toml"
check_large pd "$(sed -e 's/dim = 1/dim = 3/' -e 's/counts = \[400\]/counts = [250, 250, 250]/' "$pd")" \
  "15625000 points, 1880110848 bonds" "90.8 GB when it runs" "13 x 13 x 13 sub-body"
# A large horizon: 60^3 points at horizon_factor 14 (1.88·10^9 bonds): the sub-body of four
# horizons (57^3 points, ~10^9 bonds) would cost as much as the run, so a smaller one (at most
# 5·10^6 bonds, 13^3) is built and the stable step is called an estimate (~1.4 s, 0.15 GB).
check_large pd_m14 "$(sed -e 's/dim = 1/dim = 3/' -e 's/counts = \[400\]/counts = [60, 60, 60]/' \
  -e 's/horizon_factor = 3.0/horizon_factor = 14.0/' "$pd")" "216000 points, 1884341712 bonds" "13 x 13 x 13 sub-body" "the step is an estimate"
# The sub-body gives the whole body's values: a 30 x 20 x 18 body (j2 and pmb) is run, and its
# config.resolved.toml (points, bonds, stable_time_step_s, time_step_s, steps under [derived],
# compared to 1e-12 relative) is checked again with --check, which builds only a 13^3 sub-body.
mid=$(sed -e 's/dim = 1/dim = 3/' -e 's/counts = \[400\]/counts = [30, 20, 18]/' -e 's/end_time = 2e-7/end_time = 2e-9/' "$pd")
pmb=$(printf '%s\n' "$mid" | sed -e 's/model = "j2"/model = "pmb"\nmicromodulus = 1e21\ncritical_stretch = 0.01/' \
  -e '/^young\|^poisson\|^yield_stress/d')
for model in j2 pmb; do
  if [ $model = j2 ]; then text="$mid"; else text="$pmb"; fi
  printf '%s\n' "$text" > "$WORK/mid_$model.toml"
  "$SF" run "$WORK/mid_$model.toml" -q --output "$WORK/mid_$model" > /dev/null
  "$SF" run "$WORK/mid_$model/config.resolved.toml" --check > "$WORK/stdout" 2>&1 \
    || fail "$model: the sub-body's derived values differ from the run's: $(cat "$WORK/stdout")"
  grep -qF "10800 points, 1117512 bonds" "$WORK/stdout" || fail "$model: $(cat "$WORK/stdout")"
  grep -qF "13 x 13 x 13 sub-body" "$WORK/stdout" || fail "$model: no sub-body: $(cat "$WORK/stdout")"
  echo "ok: $model sub-body = whole body: $(cat "$WORK/stdout")"
done
# Right above the bond bound: refused by key with the count and its memory (exit 2).
expect_error "$(sed -e 's/dim = 1/dim = 3/' -e 's/counts = \[400\]/counts = [100, 100, 100]/' \
  -e 's/horizon_factor = 3.0/horizon_factor = 10.0/' "$pd")" "body.horizon_factor" "3.72e+09 bonds" "149 GB" \
  "at most 2e+09 bonds"

# MD: 400^3 fcc cells, 2.56·10^8 atoms (~102 GB at ~400 B an atom): the crystal is counted (one
# repeat cell times the cells, as no region deletes or selects atoms), only 3^3 cells are built
# for the types and the overlap check.
md=$(sed 's/repeat = \[4, 4, 4\]/repeat = [400, 400, 400]/' "$ROOT/tests/cli/cases/tiny_cu.toml")
check_large md "$md" "256000000 atoms" "102 GB when it runs" "the crystal counted, not built"
# The count is the built crystal's: the [111] void example (rotated cells) with a deleted sphere
# and a block group (every site visited), and without them (one cell multiplied, plus the sites
# create_atoms puts on the shrink-wrapped zhi face), run for 4 steps;
# --check of its config.resolved.toml derives the same atoms, atoms_deleted, atoms_in_group_*
# and density_g_cc (1e-12) from the counted crystal.
void="$ROOT/examples/md_void_shock_111/case.toml"
with_regions=$(sed -e 's/steps = 500/steps = 2/' -e 's/steps = 3000/steps = 2/' -e 's/^radius = 5.0/radius = 5.0\n\n[[system.group]]\nname = "top"\nshape = "block"\nxlo = -100.0\nxhi = 100.0\nylo = -100.0\nyhi = 100.0\nzlo = 100.0\nzhi = 1000.0\n\n[[system.group]]\nname = "cu"\ntypes = [1]/' "$void")
without=$(sed -e 's/steps = 500/steps = 2/' -e 's/steps = 3000/steps = 2/' -e '/^\[\[system.delete\]\]/,/^radius = 5.0/d' \
  -e 's/^elements = \["Cu"\]/elements = ["Cu"]\n\n[[system.group]]\nname = "cu"\ntypes = [1]/' "$void")
for name in with_regions without; do
  if [ $name = without ]; then text="$without"; atoms=8760; else text="$with_regions"; atoms=8717; fi
  printf '%s\n' "$text" > "$WORK/$name.toml"
  "$SF" run "$WORK/$name.toml" -q --output "$WORK/$name" > /dev/null
  grep -q "^atoms = $atoms\$" "$WORK/$name/config.resolved.toml" || fail "$name: the run does not have $atoms atoms"
  "$SF" run "$WORK/$name/config.resolved.toml" --check > "$WORK/stdout" 2>&1 \
    || fail "$name: the counted crystal differs from the built one: $(cat "$WORK/stdout")"
  grep -qF "($atoms atoms" "$WORK/stdout" && grep -qF "counted, not built" "$WORK/stdout" || fail "$name: $(cat "$WORK/stdout")"
  echo "ok: md $name: counted = built: $(cat "$WORK/stdout")"
done
echo "check_large_cases: dbm, phasefield, pd, md checked without their arrays"
