#!/usr/bin/env bash
# MD dumps and input files as the ecosystem writes and finds them, on a small Cu-Ni crystal:
# - the potential file found through $LAMMPS_POTENTIALS (LAMMPS's rule: the file's name in that
#   folder when it is not found as given), and refused with the places tried without it;
# - an `element` column (names from the eam/alloy file: the case names none) and ITEM: TIME
#   (dump_time), in frames named dump.<step zero-padded to the digits of the last step>;
# - read by `analyze atoms`, by the Python Run.open and by ASE with the right species (skipped
#   with a message when python3-ase is absent);
# - extended XYZ with dump_full_precision: positions read back bit for bit from final.data's;
# - a data-file mass that differs from the potential file's: the potential's is used (as LAMMPS
#   pair_coeff does) and the log says so.
source "$(dirname "$0")/lib.bash"
set -e
mkdir -p "$WORK/pots"
cp /usr/share/lammps/potentials/CuNi.eam.alloy "$WORK/pots/CuNi_test.eam.alloy"
cat > "$WORK/case.toml" <<'EOF'
method = "md"
[system.lattice]
style = "fcc"
a0 = 3.56
repeat = [3, 3, 3]
boundary = "pps"
basis_types = [1, 2, 1, 2]
[potential]
style = "eam/alloy"
file = "CuNi_test.eam.alloy"
elements = ["Cu", "Ni"]
[md]
timestep = 0.001
[velocity]
temperature = 300.0
[output]
dump_every = 5
dump_fields = ["id", "type", "element", "x", "y", "z", "vx"]
dump_time = true
[[stage]]
steps = 10
EOF

# Not found as given and no LAMMPS_POTENTIALS: refused naming the key and the places tried.
set +e
env -u LAMMPS_POTENTIALS "$SF" run "$WORK/case.toml" -o "$WORK/none" -q > /dev/null 2> "$WORK/stderr"
code=$?
set -e
[ $code -eq 2 ] || fail "missing potential: exit $code, expected 2"
grep -q "potential.file.*CuNi_test.eam.alloy' not found; tried" "$WORK/stderr" || fail "message: $(cat "$WORK/stderr")"
LAMMPS_POTENTIALS="$WORK/pots" "$SF" run "$WORK/case.toml" -o "$WORK/run" -q > /dev/null 2> "$WORK/stderr" \
  || fail "run with LAMMPS_POTENTIALS failed: $(cat "$WORK/stderr")"
grep -q "$WORK/pots/CuNi_test.eam.alloy" "$WORK/run/config.resolved.toml" || fail "the potential found is not the one in \$LAMMPS_POTENTIALS"
echo "ok: potential file found through \$LAMMPS_POTENTIALS, refused without it"

# Frame names padded to two digits (10 steps), ITEM: TIME, the element column.
[ "$(cd "$WORK/run/dumps" && echo *)" = "dump.00.lammpstrj dump.05.lammpstrj dump.10.lammpstrj" ] \
  || fail "frame names: $(ls "$WORK/run/dumps")"
dump="$WORK/run/dumps/dump.10.lammpstrj"
[ "$(sed -n 1,2p "$dump" | tr '\n' ' ')" = "ITEM: TIME 0.01 " ] || fail "no ITEM: TIME 0.01 first: $(head -3 "$dump")"
grep -q "^ITEM: ATOMS id type element x y z vx$" "$dump" || fail "columns: $(grep ATOMS "$dump")"
awk '/^ITEM: ATOMS/ { on = 1; next } on && !(($2 == 1 && $3 == "Cu") || ($2 == 2 && $3 == "Ni")) { bad++ } END { exit bad > 0 }' "$dump" \
  || fail "element names do not follow the types"
echo "ok: frames dump.00/05/10, ITEM: TIME, element Cu/Ni by type"

"$SF" analyze atoms "$WORK/run" -o "$WORK/analysis" > "$WORK/stdout" || fail "analyze atoms refused the dumps"
grep -q "analysed 3 frames (378 atoms)" "$WORK/stdout" || fail "analyze atoms: $(cat "$WORK/stdout")"
grep -q "^ITEM: ATOMS id type element x y z vx" "$WORK/analysis/dump.10.lammpstrj" || fail "annotated dump lost the element column"
echo "ok: analyze atoms reads the three frames and keeps the element column"

