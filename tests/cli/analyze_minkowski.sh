#!/usr/bin/env bash
# `shockfield analyze minkowski` on small fixture fields (tests/fixtures/analysis/fields): the
# CSV holds the known functionals, a PNG is written; series (.pvd), binary VTK image data and a
# single-layer grid taken as 3D.
source "$(dirname "$0")/lib.bash"
set -e
F="$ROOT/tests/fixtures/analysis/fields"
png() { [ "$(head -c 4 "$1" | tail -c 3)" = "PNG" ] || fail "$1 is not a PNG"; }
# column NAME FILE ROW: value of column NAME in data row ROW (1 = first after the header).
column() {
  awk -F, -v name="$1" -v row="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i }
    NR == row + 1 { print $c }' "$2"
}
near() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; exit !(d <= tol && -d <= tol) }' ||
  fail "$4: $1, expected $2 ± $3"; }

# Two hot disks of 69 cells (radius 5) in a 32 x 24 field at 300 K, disks at 400 K; periodic.
"$SF" analyze minkowski "$F/two_disks.csv" -t 250,350,450 -o "$WORK/disks" > "$WORK/out.txt"
csv="$WORK/disks/minkowski.csv"
# The fixture names no unit: every column with one says `unknown` (docs/conventions.md).
[ "$(head -1 "$csv")" = "file,time_unknown,threshold_unknown,A,L_unknown,chi,chi_per_black" ] ||
  fail "header: $(head -1 "$csv")"
[ "$(wc -l < "$csv")" -eq 4 ] || fail "expected 3 rows: $(cat "$csv")"
near "$(column A "$csv" 1)" 1 0 "A below every value"
near "$(column L_unknown "$csv" 1)" 0 0 "L of an all-white torus"
[ "$(column chi "$csv" 1)" = 0 ] || fail "chi of an all-white torus"
near "$(column A "$csv" 2)" 0.1796875 1e-9 "A of the disks (138 of 768 cells)"
# Two circles of the digitised disks' area (69 cells: r = 4.69): 2 x 2 sqrt(69 pi) = 58.9.
near "$(column L_unknown "$csv" 2)" 58.9 3 "L of two disks (Crofton estimate within 5 %)"
[ "$(column chi "$csv" 2)" = 2 ] || fail "chi of two disks: $(column chi "$csv" 2)"
near "$(column chi_per_black "$csv" 2)" "$(awk 'BEGIN { printf "%.12g", 2 / 630 }')" 1e-9 "chi / black cells"
near "$(column A "$csv" 3)" 0 0 "A above every value"
png "$WORK/disks/minkowski.png"
grep -q "wrote .*minkowski.png" "$WORK/out.txt" || fail "no 'wrote' line for the PNG"
# 4-connectivity and the open boundary give the same chi for separated disks.
"$SF" analyze minkowski "$F/two_disks.csv" -t 350 --connectivity 4 --boundary open --no-plot \
  -o "$WORK/disks4" > /dev/null
[ "$(column chi "$WORK/disks4/minkowski.csv" 1)" = 2 ] || fail "chi with 4-connectivity"
[ ! -e "$WORK/disks4/minkowski.png" ] || fail "--no-plot wrote a PNG"

# A .pvd series: its fields in time order, at its times; raw appended / base64 binary data.
"$SF" analyze minkowski "$F/series.pvd" -t 50 --no-plot -o "$WORK/series" > /dev/null
csv="$WORK/series/minkowski.csv"
[ "$(column time_unknown "$csv" 1),$(column time_unknown "$csv" 2)" = "0.25,0.5" ] || fail "series times: $(cat "$csv")"
[ "$(column V "$csv" 1)" = "$(column V "$csv" 2)" ] || fail "the two series fields differ"
# A run folder: its one .pvd of image data (here series.pvd) stands for its fields.
"$SF" analyze minkowski "$F" -t 50 --no-plot -o "$WORK/folder" > /dev/null
cmp -s <(cut -d, -f2- "$csv") <(cut -d, -f2- "$WORK/folder/minkowski.csv") ||
  fail "the folder gave other rows than its .pvd"
"$SF" analyze minkowski "$F/raw.vti" "$F/binary.vti" --array T -t 50 --times 1,2 --no-plot \
  -o "$WORK/binary" > /dev/null
v=$(awk 'BEGIN { printf "%.12g", 11 / 24 }')  # z = 1 is above 50 but for the void (or 0) cell
near "$(column V "$WORK/binary/minkowski.csv" 1)" "$v" 1e-9 "V of raw.vti above 50"
near "$(column V "$WORK/binary/minkowski.csv" 2)" "$v" 1e-9 "V of binary.vti above 50"

# A single z layer taken as 3D: one hot voxel is a unit cube (chi = 1, V = 1/12, 3D columns).
printf '0,0,0,0\n0,1,0,0\n0,0,0,0\n' > "$WORK/layer.csv"
"$SF" analyze minkowski "$WORK/layer.csv" --dimension 3 --boundary open -t 0.5 --no-plot \
  -o "$WORK/layer" > /dev/null
csv="$WORK/layer/minkowski.csv"
[ "$(head -1 "$csv")" = "file,time_unknown,threshold_unknown,V,S_unknown,b_unknown,M_unknown,chi,chi_per_black" ] ||
  fail "3D header: $(head -1 "$csv")"
# A grid that names its units (`# units`, `# length_units`) and --time-units: the 3D columns in them.
{ echo "# units = K"; echo "# length_units = m"; cat "$WORK/layer.csv"; } > "$WORK/layer_K.csv"
"$SF" analyze minkowski "$WORK/layer_K.csv" --dimension 3 --boundary open -t 0.5 --times 2e-9 --time-units s \
  --no-plot -o "$WORK/layer_K" > /dev/null
[ "$(head -1 "$WORK/layer_K/minkowski.csv")" = "file,time_s,threshold_K,V,S_m2,b_m,M_m,chi,chi_per_black" ] ||
  fail "3D header in units: $(head -1 "$WORK/layer_K/minkowski.csv")"
# Fields of one analysis in different units are refused (a column names one unit).
if "$SF" analyze minkowski "$WORK/layer_K.csv" "$WORK/layer.csv" -t 0.5 --no-plot -o "$WORK/mixed" \
  > /dev/null 2> "$WORK/mixed.txt"; then fail "fields in K and without units were analysed together"; fi
grep -q "units '' but .*layer_K.csv has 'K'" "$WORK/mixed.txt" || fail "mixed units: $(cat "$WORK/mixed.txt")"
[ "$(column chi "$csv" 1)" = 1 ] || fail "chi of one voxel"
near "$(column V "$csv" 1)" "$(awk 'BEGIN { printf "%.12g", 1 / 12 }')" 1e-9 "V of one voxel in 12"

# -n spreads its thresholds over the values of all the fields: a uniform first frame (a shock run
# before the shock) must not squeeze them into its round-off (300 - 2e-13 ... 300).
awk 'NR == 1 { print; next } { gsub(/400/, "300"); print }' "$F/two_disks.csv" > "$WORK/uniform.csv"
"$SF" analyze minkowski "$WORK/uniform.csv" "$F/two_disks.csv" --times 0,1 -n 5 --no-plot \
  -o "$WORK/range" > /dev/null
csv="$WORK/range/minkowski.csv"
near "$(column threshold_unknown "$csv" 1)" 300 0 "lowest threshold over both fields"
near "$(column threshold_unknown "$csv" 5)" 400 0 "highest threshold over both fields"
near "$(column threshold_unknown "$csv" 3)" 350 1e-9 "middle threshold"
echo "analyze_minkowski: ok"
