#!/usr/bin/env bash
# A triclinic box in an MD run (issue 18): 100 NVE steps on the LAMMPS-written triclinic data file
# (tests/fixtures/io/data_triclinic.data, 48 Cu/Ni atoms, tilts 3.615 -3.615 1.8075 Å) follow
# LAMMPS (tests/fixtures/lammps_triclinic/nve.thermo, regenerate.sh there) in pe, ke, pressure and
# the three shear pressures to 1e-8 relative (thermo.csv has 10 significant digits: 5e-10, plus the
# growth of round-off over 100 steps of a hot, chaotic crystal); final.data keeps the tilt and is
# read by LAMMPS read_data (when lmp is installed) and by shockfield; the dumps carry LAMMPS's
# triclinic header; msst runs along z, and msst along x or y, nphug but along z, pistons and
# relax_box refuse a tilted box by key (exit 2);
# profiles along x and y bin the fractional coordinate; npt couple = "tri" follows LAMMPS fix npt
# tri (also with shear_pressure targets) and resumes bitwise; fix deform tilt rates follow LAMMPS;
# the cell flips past half an edge (flip = false stops, exit 3); a crystal built into a tilted
# cell; simple shear gives LAMMPS's C44.
source "$(dirname "$0")/lib.bash"
set -e
# cu_u3_case DATA_FILE TIMESTEP THERMO_EVERY: the head of a case of Cu_u3 copper read from a data
# file (skin 1 Å), up to its [output] table.
cu_u3_case() {
  printf 'method = "md"\n[system]\ndata_file = "%s"\n[potential]\nstyle = "eam"\nfile = "Cu_u3.eam"\n' "$1"
  printf '[md]\ntimestep = %s\nskin = 1.0\n[output]\nthermo_every = %s\n' "$2" "$3"
}
case_text="method = \"md\"
[system]
data_file = \"$ROOT/tests/fixtures/io/data_triclinic.data\"
[potential]
style = \"eam/alloy\"
file = \"CuNi.eam.alloy\"
elements = [\"Cu\", \"Ni\"]
[md]
timestep = 0.002
skin = 1.0
[output]
thermo_every = 10
dump_every = 100
[[stage]]
steps = 100"
run_expecting 0 "$case_text"
/usr/bin/python3 - "$WORK/out/thermo.csv" "$ROOT/tests/fixtures/lammps_triclinic/nve.thermo" <<'PY'
import csv, sys
ours = {int(r["step"]): r for r in csv.DictReader(open(sys.argv[1]))}
names = ["temperature_K", "pe_eV", "ke_eV", "etotal_eV", "press_bar", "pxy_bar", "pxz_bar", "pyz_bar"]
worst = 0.0
for line in open(sys.argv[2]):
    step, *values = line.split()
    row = ours[int(step)]
    for name, ref in zip(names, map(float, values)):
        scale = max(abs(ref), 1.0) if not name.startswith("p") else 2e5  # pressures: of the 2e5 bar scale
        worst = max(worst, abs(float(row[name]) - ref) / scale)
print(f"largest deviation from LAMMPS over 11 rows: {worst:.2e}")
sys.exit(0 if worst < 1e-8 else f"FAIL: NVE in the triclinic cell deviates from LAMMPS by {worst:.2e} > 1e-8")
PY
grep -q "^3.615 -3.615 1.8075 xy xz yz$" "$WORK/out/final.data" || fail "final.data lost the tilt: $(sed -n 5,10p "$WORK/out/final.data")"
grep -q "^ITEM: BOX BOUNDS xy xz yz pp pp pp$" "$WORK/out/dumps/dump.100.lammpstrj" || fail "the dump has no triclinic header"
if command -v lmp > /dev/null; then
  lammps_reads_data "$WORK/out/final.data" 48
  echo "ok: LAMMPS reads final.data (48 atoms)"
fi
mv "$WORK/out" "$WORK/first"
run_expecting 0 "${case_text/$ROOT\/tests\/fixtures\/io\/data_triclinic.data/$WORK/first/final.data}"
# What does not take a tilted box yet stops the case by key.
# msst shocks a tilted cell along z (its remap keeps the tilts, as LAMMPS's; equal to LAMMPS fix
# msst in tests/unit/md_msst), not along x or y.
run_expecting 0 "$case_text
ensemble = \"msst\"
[stage.msst]
axis = \"z\"
shock_speed = 60"
expect_error "$case_text
ensemble = \"msst\"
[stage.msst]
axis = \"x\"
shock_speed = 60" "stage[0].msst.axis" "\"z\" in a triclinic box (tilt 3.615 -3.615 1.8075): msst compresses a tilted cell along z only"
expect_error "$case_text
ensemble = \"nphug\"
[stage.nphug]
style = \"iso\"
pressure = 1e5" "stage[0].nphug.style" "\"z\" in a triclinic box (tilt 3.615 -3.615 1.8075): nphug compresses a tilted cell along z only"
expect_error "$case_text
[stage.piston]
speed = 5" "stage[0]" "piston" "a piston is not supported in a triclinic box"
expect_error "${case_text/steps = 100/ensemble = \"minimize\"
relax_box = [\"x\"]}" "stage[0]" "relax_box" "relaxing the box is not supported in a triclinic box"
# npt with couple = "tri" through the case file (LAMMPS `fix npt temp 300 300 0.1 tri 1000 1000
# 0.5`, fixtures/lammps_npt_tri, the peer of tests/unit/md_npt/test_npt_tri_lammps.cpp): 400 steps
# of 256 atoms in a sheared cell follow LAMMPS in T, pe, press, the shear pressures, the edges and
# econserved, and (thermo.csv's xy_A xz_A yz_A of a tilted run) the tilts to 1e-9 (LAMMPS's own
# 1-vs-2-rank spread is 2e-11 relative in pe, 1e-13 bar/bar in the pressures), and final.data has
# LAMMPS's final tilts to 1e-12 Å (spread 5e-14 Å).
npt_fixture="$ROOT/tests/fixtures/lammps_npt_tri"
npt_tri_case="$(cu_u3_case "$npt_fixture/start.data" 0.002 10)
thermo_full_precision = true
[[stage]]
steps = 400
ensemble = \"npt\"
temperature = 300
damping = 0.1
pressure = 1000
pressure_damping = 0.5
couple = \"tri\""
run_expecting 0 "$npt_tri_case"
/usr/bin/python3 - "$WORK/out/thermo.csv" "$npt_fixture/tri.thermo" "$WORK/out/final.data" <<'PY'
import csv, sys
ours = {int(r["step"]): r for r in csv.DictReader(open(sys.argv[1]))}
# tri.thermo: step temp pe ke etotal press pxx pyy pzz pxy pxz pyz lx ly lz xy xz yz vol econserve
columns = {"temperature_K": 1, "pe_eV": 2, "press_bar": 5, "pxy_bar": 9, "pxz_bar": 10, "pyz_bar": 11,
           "lx_A": 12, "ly_A": 13, "lz_A": 14, "xy_A": 15, "xz_A": 16, "yz_A": 17, "econserved_eV": 19}
worst, last = 0.0, None
for line in open(sys.argv[2]):
    values = [float(v) for v in line.split()]
    row, last = ours[int(values[0])], values
    for name, c in columns.items():
        scale = 3e4 if name.startswith("p") and name != "pe_eV" else max(abs(values[c]), 1.0)  # pressures: of the 3e4 bar scale
        worst = max(worst, abs(float(row[name]) - values[c]) / scale)
tilt = next([float(w) for w in l.split()[:3]] for l in open(sys.argv[3]) if l.rstrip().endswith("xy xz yz"))
tilt_error = max(abs(a - b) for a, b in zip(tilt, last[15:18]))
print(f"npt tri: largest deviation from LAMMPS {worst:.2e}; final tilts {tilt} (LAMMPS {last[15:18]}, {tilt_error:.1e} A)")
sys.exit(0 if worst < 1e-9 and tilt_error < 1e-12 else "FAIL: npt couple = tri deviates from LAMMPS fix npt tri")
PY
# Stopped at step 170 and resumed (the tilts' barostat rates from the checkpoint): the same
# thermo.csv and final.data, byte for byte.
stop_then_resume "$WORK/case.toml" "$WORK/npt_resumed" 170
same_files "$WORK/out" "$WORK/npt_resumed" thermo.csv final.data
echo "ok: npt tri resumed from its checkpoint equals the uninterrupted run"
# Shear-pressure targets through the case file (shear_pressure = LAMMPS `xy 5000 5000 0.5 xz
# -4000 -4000 0.5`, fixtures/lammps_npt_tri/tri_shear.thermo): the first 100 steps follow LAMMPS
# in the shear pressures, tilts and econserved (with its strain energy) to 1e-9 as above.
run_expecting 0 "${npt_tri_case/steps = 400/steps = 100}
shear_pressure = [5000, -4000, 0]"
/usr/bin/python3 - "$WORK/out/thermo.csv" "$npt_fixture/tri_shear.thermo" <<'PY'
import csv, sys
ours = {int(r["step"]): r for r in csv.DictReader(open(sys.argv[1]))}
columns = {"pxy_bar": 9, "pxz_bar": 10, "pyz_bar": 11, "xy_A": 15, "xz_A": 16, "econserved_eV": 19}
worst = 0.0
for line in open(sys.argv[2]):
    values = [float(v) for v in line.split()]
    if int(values[0]) > 100: break
    for name, c in columns.items():
        scale = 3e4 if name.startswith("p") else max(abs(values[c]), 1.0)
        worst = max(worst, abs(float(ours[int(values[0])][name]) - values[c]) / scale)
print(f"npt tri with shear targets: largest deviation from LAMMPS {worst:.2e}")
sys.exit(0 if worst < 1e-9 else "FAIL: shear_pressure deviates from LAMMPS fix npt tri xy/xz targets")
PY
# Profiles along x and y in the tilted cell bin the fractional coordinate s (slabs parallel to the
# b-c or a-c face): on the npt run's final.data (thermal positions, tilts 3.59 0.014 0.0046 Å) the
# step-0 count per 3.7 Å bin equals numpy's binning of s·L (L = lx, ly) and the density
# count·m/(V·width_b/L) to the 10 printed digits (width_b: the last slab ends at the face); binning the Cartesian x instead gives other counts
# (the check sees a tilt ignored).
cp "$WORK/out/final.data" "$WORK/npt_final.data"
profile_case="${npt_tri_case/$npt_fixture\/start.data/$WORK/npt_final.data}"
for axis in x y; do
  run_expecting 0 "${profile_case/thermo_full_precision = true/profile_every = 10
profile_axis = \"$axis\"
profile_bin_width = 3.7}"
  /usr/bin/python3 - "$WORK/out/profiles.csv" "$WORK/npt_final.data" "$axis" <<'PY'
import csv, sys
import numpy as np
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["step"] == "0"]
lines = open(sys.argv[2]).read().splitlines()
value = lambda key, n: [float(w) for w in next(l for l in lines if l.endswith(key)).split()[:n]]
lo, hi = np.array([value(f"{a}lo {a}hi", 2) for a in "xyz"]).T
tilt = np.array(value("xy xz yz", 3))
start = next(k for k, l in enumerate(lines) if l.startswith("Atoms")) + 2
x = np.array([[float(w) for w in l.split()[2:5]] for l in lines[start:start + 256]])
(lx, ly, lz), (xy, xz, yz) = hi - lo, tilt
s = np.linalg.solve(np.array([[lx, 0, 0], [xy, ly, 0], [xz, yz, lz]]).T, (x - lo).T).T
d, width = "xyz".index(sys.argv[3]), 3.7
length = (hi - lo)[d]
nbins = int(np.ceil(length / width - 1e-9))
counts = np.bincount(np.clip(np.floor(s[:, d] * length / width).astype(int), 0, nbins - 1), minlength=nbins)
cartesian = np.bincount(np.clip(np.floor((x[:, d] - lo[d]) / width).astype(int), 0, nbins - 1), minlength=nbins)
ours = np.array([int(r["count"]) for r in rows])
widths = np.full(nbins, width)
widths[-1] = length - (nbins - 1) * width  # the last slab ends at the cell face
density = ours * 63.55 / (np.prod(hi - lo) * widths / length) * 1.66053904  # amu/A^3 to g/cm^3 (core/units.hpp)
worst = max(abs(float(r["density_g_cc"]) - rho) / rho for r, rho in zip(rows, density))
print(f"profile along {sys.argv[3]}: counts {ours.tolist()} (numpy on s: {counts.tolist()}; on the Cartesian axis: "
      f"{cartesian.tolist()}), density = count m/(V width_b/L) within {worst:.1e}")
