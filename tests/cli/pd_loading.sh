#!/usr/bin/env bash
# PD loading and geometry from case files (docs/pd.md): a pre-cracked plate whose edge is pushed
# at a prescribed velocity runs with damage along its crack and none elsewhere, the pushed edge at
# x + v·t and v, and stopped and resumed gives the same files bitwise (a disc of it a separate
# body); the J2 plate runs with the same crack left out of its families; a block runs as striker
# and target (separate bodies); bad [[crack]] and [[region]]
# tables are refused before the run with the file, key and what was expected (a crack outside the
# body, a zero-length crack, a corner of the wrong dimension, a crack in a 1D bar, a non-planar
# polygon in 3D; a region selecting no point, with both or neither velocity, a velocity of the
# wrong size, no loading at all, overlapping bodies, a separate body without contact). A bar with a
# ramped prescribed displacement and a velocity formula runs as prescribed (its resume:
# stop_resume.sh pd_loading) and runs bitwise the same with the formula's values from a velocity
# file; bad formulas, files, displacements and ramps are refused before the run. The bar and the
# plate as point clouds from files (points_file) run bitwise as their lattices; bad clouds
# (coinciding or isolated points, counts beside points_file, a bad line) and regions selecting no
# point of a cloud are refused. A lattice moved by [body] origin runs as the cloud of its points;
# two point files ([[body.points]]) run as two bodies; a region held in x only is reported and
# bad component lists are refused.
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

# The bar of pd_bar_loading.toml: its first 3 points displaced by 1 µm over 0.2 µs, its right
# quarter (x >= 15 mm, 100 points) starting at 1e3·(x − 15 mm) m/s.
bar_case="$ROOT/tests/cli/cases/pd_bar_loading.toml"
"$SF" run "$bar_case" --output "$WORK/bar" -q > /dev/null
grep -q "region 0: 3 points displaced by (1e-06, 0, 0) m ramped over 2e-07 s" "$WORK/bar/log.txt" ||
  fail "the displaced end is not reported: $(grep region "$WORK/bar/log.txt")"
grep -q "region 1: 100 points starting at the velocity (1e3 \* (x - 15e-3)) m/s" "$WORK/bar/log.txt" ||
  fail "the formula is not reported: $(grep region "$WORK/bar/log.txt")"
# At t = 0 the formula's velocities (x = 17.5 mm: 2.5 m/s; 10 mm: 0); at the end (t = 0.4 µs,
# after the ramp) the displaced end at exactly 1 µm and at rest.
awk -F, 'NR > 1 && ($1 == 0.0175 && $5 != 2.5 || $1 == 0.01 && $5 != 0) { bad = bad " " $1 ": " $5 }
         END { if (bad != "") { print "velocities at t = 0:" bad; exit 1 } }' "$WORK/bar/profiles/profile_0.csv" ||
  fail "the velocity formula was not applied"
awk -F, 'NR > 1 && $1 <= 0.000125 { if ($4 != 1e-06 || $5 != 0) bad = bad " " $1 ": " $4 " " $5; n++ }
         END { if (bad != "" || n != 3) { print n " points:" bad; exit 1 } }' "$WORK/bar/profiles/profile_4.csv" ||
  fail "the displaced end is not at 1 µm at rest after the ramp"
grep -q "region 2: 3 points with the body force (-1000000000000, 0, 0) N/m³" "$WORK/bar/log.txt" ||
  fail "the body force is not reported: $(grep region "$WORK/bar/log.txt")"
# The body force turns the last point back: vx at t = 0.4 µs is −0.28 m/s, +2.71 without it (its
# impulse is checked in tests/unit/pd/test_regions.cpp).
awk -F, 'NR > 1 && $1 == 0.01995 { exit !($5 < 0) }' "$WORK/bar/profiles/profile_4.csv" ||
  fail "the pushed end was not slowed by the body force"
echo "ok: ramped displacement, velocity formula and body force applied"
# (Stopped mid-ramp and resumed bitwise: cli.stop_resume.pd_loading.)
bar_files="series.csv profiles/index.csv $(cd "$WORK/bar" && ls profiles/profile_*.csv profiles/points_*.vtp)"
# The formula's values at the lattice points (x = 50 µm · i, as lattice_cloud places them; the
# same IEEE operations in Python) to 17 digits: the velocity_file route gives the same files.
/usr/bin/python3 -c "
print('x,y,z,vx,vy,vz')
for i in range(300, 400):
    x = 50e-6 * i
    print(f'{x!r},0,0,{1e3 * (x - 15e-3)!r},0,0')" > "$WORK/bar_velocity.csv"
