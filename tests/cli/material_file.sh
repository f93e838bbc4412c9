#!/usr/bin/env bash
# Material files (docs/materials.md): an MPM [[material]] and a PD [material] read `file = ...`
# relative to the case; the run's log and config.resolved.toml name the file, its SHA-256 and
# its provenance; a material file changed after the run started is refused on --resume; bad
# material files and cases missing what their model needs are refused naming the file and key.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
mkdir -p "$WORK/m"
# The library's aluminium written out as a material file (G = E/(2(1+ν)) = 69 GPa/2.66).
cat > "$WORK/m/al.toml" <<'EOF'
name = "al_file"
[eos]
rho0 = 2700.0
c0 = 5350.0
s = 1.34
gamma0 = 1.96
[elasticity]
shear = 25.93984962406015e9
[strength]
yield_stress = 120e6
tangent_modulus = 384e6
[thermal]
heat_capacity = 880.0
conductivity = 237.0
[provenance.hand]
command = "typed in from the library"
date = "2026-12-01"
EOF
mpm="$ROOT/tests/cli/cases/mpm_tiny.toml"
sed 's|library = "aluminium_seed000"|file = "m/al.toml"|' "$mpm" > "$WORK/file.toml"
"$SF" run "$WORK/file.toml" --output "$WORK/file" -q --stop-after 20 > /dev/null 2>&1 || [ $? -eq 130 ] || fail "stop"
"$SF" run "$WORK/file.toml" --output "$WORK/file" -q --resume > /dev/null
"$SF" run "$mpm" --output "$WORK/lib" -q > /dev/null
sha=$(sha256sum "$WORK/m/al.toml" | cut -d' ' -f1)
grep -qF "material file: 'al' from $WORK/m/al.toml (sha256 $sha)" "$WORK/file/log.txt" || fail "log lacks the material file"
grep -qF "provenance.hand.command = typed in from the library" "$WORK/file/log.txt" || fail "log lacks its provenance"
grep -qF "'material[0].file.sha256' = '$sha'" "$WORK/file/config.resolved.toml" || fail "resolved config lacks the hash"
grep -qF "'material[0].file.provenance.hand.date' = '2026-12-01'" "$WORK/file/config.resolved.toml" \
  || fail "resolved config lacks the provenance"
grep -qF "file = '$WORK/m/al.toml'" "$WORK/file/config.resolved.toml" || fail "resolved config lacks the path"
grep -q "^c0 = 5350" "$WORK/file/config.resolved.toml" || fail "resolved config lacks the file's values"
# The same numbers as the library material: the same run (final series row to 8 digits; the
# resumed run is bit-identical to a straight one, stop_resume.sh).
python3 - "$WORK/file/series.csv" "$WORK/lib/series.csv" <<'EOF' || fail "file and library runs differ"
import sys
a, b = ([float(v) for v in open(f).read().split("\n")[-2].split(",")] for f in sys.argv[1:])
assert all(abs(x - y) <= 1e-8 * max(1.0, abs(y)) for x, y in zip(a, b)), (a, b)
EOF
# The material file changed after the run started: --resume refuses (exit 2) and names it.
"$SF" run "$WORK/file.toml" --output "$WORK/chg" -q --stop-after 5 > /dev/null 2>&1 || true
sed -i 's/c0 = 5350.0/c0 = 5360.0/' "$WORK/m/al.toml"
set +e
"$SF" run "$WORK/file.toml" --output "$WORK/chg" -q --resume > /dev/null 2> "$WORK/resume.txt"
code=$?
set -e
[ $code -eq 2 ] || fail "resume after a material change: exit $code"
grep -qF "input file $WORK/m/al.toml changed since the run started" "$WORK/resume.txt" || fail "$(cat "$WORK/resume.txt")"
sed -i 's/c0 = 5360.0/c0 = 5350.0/' "$WORK/m/al.toml"
echo "ok: material file used, logged, resolved; change detected on --resume"

