#!/usr/bin/env bash
# PD loading and geometry from case files (docs/pd.md): a pre-cracked plate runs with damage along
# its crack and none elsewhere, and bad [[crack]] tables are refused before the run with the file,
# key and what was expected (a crack outside the body, a zero-length crack, a corner of the wrong
# dimension, a crack in a 1D bar, a non-planar polygon in 3D).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
case="$ROOT/tests/cli/cases/pd_plate_precrack.toml"
plate=$(cat "$case")
"$SF" run "$case" --output "$WORK/plate" -q > /dev/null
grep -q "pre-cracks: 1 crack(s) cut" "$WORK/plate/log.txt" || fail "the log does not report the cut bonds"
# damage_at X_M Y_M: the damage column of the last profile at that reference point.
damage_at() {
  awk -F, -v x="$1" -v y="$2" 'NR > 1 && $1 == x && $2 == y { print $NF }' "$WORK/plate/profiles/profile_0.csv"
}
for y in 0.002 0.005 0.008; do
  for x in 0.019 0.02; do
    awk -v d="$(damage_at $x $y)" 'BEGIN { exit !(d > 0.1) }' || fail "no damage beside the crack at ($x, $y): $(damage_at $x $y)"
  done
done
for point in "0.019 0.015" "0.005 0.005" "0.035 0.005"; do
  [ "$(damage_at $point)" = "0" ] || fail "damage away from the crack at ($point): $(damage_at $point)"
done
echo "ok: pre-cracked plate damaged along its crack only"

crack='from = [19.5e-3, -1e-3]
to = [19.5e-3, 9.5e-3]'
expect_error "${plate/"$crack"/from = [50e-3, -1e-3]
to = [50e-3, 9.5e-3]}" "case.toml" "crack[0].from" "cuts no bond of the body"
expect_error "${plate/"$crack"/from = [1e-3, 1e-3]
to = [1e-3, 1e-3]}" "crack[0].to" "same point"
expect_error "${plate/"$crack"/from = [1e-3, 1e-3, 0.0]
to = [1e-3, 2e-3]}" "crack[0].from" "2 numbers"
expect_error "${plate/"$crack"/from = [1e-3, 1e-3]
to = [1e-3, 2e-3]
depth = 1.0}" "unknown key" "crack[0].depth"
bar=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/pd_tiny.toml")
expect_error "$bar
[[crack]]
from = [1e-3]" "crack[0].from" "1D bar"
block=$(cat "$ROOT/tests/cli/cases/pd_block_contact.toml")
expect_error "$block
[[crack]]
vertices = [5e-3, -1e-3, -1e-3, 5e-3, 9e-3, -1e-3, 5e-3, 9e-3, 9e-3, 5.1e-3, -1e-3, 9e-3]" "crack[0].vertices" "off the plane of the others"
expect_error "$block
[[crack]]
vertices = [5e-3, -1e-3, -1e-3, 5e-3, 9e-3, -1e-3]" "crack[0].vertices" "at least three corners"
echo "pd_loading: all cases passed"