formula='velocity_formula = ["1e3 * (x - 15e-3)"]'
bar_text=$(cat "$bar_case")
echo "${bar_text/"$formula"/velocity_file = \"$WORK/bar_velocity.csv\"}" > "$WORK/bar_file.toml"
"$SF" run "$WORK/bar_file.toml" --output "$WORK/bar_file" -q > /dev/null
same_files "$WORK/bar" "$WORK/bar_file" $bar_files
echo "ok: velocity_file gives the velocity_formula run bitwise"
expect_error "${bar_text/"$formula"/velocity_formula = [\"1e3 * (x - \"]}" "region[1].velocity_formula" "character 12" \
  "the text ends where a number"
expect_error "${bar_text/"$formula"/velocity_formula = [\"1e3 * t\"]}" "region[1].velocity_formula" "character 7" \
  "unknown name 't'"
expect_error "${bar_text/"$formula"/velocity_formula = [\"x\", \"0\"]}" "region[1].velocity_formula" "2 formulas (expected 1"
expect_error "${bar_text/"$formula"/velocity_formula = [\"sqrt(x - 0.0175)\"]}" "region[1].velocity_formula" \
  "is not finite" "at the point (0.015000000000000001, 0, 0) m"
expect_error "${bar_text/"$formula"/velocity_formula = [1.0]}" "region[1].velocity_formula"
expect_error "${bar_text/"$formula"/$formula
ramp_time = 1e-7}" "region[1].ramp_time" "only a prescribed_displacement"
expect_error "${bar_text/"$formula"/$formula
velocity = [1.0]}" "region[1]" "exactly one of velocity, velocity_formula"
expect_error "${bar_text/ramp_time = 2e-7/ramp_time = -1e-7}" "region[0].ramp_time"
expect_error "${bar_text/"body_force = [-1e12]"/body_force = [-1e12, 0.0]}" "region[2].body_force" "1 number"
expect_error "${bar_text/"prescribed_displacement = [1e-6]"/prescribed_displacement = [1e-6, 0.0]}" \
  "region[0].prescribed_displacement" "1 number"
expect_error "${bar_text/"$formula"/velocity_file = \"missing.csv\"}" "region[1].velocity_file" "missing.csv"
sed 's/^x,y,z,vx,vy,vz$/x,y,vx/' "$WORK/bar_velocity.csv" > "$WORK/bad_header.csv"
expect_error "${bar_text/"$formula"/velocity_file = \"$WORK/bad_header.csv\"}" "region[1].velocity_file" \
  "bad_header.csv:1" "expected the header 'x,y,z,vx,vy,vz'"
sed '3d' "$WORK/bar_velocity.csv" > "$WORK/skipped_row.csv"
expect_error "${bar_text/"$formula"/velocity_file = \"$WORK/skipped_row.csv\"}" "region[1].velocity_file" \
  "skipped_row.csv:3" "not that of the region's point 1"
head -n 50 "$WORK/bar_velocity.csv" > "$WORK/short.csv"
expect_error "${bar_text/"$formula"/velocity_file = \"$WORK/short.csv\"}" "region[1].velocity_file" \
  "49 velocity rows for the 100 points"
