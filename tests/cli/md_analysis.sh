#!/usr/bin/env bash
# The in-run [analysis] table of an MD case (tests/cli/cases/tiny_cu_analysis.toml: 4x4x4 Cu at
# 1400 K, a-CNA, CNA, CSP, coordination and diamond every 25 steps, their columns in the dumps every 50):
# structures.csv has a row per analysis step, and at the dump steps its counts and fractions are
# exactly those `shockfield analyze atoms` finds on the run's own dumps (full precision: the same
# atoms), and the dumps' per-atom columns are exactly what analyze atoms appends (the annotated
# dump is byte-identical to the run's). Then bad [analysis] tables, refused by key.
source "$(dirname "$0")/lib.bash"
set -e
case_file="$ROOT/tests/cli/cases/tiny_cu_analysis.toml"
"$SF" run "$case_file" --output "$WORK/run" -q > /dev/null
s="$WORK/run/structures.csv"
[ "$(wc -l < "$s")" -eq 14 ] || fail "structures.csv: $(wc -l < "$s") lines, expected a header and 13 rows (steps 0, 25, ..., 300)"
head -1 "$s" | grep -q "^step,time_ps,atoms,cna_fcc,.*,acna_other_fraction,dia_cubic,.*,dia_other_fraction$" || fail "header: $(head -1 "$s")"
awk -F, 'NR > 1 && ($1 != (NR - 2) * 25 || $3 != 256) { exit 1 }' "$s" || fail "steps: $(cut -d, -f1-3 "$s")"
awk -F, 'NR > 1 && $4 < 256 { hot++ } END { exit !hot }' "$s" || fail "no frame with non-fcc CNA atoms at 1400 K: the test would not see a difference"

"$SF" analyze atoms "$WORK/run" --cna 3.0858 --adaptive-cna --csp 12 --coordination 3.0858 --diamond -o "$WORK/a" > /dev/null
awk -F, 'NR > 1 && $1 % 50 == 0' "$s" | cut -d, -f3- > "$WORK/inrun"
awk -F, 'NR > 1' "$WORK/a/structures.csv" | cut -d, -f3- > "$WORK/post"
[ "$(wc -l < "$WORK/post")" -eq 7 ] || fail "analyze atoms read $(wc -l < "$WORK/post") frames, expected 7"
cmp "$WORK/inrun" "$WORK/post" || fail "in-run fractions differ from analyze atoms on the dumps: $(diff "$WORK/inrun" "$WORK/post" | head -5)"
echo "ok: in-run structures.csv = analyze atoms on the run's 7 dumps ($(awk -F, 'NR > 1 { printf "%s ", $4 }' "$WORK/a/structures.csv")fcc by CNA)"
for f in "$WORK"/run/dumps/*.lammpstrj; do
  grep -q "^ITEM: ATOMS id type x y z vx vy vz coord cna acna csp dia$" "$f" || fail "$f columns: $(sed -n 9p "$f")"
  cmp "$f" "$WORK/a/$(basename "$f")" || fail "$(basename "$f"): the run's columns differ from analyze atoms'"
done
echo "ok: the dumps' coord cna acna csp dia columns = analyze atoms', byte for byte"

# Bad tables: exit 2 before anything runs, the key named.
base=$(cat "$case_file")
expect_error "${base/methods = \[\"acna\", \"cna\", \"csp\", \"coordination\", \"diamond\"\]/methods = [\"acna\", \"wurtzite\"]}" "analysis.methods" 'got "wurtzite"'
expect_error "${base/cutoff = 3.0858/}" "analysis.cutoff"
expect_error "${base/every = 25/every = 0}" "analysis.every"
expect_error "${base/dump_every = 50/dump_every = 0}" "analysis.dump_columns" "dump_every > 0"
expect_error "${base/dump_columns = true/csp_neighbors = 7}" "analysis.csp_neighbors" "even"
expect_error "${base/dump_columns = true/dump_columns = true
coordinates = 1}" "analysis.coordinates"
echo "all md analysis checks passed"
