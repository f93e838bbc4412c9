#!/usr/bin/env bash
# The docs are not stale (tests/cli/docs_current.py): every `shockfield SUB --flag` they quote is in
# that subcommand's --help, every key of their key tables is read by name in src/shockfield; and
# every repository path and Python name (shockfield.x.y) they quote exists; and the check fails on a planted stale sentence of each
# kind (a flag the command lacks, a flag of another subcommand, a key nobody reads, a file that is
# not there, a Python module that is not there).
source "$(dirname "$0")/lib.bash"
set -e
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
if check "$WORK/stale.md" > "$WORK/report.txt"; then fail "the check passed a stale page: $(cat "$WORK/report.txt")"; fi
for p in "stale.md:1: \`shockfield analyze stats\` has no --histogram-bins" \
  "stale.md:3: \`shockfield analyze minkowski\` has no --reference-threshold" \
  "stale.md:10: key \`cell_sizing_rule\` of a key table is read nowhere" \
  "stale.md:12: path \`src/shockfield/analysis/grid_reader.cpp\` does not exist" \
  "stale.md:13: Python name \`shockfield_plot.vtk_arrays\` does not exist"; do
  grep -qF -- "$p" "$WORK/report.txt" || fail "not reported: $p ($(cat "$WORK/report.txt"))"
done
[ "$(wc -l < "$WORK/report.txt")" -eq 5 ] || fail "more than the five planted problems: $(cat "$WORK/report.txt")"
echo "docs_current: ok"