PYTHONPATH="$ROOT/python" /usr/bin/python3 - "$WORK/run" <<'PY' || fail "Python Run.open"
import sys
from shockfield import Run
frames = list(Run.open(sys.argv[1]).frames("dumps"))
assert [f.step for f in frames] == [0, 5, 10], [f.step for f in frames]
assert abs(frames[-1].time - 0.01) < 1e-15, frames[-1].time
atoms = frames[-1].data
assert set(atoms["element"][atoms["type"] == 2]) == {"Ni"} and set(atoms["element"][atoms["type"] == 1]) == {"Cu"}
print("ok: Python Run.open reads 3 frames, times from ITEM: TIME, element names")
PY

if /usr/bin/python3 -c "import ase" 2> /dev/null; then
  /usr/bin/python3 - "$dump" <<'PY' || fail "ASE"
import sys, ase.io
atoms = ase.io.read(sys.argv[1], format="lammps-dump-text")
symbols = atoms.get_chemical_symbols()
# 3x3x3 cells and the shrink-wrapped zhi face (create_atoms fills it, as LAMMPS): 108 + 18 atoms
assert len(symbols) == 126 and symbols.count("Cu") == 63 and symbols.count("Ni") == 63, symbols[:8]
print("ok: ASE reads 126 atoms, 63 Cu and 63 Ni")
PY
else
  echo "SKIP (ASE part): python3-ase is not installed"
fi

# Extended XYZ at full precision: the last frame's positions equal final.data's to the bit.
LAMMPS_POTENTIALS="$WORK/pots" "$SF" run "$WORK/case.toml" -o "$WORK/xyz" -q --set 'output.dump_format="extxyz"' \
  --set output.dump_full_precision=true > /dev/null
/usr/bin/python3 - "$WORK/xyz" <<'PY' || fail "extxyz full precision"
import sys
run = sys.argv[1]
lines = open(f"{run}/dumps/dump.10.xyz").read().splitlines()
header = lines[1]
assert "Time=0.01" in header, header
xyz = [tuple(float(v) for v in l.split()[1:4]) for l in lines[2:]]
data = open(f"{run}/final.data").read().split("Atoms # atomic")[1].split("Velocities")[0].split("\n")
pos = {}
for l in data:
    w = l.split()
    if len(w) >= 5:
        pos[int(w[0])] = tuple(float(v) for v in w[2:5])
ids = range(1, len(xyz) + 1)
assert len(pos) == len(xyz) == 126
species = [l.split()[0] for l in lines[2:]]
assert set(species) == {"Cu", "Ni"}, set(species)
same = sum(pos[i] == p for i, p in zip(ids, xyz))
# final.data wraps positions into the periodic x and y (write_data does): an atom that left the
# box since the last rebuild differs by a box length there. With %g (6 digits) none would be equal.
lattice = [float(v) for v in header.split('Lattice="')[1].split('"')[0].split()]
lengths = (lattice[0], lattice[4], lattice[8])
for i, p in zip(ids, xyz):
    for d in range(3):
        diff = p[d] - pos[i][d]
        assert abs(diff - round(diff / lengths[d]) * lengths[d]) < 1e-12, (i, d, p, pos[i])
assert same >= 93, f"only {same} of 126 positions equal"
print(f"ok: extxyz full precision: {same} of 126 positions equal final.data's bit for bit, the others by a "
      "periodic box length; species Cu/Ni")
PY

# A data file whose Masses give Ni 60 amu: the potential file's 58.689 is used and the log says so.
sed 's/^2 58.689\(.*\)$/2 60.0\1/' "$WORK/run/final.data" > "$WORK/heavy.data"
grep -q "^2 60.0" "$WORK/heavy.data" || fail "could not edit the Masses of $(grep -A4 Masses "$WORK/run/final.data")"
cat > "$WORK/read.toml" <<EOF
method = "md"
[system]
data_file = "$WORK/heavy.data"
boundary = "pps"
[potential]
style = "eam/alloy"
file = "CuNi.eam.alloy"
elements = ["Cu", "Ni"]
[md]
timestep = 0.001
[[stage]]
steps = 1
EOF
"$SF" run "$WORK/read.toml" -o "$WORK/heavy" -q > /dev/null
grep -q "note: atom type 2: the data file's mass 60 amu differs from the potential file's 58.689 amu, which is used" "$WORK/heavy/log.txt" \
  || fail "no note on the differing mass: $(grep -i mass "$WORK/heavy/log.txt")"
grep -q "^2 58.689 " "$WORK/heavy/final.data" || fail "the potential's mass was not used: $(grep -A4 Masses "$WORK/heavy/final.data")"
echo "ok: a differing data-file mass is reported and the potential file's is used"
echo "md_dumps: all checks passed"
