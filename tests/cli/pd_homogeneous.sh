#!/usr/bin/env bash
# `method = "pd"` with [homogeneous]: Taylor compression of 10 random grains along eq. 44 writes
# stress_strain.csv (Taylor axial stress = mean of the grains' eq.-45 stresses in grains.csv),
# grain_summary.csv and the same numbers with 1 and 2 threads; bad [homogeneous] input is refused
# with file, key and expectation.
source "$(dirname "$0")/lib.bash"
set -e
case_text='method = "pd"
[material]
model = "crystal"
density = 8960.0
orientation = "random"
taylor_grains = 10
seed = 3
[homogeneous]
strain_rate = -0.01
end_strain = -0.05
strain_increment = 5e-4
output_increment = 0.01'
printf '%s\n' "$case_text" > "$WORK/case.toml"
"$SF" run "$WORK/case.toml" --output "$WORK/one" -q -j 1 > /dev/null
"$SF" run "$WORK/case.toml" --output "$WORK/two" -q -j 2 > /dev/null
for f in stress_strain.csv grains.csv grain_summary.csv config.resolved.toml log.txt; do
  [ -s "$WORK/one/$f" ] || fail "missing $f"
done
cmp "$WORK/one/grains.csv" "$WORK/two/grains.csv" || fail "grain stresses depend on the thread count"
[ "$(wc -l < "$WORK/one/stress_strain.csv")" -eq 7 ] || fail "expected 6 rows (ε = 0, -0.01 .. -0.05)"
[ "$(head -1 "$WORK/one/grains.csv" | tr ',' '\n' | wc -l)" -eq 11 ] || fail "grains.csv: strain + 10 grains"
[ "$(wc -l < "$WORK/one/grain_summary.csv")" -eq 11 ] || fail "grain_summary.csv: 10 grains"
grep -q '^grains = 10' "$WORK/one/config.resolved.toml" || fail "derived grain count"
# The Taylor column is the mean of the grain columns (eq. 43; both printed to ~10 digits), and
# at ε = -0.05 the aggregate flows in compression above the Taylor estimate 3.06·g0 = 49 MPa.
paste -d, <(tail -n +2 "$WORK/one/stress_strain.csv") <(tail -n +2 "$WORK/one/grains.csv") | awk -F, '
  { s = 0; for (i = 9; i <= 18; ++i) s += $i; m = s / 10
    if ($3 == 0 && m == 0) next
    if ((m - $3) ^ 2 > (1e-8 * $3) ^ 2) { print "row " NR ": taylor " $3 " vs grain mean " m; bad = 1 } }
  END { if (bad) exit 1; if (-$3 < 49e6) { print "final Taylor stress " $3; exit 1 } }' || fail "Taylor average"
echo "ok: homogeneous run, $(tail -1 "$WORK/one/log.txt" | head -c 160)"

# With a material file (g0 from a bridge): log.txt and config.resolved.toml name the file, its
# SHA-256 and its provenance, as every run that uses a material file does (docs/materials.md).
printf '[elasticity]\ndensity = 8960.0\nc11 = 168.4e9\nc12 = 121.4e9\nc44 = 75.4e9\n[strength]\ng0 = 20e6\n[provenance.yield]\ncommand = "shockfield bridge yield runs/x"\n' > "$WORK/cu.toml"
printf '%s\n' "${case_text/density = 8960.0/file = \"cu.toml\"}" > "$WORK/file_case.toml"
"$SF" run "$WORK/file_case.toml" --output "$WORK/file" -q -j 1 > /dev/null
sha=$(sha256sum "$WORK/cu.toml" | cut -d' ' -f1)
grep -qF "material file: $WORK/cu.toml (sha256 $sha)" "$WORK/file/log.txt" || fail "log.txt lacks the material file and hash"
grep -qF 'material file: provenance.yield.command = shockfield bridge yield runs/x' "$WORK/file/log.txt" \
  || fail "log.txt lacks the material file's provenance"
grep -qF "$sha" "$WORK/file/config.resolved.toml" || fail "config.resolved.toml lacks the material file's hash"
grep -q "^g0 = 2e+07$" "$WORK/file/config.resolved.toml" || fail "g0 not taken from the material file"
echo "ok: homogeneous run names its material file"

expect_error "${case_text/end_strain = -0.05/end_strain = 0.05}" "homogeneous.end_strain" "sign of strain_rate"
expect_error "${case_text/strain_increment = 5e-4/strain_increment = 0.1}" "homogeneous.strain_increment"
expect_error "${case_text/output_increment = 0.01/output_increment = 0.01
speed = 3.0}" "unknown key" "homogeneous.speed"
expect_error "${case_text/model = \"crystal\"/model = \"j2\"}" "material.model" "model = \"crystal\""
expect_error "${case_text/orientation = \"random\"/orientation = \"random_grains\"}" "material.taylor_grains" "random_grains"
expect_error "${case_text/taylor_grains = 10/taylor_grains = 0}" "material.taylor_grains"
printf '%s\n' "$case_text" > "$WORK/case.toml"
set +e
"$SF" run "$WORK/case.toml" --output "$WORK/one" --resume -q 2> "$WORK/stderr"
code=$?
set -e
[ $code -eq 2 ] && grep -qF "keeps no checkpoint" "$WORK/stderr" || fail "--resume of a homogeneous run: $code $(cat "$WORK/stderr")"
echo "pd_homogeneous: all checks passed"
