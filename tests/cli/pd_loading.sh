#!/usr/bin/env bash
# PD loading and geometry from case files (docs/pd.md): a pre-cracked plate whose edge is pushed
# at a prescribed velocity runs with damage along its crack and none elsewhere, the pushed edge at
# x + v·t and v, and stopped and resumed gives the same files bitwise (a disc of it a separate
# body); the J2 plate runs with the same crack left out of its families; a block runs as striker
# and target (separate bodies); bad [[crack]] and [[region]]
# tables are refused before the run with the file, key and what was expected (a crack outside the
# body, a zero-length crack, a corner of the wrong dimension, a crack in a 1D bar, a non-planar
# polygon in 3D; a region selecting no point, with both or neither velocity, a velocity of the
# wrong size, no loading at all, overlapping bodies, a separate body without contact).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
case="$ROOT/tests/cli/cases/pd_plate_loading.toml"
plate=$(cat "$case")
"$SF" run "$case" --check | grep -q "valid pd case (800 points" || fail "--check does not report the case"
"$SF" run "$case" --output "$WORK/plate" -q > /dev/null
grep -q "pre-cracks: 1 crack(s) cut" "$WORK/plate/log.txt" || fail "the log does not report the cut bonds"
grep -q "region 0: 60 points held at (20, 0, 0) m/s" "$WORK/plate/log.txt" || fail "the log does not report the held region"
# The disc of radius 2.5 mm around the point (33, 15) mm: the 21 points within 2.5 spacings.
grep -q "region 1: 21 points starting at (0, -5, 0) m/s, a separate body" "$WORK/plate/log.txt" || fail "the log does not report the disc"
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
# The pushed edge (x <= 2.5 mm) at t = 2 µs: ux = 20 m/s · 2 µs = 4e-5 m, vx = 20 m/s (profile digits).
awk -F, 'NR > 1 && $1 <= 0.0025 { if ($4 != 4e-05 || $5 != 20 || $6 != 0) bad = bad " " $1 "," $2 ": " $4 " " $5 " " $6; n++ }
         END { if (bad != "" || n != 60) { print n " points, held wrongly:" bad; exit 1 } }' \
  "$WORK/plate/profiles/profile_0.csv" || fail "the prescribed edge did not move at exactly 20 m/s"
echo "ok: the 60 points of the pushed edge at x + v·t with v"
echo "${plate/series_interval = 1e-7/series_interval = 1e-7
profile_interval = 5e-7}" > "$WORK/resume.toml"
"$SF" run "$WORK/resume.toml" --output "$WORK/straight" -q > /dev/null
stop_then_resume "$WORK/resume.toml" "$WORK/split" 7
same_files "$WORK/straight" "$WORK/split" series.csv profiles/index.csv \
  $(cd "$WORK/straight" && ls profiles/profile_*.csv profiles/points_*.vtp)
echo "ok: held region and pre-crack resumed bitwise"
# The correspondence model (J2) runs on the family without the cut bonds (damage stays 0).
j2="${plate/separate = true
/}"
j2="${j2/model = \"lps\"/model = \"j2\"}"
j2="${j2/bulk = 158e9
shear = 73e9
critical_stretch = 0.01/young = 190e9
poisson = 0.3
yield_stress = 1.9e9}"
echo "$j2" > "$WORK/j2.toml"
"$SF" run "$WORK/j2.toml" --output "$WORK/j2" -q > /dev/null
grep -q "pre-cracks: 1 crack(s) cut 169 bonds (left out of the correspondence family)" "$WORK/j2/log.txt" ||
  fail "J2 pre-crack not reported: $(grep pre-cracks "$WORK/j2/log.txt")"
grep -q "pre-cracks: 1 crack(s) cut 169 bonds (broken from step 0)" "$WORK/plate/log.txt" ||
  fail "LPS pre-crack count differs from J2's: $(grep pre-cracks "$WORK/plate/log.txt")"
echo "ok: J2 plate with the same crack (169 bonds) runs"

crack='from = [19.5e-3, -1e-3]
to = [19.5e-3, 9.5e-3]'
expect_error "${plate/"$crack"/from = [50e-3, -1e-3]
to = [50e-3, 9.5e-3]}" "case.toml" "crack[0].from" "cuts no bond of the body"
"$SF" run "$WORK/case.toml" --check > /dev/null 2> "$WORK/check.txt" && fail "--check passed a crack outside the body"
grep -qF "crack[0].from" "$WORK/check.txt" || fail "--check does not name the crack: $(cat "$WORK/check.txt")"
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
edge='xhi = 2.5e-3
prescribed_velocity = [20.0, 0.0]'
expect_error "${plate/"$edge"/xlo = 50e-3
prescribed_velocity = [20.0, 0.0]}" "region[0].shape" "selects no point of the body"
expect_error "${plate/"$edge"/xhi = 2.5e-3
velocity = [1.0, 0.0]
prescribed_velocity = [20.0, 0.0]}" "region[0]" "exactly one of velocity"
expect_error "${plate/"$edge"/xhi = 2.5e-3}" "region[0]" "exactly one of velocity"
expect_error "${plate/"$edge"/xhi = 2.5e-3
prescribed_velocity = [20.0, 0.0, 0.0]}" "region[0].prescribed_velocity" "2 numbers"
expect_error "${plate/shape = \"sphere\"/shape = \"cone\"}" "region[1].shape" "expected one of"
expect_error "$(sed '/^\[loading\]/,/^speed/d' <<< "$bar")" "loading" "missing required table [loading]"
# Separate bodies: the block of pd_block_contact.toml as a striker (left half, a separate region at
# 100 m/s) and a target (the rest, at rest), bonded to nothing across: it runs; overlapping bodies
# and a separate body without the contact force (J2) are refused.
striker='[[region]]
shape = "block"
xhi = 4.75e-3
separate = true
velocity = [100.0, 0.0, 0.0]'
two_bodies=$(sed '/^\[loading\]/,/^speed/d' <<< "$block")
echo "$two_bodies
$striker" > "$WORK/two_bodies.toml"
"$SF" run "$WORK/two_bodies.toml" --output "$WORK/two_bodies" -q --set solver.end_time=2e-5 > /dev/null
grep -q "region 0: 640 points starting at (100, 0, 0) m/s, a separate body" "$WORK/two_bodies/log.txt" ||
  fail "the striker is not reported: $(grep region "$WORK/two_bodies/log.txt")"
echo "ok: striker and target as separate bodies of one lattice"
expect_error "$two_bodies
$striker
[[region]]
shape = \"block\"
xlo = 4.25e-3
separate = true" "region[1].separate" "overlaps the separate body of region[0]"
expect_error "${j2/"$edge"/xhi = 2.5e-3
separate = true}" "region[0].separate" "contact force"
echo "pd_loading: all cases passed"
