#!/usr/bin/env bash
# The docs are not stale (tests/cli/docs_current.py): every `shockfield SUB --flag` they quote is in
# that subcommand's --help, every key of a method's key tables is read in that section by its case
# readers (of other pages: by name somewhere in src/shockfield); every repository path and Python
# name (shockfield.x.y) they quote exists; every quoted-value marker follows a number and names an
# example (the values themselves: docs_values.sh); every example has a README, a run.sh and a picture. The check fails on a planted stale sentence of
# each kind (a flag the command lacks, a flag of another subcommand, a key nobody reads, a key of
# another section, a key of another method, a file that is not there, a Python module that is not
# there).
source "$(dirname "$0")/lib.bash"
set -e
export DOCS_CURRENT_KEYS_CACHE="$WORK/case_keys.json"  # the planted run reuses the first run's case keys
check() { /usr/bin/python3 "$ROOT/tests/cli/docs_current.py" "$SF" "$ROOT" "$@"; }
check || fail "the docs quote flags or keys that no longer exist (above)"
cat > "$WORK/stale.md" <<'DOC'
Run the analysis with `shockfield analyze stats fields/ --bins 8 --histogram-bins 8 -o out`, then
```
shockfield analyze minkowski fields/ -n 8 \
    --reference-threshold 350 -o out
```
### `[grid]`
| key | meaning | default |
|---|---|---|
| `cell_size` | cell size [m] | required |
| `cell_sizing_rule` | a key no reader reads | 1 |

The reader is `src/shockfield/analysis/field_reader` (`src/shockfield/analysis/grid_reader.cpp` before).
Python reads them with `shockfield.vtk_arrays.read_vtk_arrays`, not `shockfield_plot.vtk_arrays`.
DOC
# A page of the MPM method (named like docs/mpm.md): its keys are checked per section. `courant` is
# an MPM key of [solver], not [output]; `dump_every` an MD key; `field_interval` and the [[stage]]
# sub-table's `q` (paragraph heading, an msst key on an MD page below) are where they belong.
mkdir -p "$WORK/pages"
cat > "$WORK/pages/mpm.md" <<'DOC'
### `[output]`
| key | meaning | default |
|---|---|---|
| `field_interval` | fields every … s | 0 |
| `courant` | a [solver] key under [output] | 0.3 |
| `dump_every` | an MD key on the MPM page | 0 |
DOC
cat > "$WORK/pages/md.md" <<'DOC'
### `[[stage]]`
`[stage.msst]` (with `ensemble = "msst"`):

| key | meaning | default |
|---|---|---|
| `q` | cell mass-like parameter | 10 |
| `cell_size` | an MPM [grid] key under an MD stage | required |
DOC
if check "$WORK/stale.md" "$WORK/pages/mpm.md" "$WORK/pages/md.md" > "$WORK/report.txt"; then
  fail "the check passed a stale page: $(cat "$WORK/report.txt")"
fi
reports_planted "$WORK/report.txt" 8 \
  "stale.md:1: \`shockfield analyze stats\` has no --histogram-bins" \
  "stale.md:3: \`shockfield analyze minkowski\` has no --reference-threshold" \
  "stale.md:10: key \`cell_sizing_rule\` of a key table is read nowhere" \
  "stale.md:12: path \`src/shockfield/analysis/grid_reader.cpp\` does not exist" \
  "stale.md:13: Python name \`shockfield_plot.vtk_arrays\` does not exist" \
  "mpm.md:5: key \`courant\` is not read in [output] of a mpm case" \
  "mpm.md:6: key \`dump_every\` is not read in [output] of a mpm case" \
  "md.md:7: key \`cell_size\` is not read in [stage.msst] of a md case"
# An example without a run.sh and a picture, in a tree of its own.
mkdir -p "$WORK/tree/examples/bare" "$WORK/tree/examples/whole" "$WORK/tree/src/shockfield"
touch "$WORK/tree/examples/bare/README.md" "$WORK/tree/examples/whole/"{README.md,run.sh,picture.png} "$WORK/empty.md"
if /usr/bin/python3 "$ROOT/tests/cli/docs_current.py" "$SF" "$WORK/tree" "$WORK/empty.md" > "$WORK/report.txt"; then
  fail "the check passed an example without run.sh and picture"
fi
reports_planted "$WORK/report.txt" 2 "examples/bare: run.sh missing" "examples/bare: a picture (.png) missing"
echo "docs_current: ok"