tilt_seen = d == 1 or not np.array_equal(counts, cartesian)  # y: yz = 0.005 A moves hardly an atom
sys.exit(0 if np.array_equal(ours, counts) and worst < 1e-9 and tilt_seen
         else "FAIL: the tilted cell's profile is not binned along the fractional coordinate")
PY
done
expect_error "$npt_tri_case
pressure_dims = [\"x\", \"xy\"]" "stage[0]" "pressure_dims" "couple = \"tri\" barostats x, y, z, xy, xz and yz"
expect_error "${npt_tri_case/couple = \"tri\"/pressure_dims = [\"x\", \"shear\"]}" "stage[0]" "pressure_dims" \
  "expected a list of \"x\", \"y\", \"z\", \"xy\", \"xz\", \"yz\""
expect_error "${npt_tri_case/couple = \"tri\"/pressure_dims = [\"x\", \"xy\"]
shear_pressure = [5000, -4000, 0]}" "stage[0]" "shear_pressure" \
  "a target for the xz tilt, which is not barostatted: use couple = \"tri\" or list \"xz\" in pressure_dims"
expect_error "$npt_tri_case
shear_pressure = [5000, -4000]" "stage[0]" "shear_pressure"
expect_error "${npt_tri_case/couple = \"tri\"/pressure_dims = [\"xz\"]
deform_tilt_rate = [0, 0.01, 0]}" "stage[0]" "deform_tilt_rate" "the xz tilt is barostatted by npt and deformed at once"
# A tilt whose second dimension is not periodic cannot be barostatted (LAMMPS: "Cannot use fix npt
# on a 2nd non-periodic dimension"): the crystal below in an orthogonal cell, fixed in y.
lattice_case=$(cat "$ROOT/tests/cli/cases/tilted_fcc.toml")
expect_error "${lattice_case/tilt = \[2.1, -3.3, 1.7\]/boundary = \"pfp\"}
ensemble = \"npt\"
temperature = 300
pressure = 0
pressure_dims = [\"x\", \"xy\"]" "stage[0]" "pressure_dims" "npt can only change the xy tilt when y is periodic"

# A crystal built into a tilted cell: fcc [1-10] [11-2] [111], 4 x 3 x 2 repeats, tilts 2.1 -3.3 1.7 Å
# (the lattice test's LAMMPS peer: 144 atoms); a tilt beyond LAMMPS's limit is refused by key.
run_expecting 0 "$lattice_case"
grep -q "^144 atoms$" "$WORK/out/final.data" || fail "the tilted fcc has not 144 atoms: $(sed -n 3p "$WORK/out/final.data")"
grep -q "^2.1 -3.3 1.7 xy xz yz$" "$WORK/out/final.data" || fail "final.data lost the tilt"
expect_error "${lattice_case/tilt = \[2.1/tilt = [6.1}" "system.lattice.tilt" "tilt xy = 6.1 is beyond LAMMPS's limit"
# Tilt rates: 200 NVE steps of Cu under deform_rate x 0.01 and deform_tilt_rate 0.05 -0.03 0.02
# (1/ps) follow LAMMPS's fix deform ... remap x (fixtures/lammps_triclinic/deform.thermo) in T, pe,
# ke, etotal, press, pxy pxz pyz to 1e-8 (thermo.csv's 10 digits plus 200 steps of round-off
# growth), and the final tilts equal LAMMPS's to 1e-12 Å.
fixture="$ROOT/tests/fixtures/lammps_triclinic"
run_expecting 0 "$(cu_u3_case "$fixture/deform_start.data" 0.001 20)
[[stage]]
steps = 200
deform_rate = [0.01, 0, 0]
deform_tilt_rate = [0.05, -0.03, 0.02]"
/usr/bin/python3 - "$WORK/out/thermo.csv" "$fixture/deform.thermo" "$WORK/out/final.data" <<'PY'
import csv, sys
ours = {int(r["step"]): r for r in csv.DictReader(open(sys.argv[1]))}
names = ["temperature_K", "pe_eV", "ke_eV", "etotal_eV", "press_bar", "pxy_bar", "pxz_bar", "pyz_bar", "lx_A"]
worst, last = 0.0, None
for line in open(sys.argv[2]):
    step, *values = line.split()
    row, last = ours[int(step)], [float(v) for v in values]
    for name, ref in zip(names, last):
        scale = 1e4 if name.startswith("p") else max(abs(ref), 1.0)  # pressures: of the 1e4 bar scale
        worst = max(worst, abs(float(row[name]) - ref) / scale)
tilt = next([float(w) for w in l.split()[:3]] for l in open(sys.argv[3]) if l.rstrip().endswith("xy xz yz"))
tilt_error = max(abs(a - b) for a, b in zip(tilt, last[-3:]))
print(f"fix deform with tilt rates: largest deviation from LAMMPS {worst:.2e}; final tilts {tilt} (LAMMPS {last[-3:]}, {tilt_error:.1e} A)")
sys.exit(0 if worst < 1e-8 and tilt_error < 1e-12 else "FAIL: deform_tilt_rate deviates from LAMMPS fix deform")
PY
# Stopped at step 110 and resumed (box tilt and the fix's start tilt from the checkpoint): the same
# thermo.csv and final.data, byte for byte, as the uninterrupted run.
stop_then_resume "$WORK/case.toml" "$WORK/resumed" 110
same_files "$WORK/out" "$WORK/resumed" thermo.csv final.data
echo "ok: the tilted, deforming run resumed from its checkpoint equals the uninterrupted one"

# Cell flips (fixtures/lammps_triclinic/in.flip; compared with LAMMPS by
# tests/unit/md_npt/test_cell_flip.cpp): xy at 1/ps from lx/4 passes lx/2 at step 126 and the
# cell flips (final.data's xy is negative, the run ends normally); with flip = false the run
# stops there (exit 3) naming the setting.
flip_case="$(cu_u3_case "$fixture/deform_start.data" 0.002 10)
[[stage]]
steps = 130
deform_tilt_rate = [1.0, 0, 0]"
run_expecting 0 "$flip_case"
awk '/xy xz yz$/ { exit ($1 < -7 && $1 > -7.3) ? 0 : 1 }' "$WORK/out/final.data" || fail "the cell did not flip: $(grep 'xy xz yz' "$WORK/out/final.data")"
run_expecting 3 "$flip_case
flip = false" "deform_tilt_rate with flip = false (LAMMPS flip no)" "tilt xy"

# Simple shear carried by the tilt (examples/md_triclinic_shear): at gamma = 0.005 the shear stress
# over gamma is LAMMPS's C44 of Cu_u3 (76.448 GPa, fixtures/lammps_elastic, strain 1e-3) within
# 2e-4 relative (the next term of sigma(gamma) is cubic, ~6e-5 at this strain by the example's
# strains 0.005-0.02).
/usr/bin/python3 "$ROOT/examples/md_triclinic_shear/make_sheared.py" "$WORK" 0.005
"$SF" run "$ROOT/examples/md_triclinic_shear/case.toml" -o "$WORK/shear" -q \
  --set "system.data_file=\"$WORK/sheared_0.005.data\"" > /dev/null
c44=$(awk -F' = ' '/^c44_GPa/ {print $2}' "$ROOT/tests/fixtures/lammps_elastic/results.toml")
awk -F, -v c44="$c44" 'NR == 2 { g = -$12 * 1e-4 / 0.005; d = (g - c44) / c44; printf "C44 from the tilted cell %.4f GPa, LAMMPS %.4f GPa (%.1e)\n", g, c44, d;
  exit (d < 2e-4 && d > -2e-4) ? 0 : 1 }' "$WORK/shear/thermo.csv" || fail "the shear stress of the tilted cell is not C44 gamma"
echo "md_triclinic: ok"