# Bad material files and cases: each refused with the file and the key.
case_with() {  # case_with MATERIAL_TEXT: the MPM case on a material file with this text
  printf '%s\n' "$1" > "$WORK/m/bad.toml"
  sed 's|library = "aluminium_seed000"|file = "'"$WORK"'/m/bad.toml"|' "$mpm"
}
good=$(cat "$WORK/m/al.toml")
expect_error "$(case_with "${good/yield_stress = 120e6/}")" "bad.toml: missing strength.yield_stress" \
  "material[0].yield_stress"
expect_error "$(case_with "${good/c0 = 5350.0/c0 = 5350.0
c0_typo = 1}")" "bad.toml: unknown key 'eos.c0_typo'"
expect_error "$(case_with "${good/c0 = 5350.0/c0 = -1.0}")" "bad.toml:4: key 'eos.c0': expected a number > 0"
expect_error "$(case_with "${good/c0 = 5350.0/c0 = nan}")" "key 'eos.c0'"
expect_error "$(case_with "${good/s = 1.34/s = 1.34
s2 = 1e-4}")" "eos.s2" "linear"
expect_error "$(case_with "${good/shear = 25.93984962406015e9/c11 = 100e9}")" "bad.toml" "'elasticity.c12'" \
  "come together"
expect_error "$(case_with "${good/shear = 25.93984962406015e9/c11 = 100e9
c12 = 120e9
c44 = 50e9}")" "'elasticity.c12'" "not a stable cubic crystal"
expect_error "$(case_with "${good/shear = 25.93984962406015e9/bulk = 70e9}")" "missing elasticity.shear" "young and poisson"
expect_error "$(case_with "$good
[derived]
x = 1")" "bad.toml" "no [derived]"
expect_error "$(sed 's|library = "aluminium_seed000"|library = "aluminium_seed000"\nfile = "m/al.toml"|' "$mpm")" \
  "material[0].library" "not both"
expect_error "$(sed 's|library = "aluminium_seed000"|file = "m/none.toml"|' "$mpm")" "material[0].file" "not found"

# PD: the crystal takes density and C11, C12, C44 from the file; the file must have them.
cat > "$WORK/m/cu.toml" <<'EOF'
[elasticity]
density = 8930.0
c11 = 170e9
c12 = 124e9
c44 = 75e9
EOF
pd=$(sed -e 's|model = "j2"|model = "crystal"\nfile = "'"$WORK"'/m/cu.toml"|' -e '/^density\|^young\|^poisson\|^yield_stress/d' \
  "$ROOT/tests/cli/cases/pd_tiny.toml")
printf '%s\n' "$pd" > "$WORK/pd.toml"
"$SF" run "$WORK/pd.toml" --output "$WORK/pd" -q > /dev/null
grep -q "^c11 = 1.7e+11$" "$WORK/pd/config.resolved.toml" || fail "PD did not take c11 from the file"
grep -q "^density = 8930" "$WORK/pd/config.resolved.toml" || fail "PD did not take the density from the file"
grep -qF "material file: $WORK/m/cu.toml" "$WORK/pd/log.txt" || fail "PD log lacks the material file"
sed -i '/^c1\|^c44/d' "$WORK/m/cu.toml"
expect_error "$pd" "cu.toml: missing elasticity.c11" 'model = "crystal"'
# A material file's value is checked against the range of the case key it stands for (issue 14):
# a negative density is refused by the file's own ranges (MPM, file and key); a yield stress of
# 0 is a valid strength.yield_stress but PD's j2 yield_stress must be > 0, so the PD case refuses
# it naming the file, its key, the case key and the range (it ran with a zero yield stress before).
expect_error "$(case_with "${good/rho0 = 2700.0/rho0 = -2700.0}")" "bad.toml" "key 'eos.rho0'" "expected a number > 0"
cat > "$WORK/m/j2.toml" <<'EOF'
[eos]
rho0 = 7800.0
[elasticity]
bulk = 160e9
shear = 80e9
[strength]
yield_stress = 0.0
EOF
pdj2=$(sed -e 's|model = "j2"|model = "j2"\nfile = "'"$WORK"'/m/j2.toml"|' -e '/^density\|^young\|^poisson\|^yield_stress/d' \
  "$ROOT/tests/cli/cases/pd_tiny.toml")
expect_error "$pdj2" "j2.toml: key 'strength.yield_stress' = 0 gives material.yield_stress = 0, expected > 0"
echo "material_file: ok"
