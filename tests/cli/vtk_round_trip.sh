#!/usr/bin/env bash
# VTK output in every encoding and precision ([output] vtk_encoding, vtk_precision), read back by
# VTK itself (python3-vtk9), by shockfield.vtk_arrays and by `shockfield analyze`: the same
# values in each (Float32: the nearest float), units on every array; for MPM (grid .vti and
# particle .vtp), DBM, phase field, PD points and granular grains. Skips the VTK part with a
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
for key in ("mean_Pa", "std_Pa", "skewness"):  # the grid's pressure array says units="Pa"
    a, b = float(rows[0][key]), float(rows[1][key])
    assert abs(a - b) <= 1e-6 * max(abs(a), 1.0), (key, a, b)  # Float32: 6e-8 relative per value
print("ok: analyze stats agree")
PYEOF

run_formats dbm "$ROOT/tests/cli/cases/dbm_sod.toml"
check $(variants dbm fields/grid_000000040.vti)
# DBM's values are cell-centred: cell data, one tuple per lattice cell, on the corner extent.
"$PY" - "$WORK/dbm_zlib/fields/grid_000000040.vti" <<'PYEOF' || fail "DBM frames are not cell data on the corner extent"
import sys
try:
    import vtk
except ImportError:
    sys.exit(0)  # python3-vtk9 absent: the check above already said it skipped
r = vtk.vtkXMLImageDataReader()
r.SetFileName(sys.argv[1])
r.Update()
image = r.GetOutput()
rho = image.GetCellData().GetArray("rho")
assert rho is not None and image.GetPointData().GetArray("rho") is None
assert rho.GetNumberOfTuples() == image.GetNumberOfCells(), (rho.GetNumberOfTuples(), image.GetNumberOfCells())
PYEOF
run_formats phasefield "$ROOT/tests/cli/cases/phasefield_tiny.toml"
check $(variants phasefield fields/xi_3.vti)
# PD points: each profile is also a .vtp at the deformed positions, with the profile's values.
run_formats pd "$ROOT/tests/cli/cases/pd_tiny.toml"
check $(variants pd profiles/points_4.vtp)
grep -q 'file="points_4.vtp"' "$WORK/pd_zlib/profiles/points.pvd" || fail "points.pvd does not index points_4.vtp"
"$PY" - "$WORK/pd_ascii/profiles" "$ROOT/python" <<'PYEOF' || fail "PD points_4.vtp differs from profile_4.csv"
import sys
import numpy as np
sys.path.insert(0, sys.argv[2])
from shockfield.vtk_arrays import read_vtk_arrays
folder = sys.argv[1]
csv = np.genfromtxt(f"{folder}/profile_4.csv", delimiter=",", names=True)
vtp = read_vtk_arrays(f"{folder}/points_4.vtp")
reference = np.stack([csv["x_m"], csv["y_m"], csv["z_m"]], axis=1)
# The CSV holds 10 significant digits; the ascii Float64 .vtp is exact.
assert np.allclose(vtp["points"] - vtp["displacement"], reference, rtol=1e-9, atol=1e-15), "positions"
assert np.allclose(vtp["displacement"][:, 0], csv["ux_m"], rtol=1e-9, atol=1e-15), "displacement"
assert np.allclose(vtp["velocity"][:, 0], csv["vx_m_s"], rtol=1e-9, atol=1e-12), "velocity"
assert np.allclose(vtp["stress"][:, 0], csv["sxx_Pa"], rtol=1e-9, atol=1e-6), "stress xx"
assert np.allclose(vtp["pressure"], csv["pressure_Pa"], rtol=1e-9, atol=1e-6), "pressure"
assert np.array_equal(vtp["grain"], csv["grain"].astype(np.int32)), "grain"
print("ok: PD points_4.vtp holds profile_4.csv's values at the deformed positions")
PYEOF
# Granular grains: profiles/grains_<k>.vtp at profile_interval, the column along z (z = −depth).
run_formats granular "$ROOT/tests/cli/cases/granular_tiny.toml"
check $(variants granular profiles/grains_2.vtp)
"$PY" - "$WORK/granular_ascii" "$ROOT/python" <<'PYEOF' || fail "granular grains_2.vtp differs from probes.csv"
import re, sys
import numpy as np
sys.path.insert(0, sys.argv[2])
from shockfield.vtk_arrays import read_vtk_arrays
run = sys.argv[1]
pvd = open(f"{run}/profiles/grains.pvd").read()
times = {f: float(t) for t, f in re.findall(r'timestep="([^"]+)" part="0" file="([^"]+)"', pvd)}
assert sorted(times) == ["grains_0.vtp", "grains_1.vtp", "grains_2.vtp"], times
vtp = read_vtk_arrays(f"{run}/profiles/grains_2.vtp")
probes = np.genfromtxt(f"{run}/probes.csv", delimiter=",", names=True)
row = probes[np.argmin(abs(probes["time_s"] - times["grains_2.vtp"]))]
# The frame and the probe row due at 1e-4 s come from the same step (first at or past it).
assert abs(row["time_s"] - times["grains_2.vtp"]) <= 1e-9 * times["grains_2.vtp"], (row["time_s"], times)
for g in (0, 100, 199):  # "+ down" in the CSV, z up in the frame; the CSV holds 10 digits
    assert np.isclose(vtp["velocity"][g, 2], -row[f"velocity_{g}_m_s"], rtol=1e-9, atol=1e-15), ("velocity", g)
    assert np.isclose(vtp["contact_force"][g], row[f"force_{g}_N"], rtol=1e-9), ("force", g)
    assert np.isclose(vtp["overlap"][g], row[f"overlap_{g}_m"], rtol=1e-9), ("overlap", g)
assert not vtp["velocity"][:, :2].any() and not vtp["points"][:, :2].any(), "the column is not on the z axis"
assert np.all(np.diff(vtp["points"][:, 2]) < 0), "grain 0 is not on top"
assert np.array_equal(vtp["grain"], np.arange(200)) and vtp["type"][100] == 2 and (vtp["type"] == 1).sum() == 199
print("ok: granular grains_2.vtp holds probes.csv's values of its step, the column along z")
PYEOF
echo "vtk_round_trip: mpm, dbm, phasefield, pd and granular VTK files read alike by VTK, vtk_arrays and analyze in every format"
