#!/usr/bin/env bash
# VTK output in every encoding and precision ([output] vtk_encoding, vtk_precision), read back by
# VTK itself (python3-vtk9), by shockfield_plot.vtk_arrays and by `shockfield analyze`: the same
# values in each (Float32: the nearest float), units on every array; for MPM (grid .vti and
# particle .vtp), DBM, phase field and the macroscopic particles. Skips the VTK part with a
# message when python3-vtk9 is absent (scripts/install-deps.sh installs it).
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
PY=/usr/bin/python3
check() {  # check REFERENCE FILE...: exit 77 of the script is a skip
  set +e
  "$PY" "$ROOT/tests/cli/vtk_round_trip.py" "$@" > "$WORK/check.txt" 2>&1
  local code=$?
  set -e
  [ $code -eq 0 ] || [ $code -eq 77 ] || fail "$(cat "$WORK/check.txt")"
  cat "$WORK/check.txt"
}
# run_formats NAME CASE_FILE: the case once per encoding/precision, into $WORK/NAME_<enc>_<prec>.
run_formats() {
  local name="$1" case_file="$2"
  for format in ascii:float64 base64:float32 raw:float64 zlib:float32; do
    local enc=${format%:*} prec=${format#*:}
    sed "s/^\[output\]/[output]\nvtk_encoding = \"$enc\"\nvtk_precision = \"$prec\"/" "$case_file" > "$WORK/$name.toml"
    "$SF" run "$WORK/$name.toml" --output "$WORK/${name}_${enc}" -q > /dev/null
  done
}
variants() {  # variants NAME RELATIVE_FILE: the file of each format, the reference first
  for enc in ascii base64 raw zlib; do echo "$WORK/${1}_${enc}/$2"; done
}

run_formats mpm "$ROOT/tests/cli/cases/mpm_tiny.toml"
check $(variants mpm "fields/$(ls "$WORK/mpm_ascii/fields" | grep vti | tail -1)")
check $(variants mpm "fields/$(ls "$WORK/mpm_ascii/fields" | grep vtp | tail -1)")
# shockfield analyze reads the compressed single-precision grid as the ascii one (to float precision).
for enc in ascii zlib; do
  "$SF" analyze stats "$WORK/mpm_${enc}/fields/grid_000000066.vti" --array pressure -o "$WORK/stats_$enc" --no-plot > /dev/null
done
"$PY" - "$WORK/stats_ascii" "$WORK/stats_zlib" <<'PYEOF' || fail "analyze stats of the zlib Float32 grid differ from ascii"
import csv, sys
rows = [list(csv.DictReader(open(f"{d}/stats.csv")))[0] for d in sys.argv[1:]]
assert rows[0]["void_cells"] == rows[1]["void_cells"], "void cells differ"
for key in ("mean", "std", "skewness"):
    a, b = float(rows[0][key]), float(rows[1][key])
    assert abs(a - b) <= 1e-6 * max(abs(a), 1.0), (key, a, b)  # Float32: 6e-8 relative per value
print("ok: analyze stats agree")
PYEOF

run_formats dbm "$ROOT/tests/cli/cases/dbm_sod.toml"
check $(variants dbm fields/grid_000000040.vti)
run_formats phasefield "$ROOT/tests/cli/cases/phasefield_tiny.toml"
check $(variants phasefield fields/xi_3.vti)
echo "vtk_round_trip: mpm, dbm and phasefield VTK files read alike by VTK, vtk_arrays and analyze in every format"
