#!/usr/bin/env bash
# pair_style table in a case file: the tiny Cu case on the Morse table M11 of the LAMMPS
# cross-check runs; a missing section, a cutoff beyond the table and a bitmap table are refused
# before the run (exit 2) naming the case file's key and the table file; a pair closer than the
# table's inner distance stops the run (exit 3) naming the atoms.
source "$(dirname "$0")/lib.bash"
set -e
table="$ROOT/tests/fixtures/lammps_table/pair.table"
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/tiny_cu.toml")
base=${base/elements = \[\"Cu\"\]/masses = [63.55]}
case=${base/style = \"eam\"
file = \"Cu_u3.eam\"/style = \"table\"
interpolation = \"spline\"
points = 1000
file = \"$table\"
keyword = \"M11\"}

run_expecting 0 "$case"
grep -q "input file: .*pair.table" "$WORK/out/log.txt" || fail "the table file is not in the run's provenance"
[ "$(wc -l < "$WORK/out/thermo.csv")" -gt 10 ] || fail "no thermo rows"
expect_error "${case/keyword = \"M11\"/keyword = \"M99\"}" "case.toml" "potential.keyword" \
  "no table section 'M99'" "M11, M22, M12"
expect_error "${case/keyword = \"M11\"/keyword = \"M11\"
cutoff = 7.5}" "potential.cutoff" "outside the table" "pair.table section M11"
sed 's/^N 500 FPRIME .*$/N 512 BITMAP 1.5 7.0/' "$table" > "$WORK/bitmap.table"
expect_error "${case/$table/$WORK/bitmap.table}" "bitmap.table:" "BITMAP tables"
# Compressed to a0 = 2.0 Å (nearest neighbours 1.41 Å), below M11's inner 1.5 Å.
run_expecting 3 "${case/a0 = 3.615/a0 = 2.0}" "pair style table" "outside the table" "section M11"
echo "md_table: ok"
