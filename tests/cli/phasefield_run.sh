#!/usr/bin/env bash
# method = "phasefield" through the CLI: --check, a run and its outputs, a stopped and resumed run
# bitwise identical to an uninterrupted one (same thread count), and bad input refused with the key.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=2
case_file="$ROOT/tests/cli/cases/phasefield_tiny.toml"

"$SF" run "$case_file" --check > "$WORK/check.txt"
grep -q "valid phasefield case (1920 nodes, 2 domains, 60 steps" "$WORK/check.txt" || fail "--check: $(cat "$WORK/check.txt")"

"$SF" run "$case_file" --output "$WORK/straight" -q > /dev/null
for f in series.csv fields.pvd fields/xi_0.vti fields/xi_3.vti thermo.csv checkpoint.h5 config.resolved.toml; do
  [ -s "$WORK/straight/$f" ] || fail "no $f"
done
# A 2D grid is a slab of unit thickness: its totals are per unit length (docs/conventions.md).
head -1 "$WORK/straight/series.csv" | grep -q "^step,time,volume_fraction,free_energy_per_length,hcp_volume_per_length,equivalent_radius" ||
  fail "series.csv header: $(head -1 "$WORK/straight/series.csv")"
grep -q "hcp volume .* per unit length of thickness (fraction.*free energy .* per unit length of thickness" "$WORK/straight/log.txt" \
  || fail "the log's totals lack their per-length label: $(grep finished "$WORK/straight/log.txt")"
[ "$(wc -l < "$WORK/straight/series.csv")" -eq 14 ] || fail "series.csv: expected 13 rows (t = 0, 0.5, ..., 6)"
grep -q "FreeEng" "$WORK/straight/log.txt" || fail "no thermo table in log.txt"
grep -q "critical_radius = 7.07" "$WORK/straight/config.resolved.toml" || fail "no derived critical radius"
# The free energy column never increases (gradient flow).
awk -F, 'NR > 2 && $4 > prev + 1e-12 * (prev < 0 ? -prev : prev) { bad = 1 } NR > 1 { prev = $4 } END { exit bad }' \
  "$WORK/straight/series.csv" || fail "free energy increased in series.csv"

# The domain measures in series.csv, and the plot of a run.
head -1 "$WORK/straight/series.csv" | grep -q ",surface,mean_curvature,euler,axis_a,axis_b,axis_c," || fail "no domain measures in series.csv"
"$SF" plot phasefield "$WORK/straight" > /dev/null
[ -s "$WORK/straight/phasefield.png" ] || fail "shockfield plot phasefield wrote no PNG"

# Stop and resume: cli.stop_resume.phasefield (tests/cli/stop_resume.sh).

good=$(sed -e '/^#/d' "$case_file")
expect_error "${good/scheme = \"spectral\"/scheme = \"explicit\"}" "time.dt" "at most 0.9 dx^2/(2 sum D_d) ="
expect_error "${good/dt = 0.1/dt = 4.0}" "time.dt" "at most 1/max(a, 1 - a) = 1.66667"
expect_error "${good/D = 1.0/D = -1.0}" "model.D"
expect_error "${good/D = 1.0/D = nan}" "model.D"
expect_error "${good/a = 0.4/a = 0.4
b = 1}" "model.b"
expect_error "${good/nodes = \[48, 40\]/nodes = [48]}" "grid.nodes"
# Walls ([grid.boundary]): explicit only; a dirichlet axis needs its two values; the wall holds
# its value in the frames.
walls="${good/spacing = 0.5/spacing = 0.5