echo "ok: bad formulas, velocity files, displacements and ramps refused"
# A region held in x only (components): reported, its points at v_x = 20 m/s (the physics of the
# free components: tests/unit/pd/test_regions.cpp); bad component lists refused.
held_x="${plate/"prescribed_velocity = [20.0, 0.0]"/prescribed_velocity = [20.0, 0.0]
components = [\"x\"]}"
echo "$held_x" > "$WORK/held_x.toml"
"$SF" run "$WORK/held_x.toml" --output "$WORK/held_x" -q > /dev/null
grep -q "region 0: 60 points held at (20, 0, 0) m/s in x only (the other components free)" "$WORK/held_x/log.txt" ||
  fail "the held component is not reported: $(grep "region 0" "$WORK/held_x/log.txt")"
awk -F, 'NR > 1 && $1 <= 0.0025 { if ($4 != 4e-05 || $5 != 20) bad = bad " " $1 "," $2; n++ }
         END { if (bad != "" || n != 60) { print n " points, held wrongly:" bad; exit 1 } }' \
  "$WORK/held_x/profiles/profile_0.csv" || fail "the edge held in x did not move at 20 m/s"
expect_error "${held_x/"[\"x\"]"/[\"z\"]}" "region[0].components" "'z' (expected components of the 2D body: x, y)"
expect_error "${held_x/"[\"x\"]"/[\"x\", \"x\"]}" "region[0].components" "'x' given twice"
expect_error "${held_x/"[\"x\"]"/[]}" "region[0].components" "an empty list"
expect_error "${plate/"velocity = [0.0, -5.0]"/velocity = [0.0, -5.0]
components = [\"y\"]}" "region[1].components" "only a prescribed_velocity or prescribed_displacement"
echo "ok: a region held in x only; bad component lists refused"

# Point clouds from files: the bar's and the plate's lattice points (x = ΔX·i, volume ΔX^dim as
# lattice_cloud makes them; Python's float arithmetic and pow are the same IEEE operations) give
# the lattice runs bitwise, pre-crack, held edge and separate disc included.
/usr/bin/python3 -c "
for i in range(400):
    print(f'{50e-6 * i!r} 0 0 {pow(50e-6, 1)!r}')" > "$WORK/bar_cloud.txt"
/usr/bin/python3 -c "
print('# the 40 x 20 lattice of pd_plate_loading.toml, x fastest')
for j in range(20):
    for i in range(40):
        print(f'{1e-3 * i!r} {1e-3 * j!r} 0 {pow(1e-3, 2)!r}')" > "$WORK/plate_cloud.txt"
echo "${bar_text/"counts = [400]"/points_file = \"$WORK/bar_cloud.txt\"}" > "$WORK/bar_cloud.toml"
"$SF" run "$WORK/bar_cloud.toml" --output "$WORK/bar_cloud" -q > /dev/null
same_files "$WORK/bar" "$WORK/bar_cloud" $bar_files
echo "${plate/"counts = [40, 20]"/points_file = \"$WORK/plate_cloud.txt\"}" > "$WORK/plate_cloud.toml"
"$SF" run "$WORK/plate_cloud.toml" --output "$WORK/plate_cloud" -q > /dev/null
same_files "$WORK/plate" "$WORK/plate_cloud" series.csv profiles/profile_0.csv
grep -q "pre-cracks: 1 crack(s) cut 169 bonds (broken from step 0)" "$WORK/plate_cloud/log.txt" ||
  fail "the cloud plate's pre-crack differs: $(grep pre-cracks "$WORK/plate_cloud/log.txt")"
echo "ok: bar and plate from points_file run bitwise as their lattices"
# [body] origin: the plate's lattice moved by (0.25, -0.5) mm runs bitwise as a cloud of the moved
# points (origin + ΔX·i, the same IEEE operations), and origin beside points_file is refused.
/usr/bin/python3 -c "
for j in range(20):
    for i in range(40):
        print(f'{0.25e-3 + 1e-3 * i!r} {-0.5e-3 + 1e-3 * j!r} 0 {pow(1e-3, 2)!r}')" > "$WORK/moved_cloud.txt"
echo "${plate/"counts = [40, 20]"/counts = [40, 20]
origin = [0.25e-3, -0.5e-3]}" > "$WORK/moved_lattice.toml"
echo "${plate/"counts = [40, 20]"/points_file = \"$WORK/moved_cloud.txt\"}" > "$WORK/moved_cloud.toml"
"$SF" run "$WORK/moved_lattice.toml" --output "$WORK/moved_lattice" -q > /dev/null
"$SF" run "$WORK/moved_cloud.toml" --output "$WORK/moved_cloud" -q > /dev/null
same_files "$WORK/moved_lattice" "$WORK/moved_cloud" series.csv profiles/profile_0.csv
head -2 "$WORK/moved_lattice/profiles/profile_0.csv" | grep -q "^0.00025,-0.0005," || fail "the first point is not at the origin"
moved_cloud=$(cat "$WORK/moved_cloud.toml")
expect_error "${moved_cloud/dim = 2/dim = 2
origin = [0.0, 0.0]}" "body.origin" "not both"
echo "ok: a lattice moved by origin runs bitwise as the cloud of its points"
# Several point files, one body each ([[body.points]]): the plate without the disc and the disc as
# two files (no region makes the disc separate) give the lattice run with the disc a separate
# region. The points come in another order, so bond forces are summed in another order: the same
# to round-off (1e-9 of the largest value of each column; damage exactly).
/usr/bin/python3 -c "
plate, disc = open('$WORK/plate_part.txt', 'w'), open('$WORK/disc_part.txt', 'w')
for j in range(20):
    for i in range(40):
        x, y = 1e-3 * i, 1e-3 * j
        inside = (x - 33e-3) ** 2 + (y - 15e-3) ** 2 <= 2.5e-3 ** 2
        print(f'{x!r} {y!r} 0 {pow(1e-3, 2)!r}', file=disc if inside else plate)"
parts="${plate/"separate = true
"/}"
echo "${parts/"counts = [40, 20]"/}
[[body.points]]
file = \"$WORK/plate_part.txt\"

[[body.points]]
file = \"$WORK/disc_part.txt\"" > "$WORK/parts.toml"
"$SF" run "$WORK/parts.toml" --output "$WORK/parts" -q > /dev/null
grep -q "region 1: 21 points starting at (0, -5, 0) m/s$" "$WORK/parts/log.txt" || fail "the disc's region: $(grep "region 1" "$WORK/parts/log.txt")"
/usr/bin/python3 - "$WORK/plate/profiles/profile_0.csv" "$WORK/parts/profiles/profile_0.csv" <<'PY' || fail "the two-file plate differs from the lattice plate with a separate disc"
import sys
import numpy as np
a, b = (np.genfromtxt(f, delimiter=",", names=True) for f in sys.argv[1:])
a, b = (d[np.lexsort((d["y_m"], d["x_m"]))] for d in (a, b))
assert (a["x_m"] == b["x_m"]).all() and (a["y_m"] == b["y_m"]).all(), "different points"
assert (a["damage"] == b["damage"]).all(), "different damage"
for column in ("ux_m", "vx_m_s", "vy_m_s"):
    gap = np.abs(a[column] - b[column]).max() / np.abs(a[column]).max()
    assert gap <= 1e-9, f"{column} differs by {gap:.3g} of its largest value"
PY
two_bodies=$(cat "$WORK/parts.toml")
expect_error "${two_bodies/"dim = 2"/dim = 2
points_file = \"$WORK/plate_part.txt\"}" "body.points" "not both"
j2_parts="${two_bodies/model = \"lps\"/model = \"j2\"}"
j2_parts="${j2_parts/"bulk = 158e9
shear = 73e9
critical_stretch = 0.01"/young = 190e9
poisson = 0.3
yield_stress = 1e9}"
expect_error "$j2_parts" "body.points" "short-range contact force"
expect_error "${two_bodies/disc_part.txt/no_such_part.txt}" "body.points[1].file" "no_such_part.txt"
echo "ok: two point files run as two bodies"
cloud_bar=$(cat "$WORK/bar_cloud.toml")
expect_error "${cloud_bar/dim = 1/dim = 1
counts = [400]}" "body.counts" "not both"
{ cat "$WORK/bar_cloud.txt"; echo "5e-05 0 0 5e-05"; } > "$WORK/twice.txt"
expect_error "${cloud_bar/bar_cloud.txt/twice.txt}" "body.points_file" "points 1 and 400" "overlap"
{ cat "$WORK/bar_cloud.txt"; echo "0.05 0 0 5e-05"; } > "$WORK/isolated.txt"
expect_error "${cloud_bar/bar_cloud.txt/isolated.txt}" "body.horizon_factor" "point 400" "no neighbour within the horizon"
expect_error "${cloud_bar/horizon_factor = 3.015/horizon_factor = 0.5}" "body.horizon_factor" "smaller than the spacing"
sed '3s/.*/0.0001 0 0/' "$WORK/bar_cloud.txt" > "$WORK/short_line.txt"
expect_error "${cloud_bar/bar_cloud.txt/short_line.txt}" "body.points_file" "short_line.txt:3" "expected 'x y z volume'"
expect_error "${cloud_bar/bar_cloud.txt/no_such_cloud.txt}" "body.points_file" "no_such_cloud.txt"
expect_error "${cloud_bar/xlo = 15e-3/xlo = 25e-3}" "region[1].shape" "selects no point of the body (400 points within"
plate_cloud=$(cat "$WORK/plate_cloud.toml")
expect_error "$plate_cloud
[[region]]
shape = \"block\"
xlo = 30e-3
ylo = 12e-3
separate = true" "region[2].separate" "overlaps the separate body of region[1]"
echo "ok: bad point clouds refused"
echo "pd_loading: all cases passed"