[grid.boundary]
x = \"dirichlet\"
x_lo = 1.0
x_hi = 0.0
y = \"neumann\"}"
expect_error "$walls" "time.scheme" "the spectral scheme needs periodic boundaries"
explicit_walls="${walls/scheme = \"spectral\"/scheme = \"explicit\"}"
explicit_walls="${explicit_walls/dt = 0.1/dt = 0.05}"
expect_error "${explicit_walls/x_hi = 0.0/}" "grid.boundary.x_hi"
expect_error "${explicit_walls/y = \"neumann\"/y = \"open\"}" "grid.boundary.y"
echo "$explicit_walls" > "$WORK/walls.toml"
"$SF" run "$WORK/walls.toml" --output "$WORK/walls" -q > /dev/null
/usr/bin/python3 - "$WORK/walls/fields/xi_3.vti" "$ROOT/python" <<'PYEOF' || fail "the dirichlet walls do not hold 1 and 0"
import sys
sys.path.insert(0, sys.argv[2])
from shockfield.vtk_arrays import read_vtk_arrays
xi = read_vtk_arrays(sys.argv[1])["xi"].reshape(40, 48)
assert (xi[:, 0] == 1.0).all() and (xi[:, -1] == 0.0).all(), (xi[:, 0], xi[:, -1])
PYEOF
# A field file as the initial condition: the last frame of the straight run continues the growth
# (the restarted run's first frame holds the file's values); a file of another grid, a NaN node
# and a missing file are refused naming the file.
last="$WORK/straight/fields/xi_3.vti"
from_file="$(sed -e '/^\[\[initial/,/^$/d' "$case_file")
[initial]
file = \"$last\"
array = \"xi\""
echo "$from_file" > "$WORK/from_file.toml"
"$SF" run "$WORK/from_file.toml" --output "$WORK/from_file" -q > /dev/null
/usr/bin/python3 - "$last" "$WORK/from_file/fields/xi_0.vti" "$ROOT/python" <<'PYEOF' || fail "the run did not start from the field file"
import sys
import numpy as np
sys.path.insert(0, sys.argv[3])
from shockfield.vtk_arrays import read_vtk_arrays
a, b = (read_vtk_arrays(f)["xi"] for f in sys.argv[1:3])
assert np.array_equal(a, b), np.abs(a - b).max()
PYEOF
expect_error "${from_file/nodes = \[48, 40\]/nodes = [48, 41]}" "xi_3.vti" "48 x 40 x 1 nodes, the case's grid has 48 x 41 x 1"
printf '0,0.5\nnan,1\n' > "$WORK/nan.csv"
expect_error "${from_file/$last/$WORK/nan.csv}" "nan.csv"
expect_error "${from_file/$last/$WORK/missing.vti}" "initial.file"
# A pressure-dependent D ([model.pressure]): a uniform pressure that doubles D runs as D = 2
# from the same field (series equal to 1e-9 relative); the spectral scheme, a pressure that makes D negative and a
# step beyond the lowered explicit limit are refused.
/usr/bin/python3 -c "
print('# spacing = 0.5')
for j in range(40): print(','.join(['3e9'] * 48))" > "$WORK/pressure.csv"
# Both from the same field (the initial domains' profile width depends on D).
explicit="${from_file/scheme = \"spectral\"/scheme = \"explicit\"}"
explicit="${explicit/dt = 0.1/dt = 0.02}"
explicit="${explicit/$last/$WORK/straight/fields/xi_0.vti}"
pressured="${explicit/D = 1.0/D = 1.0

[model.pressure]
file = \"$WORK/pressure.csv\"
reference = 1e9
slope = 5e-10}"
echo "$pressured" > "$WORK/pressured.toml"
echo "${explicit/D = 1.0/D = 2.0}" > "$WORK/doubled.toml"
"$SF" run "$WORK/pressured.toml" --output "$WORK/pressured" -q > /dev/null
"$SF" run "$WORK/doubled.toml" --output "$WORK/doubled" -q > /dev/null
/usr/bin/python3 - "$WORK/pressured/series.csv" "$WORK/doubled/series.csv" <<'PYEOF' || fail "D(p) = 2D does not run as D = 2"
import sys
import numpy as np
a, b = (np.genfromtxt(f, delimiter=",", skip_header=1) for f in sys.argv[1:3])
assert a.shape == b.shape and np.allclose(a, b, rtol=1e-9, atol=1e-12), np.abs(a - b).max()
PYEOF
expect_error "${pressured/scheme = \"explicit\"/scheme = \"spectral\"}" "time.scheme" "pressure-dependent D"
expect_error "${pressured/slope = 5e-10/slope = -1e-9}" "pressure.csv" "must be positive"
expect_error "${pressured/dt = 0.02/dt = 0.05}" "time.dt" "max D(p)/D"
echo "phasefield: all checks passed"
