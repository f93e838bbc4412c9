#!/usr/bin/env bash
# `shockfield analyze atoms` on extended XYZ (ASE/OVITO): the LAMMPS fixtures written as extxyz
# (by hand, and by ASE when it is installed) give the same results as the dumps, row by row; ASE
# reads the same atoms from the file as we do (peer check); an MD run folder with extxyz dumps
# gives the same structures.csv as the same run with LAMMPS dumps; bad files are refused with the
# file and the line, exit 2 and nothing written.
source "$(dirname "$0")/lib.bash"
set -e
F="$ROOT/tests/fixtures/lammps_structure"

# dump → extxyz by hand: species Cu, Fe; two frames in one file (fcc Cu, then the stacking fault).
to_xyz() {  # DUMP SPECIES: the frame's rows as species x y z c_csp (the fixture's CSP as a property)
  awk -v sp="$2" 'NR == 4 { n = $1 } NR >= 6 && NR <= 8 { lo[NR] = $1; len[NR] = $2 - $1 }
    NR == 9 { printf "%d\nLattice=\"%.17g 0 0 0 %.17g 0 0 0 %.17g\" Origin=\"%.17g %.17g %.17g\" ", n, len[6], len[7], len[8], lo[6], lo[7], lo[8];
              printf "Properties=species:S:1:pos:R:3:c_csp:R:1 pbc=\"T T T\" Timestep=7\n" }
    NR > 9 { print sp, $3, $4, $5, $7 }' "$1"
}
{ to_xyz "$F/cu_fcc_perfect.dump" Cu; to_xyz "$F/cu_stacking_fault.dump" Cu; } > "$WORK/two.xyz"
"$SF" analyze atoms "$WORK/two.xyz" --cna 3.0858 --csp fcc --adaptive-cna -o "$WORK/xyz" > "$WORK/stdout"
grep -q "analysed 2 frames (688 atoms)" "$WORK/stdout" || fail "summary: $(cat "$WORK/stdout")"
[ -s "$WORK/xyz/two.dump" ] || fail "no two.dump written for two.xyz"
"$SF" analyze atoms "$F/cu_fcc_perfect.dump" "$F/cu_stacking_fault.dump" --cna 3.0858 --csp fcc --adaptive-cna \
  -o "$WORK/dump" > /dev/null
cut -d, -f3- "$WORK/xyz/structures.csv" > "$WORK/a"; cut -d, -f3- "$WORK/dump/structures.csv" > "$WORK/b"
cmp -s "$WORK/a" "$WORK/b" || fail "structures.csv from extxyz differs: $(cat "$WORK/xyz/structures.csv") vs $(cat "$WORK/dump/structures.csv")"
# Per atom: ids are the rows' order (1..N in each frame), cna equal to LAMMPS's c_cna of the dump
# rows in the same order, csp within 1e-10 relative of ours on the dump (the same positions).
grep -q "^ITEM: ATOMS id type element x y z c_csp cna acna csp$" "$WORK/xyz/two.dump" || fail "columns: $(grep ATOMS "$WORK/xyz/two.dump" | head -1)"
paste -d' ' <(awk '/^ITEM: ATOMS/ { f++; next } f && NF == 10 { print $1, $8, $10 }' "$WORK/xyz/two.dump") \
  <(awk 'FNR > 9 { print FNR - 9, $6 }' "$F/cu_fcc_perfect.dump" "$F/cu_stacking_fault.dump") \
  <(awk '/^ITEM: ATOMS/ { f++; next } f && NF > 9 { print $NF }' "$WORK/dump/cu_fcc_perfect.dump" "$WORK/dump/cu_stacking_fault.dump") |
  awk '{ rows++; if ($1 != $4 || $2 != $5) bad++; d = $3 - $6; if (d < 0) d = -d; s = ($6 < 0 ? -$6 : $6); if (d > 1e-10 * s + 1e-10) bad++ }
       END { if (rows != 688 || bad) { print rows, bad; exit 1 } }' || fail "per-atom cna/csp from extxyz differ"
echo "ok: two-frame extxyz file, per atom equal to the dumps (688 atoms)"

# gzip'ed extxyz, and --format extxyz for a file with another extension.
gzip -c "$WORK/two.xyz" > "$WORK/gz.xyz.gz"
cp "$WORK/two.xyz" "$WORK/other.txt"
"$SF" analyze atoms "$WORK/gz.xyz.gz" -o "$WORK/gz" > /dev/null
"$SF" analyze atoms "$WORK/other.txt" --format extxyz -o "$WORK/fmt" > /dev/null
"$SF" analyze atoms "$WORK/two.xyz" -o "$WORK/plain" > /dev/null
cmp "$WORK/gz/gz.dump" "$WORK/plain/two.dump" || fail ".xyz.gz annotated differently"
cmp "$WORK/fmt/other.dump" "$WORK/plain/two.dump" || fail "--format extxyz annotated differently"
echo "ok: .xyz.gz and --format extxyz"

# ASE as a peer: it writes the fixture, we read it; we read ASE's positions, cell and species.
if /usr/bin/python3 -c "import ase" 2> /dev/null; then
  /usr/bin/python3 - "$F/fe_bcc_perfect.dump" "$WORK/ase.xyz" <<'PY'
import sys
from ase.io import read, write
atoms = read(sys.argv[1], format="lammps-dump-text")
atoms.set_chemical_symbols(["Fe"] * len(atoms))
write(sys.argv[2], atoms, format="extxyz")
PY
  "$SF" analyze atoms "$WORK/ase.xyz" --cna 3.447 -o "$WORK/ase" > /dev/null
  awk -F, 'NR == 2 && $6 != 128 { exit 1 }' "$WORK/ase/structures.csv" || fail "ASE-written bcc Fe: $(cat "$WORK/ase/structures.csv")"
  /usr/bin/python3 - "$WORK/ase.xyz" "$WORK/ase/ase.dump" <<'PY' || fail "ASE and shockfield read different atoms"
import sys
import numpy as np
from ase.io import read
ours = read(sys.argv[2], format="lammps-dump-text")
theirs = read(sys.argv[1], format="extxyz")
assert len(ours) == len(theirs) == 128, (len(ours), len(theirs))
assert np.array_equal(ours.get_positions(), theirs.get_positions())  # full precision: exact
assert np.array_equal(ours.cell.lengths(), theirs.cell.lengths())
assert list(ours.pbc) == list(theirs.pbc)
PY
  echo "ok: ASE-written extxyz: 128 bcc; ASE reads the same positions, cell and pbc"
else
  echo "skip: ASE not installed for /usr/bin/python3 (peer check not run)"
fi

# An MD run folder with extxyz dumps: the same structures.csv as the same run with LAMMPS dumps.
sed 's/^dump_every = 100/dump_every = 50/' "$ROOT/tests/cli/cases/tiny_cu.toml" > "$WORK/lammps.toml"
sed 's/^dump_full_precision = true/&\ndump_format = "extxyz"/' "$WORK/lammps.toml" > "$WORK/xyz.toml"
"$SF" run "$WORK/lammps.toml" --output "$WORK/run_lammps" -q > /dev/null
"$SF" run "$WORK/xyz.toml" --output "$WORK/run_xyz" -q > /dev/null
ls "$WORK/run_xyz/dumps/"*.xyz > /dev/null || fail "the extxyz run wrote no .xyz dumps"
"$SF" analyze atoms "$WORK/run_lammps" --cna 3.0858 --csp fcc -o "$WORK/ra" > /dev/null
"$SF" analyze atoms "$WORK/run_xyz" --cna 3.0858 --csp fcc -o "$WORK/rb" > /dev/null
cmp "$WORK/ra/structures.csv" "$WORK/rb/structures.csv" || fail "run folder: extxyz and LAMMPS dumps differ"
[ "$(wc -l < "$WORK/rb/structures.csv")" -eq 8 ] || fail "run folder rows: $(cat "$WORK/rb/structures.csv")"
echo "ok: MD run folder of extxyz dumps = LAMMPS dumps ($(($(wc -l < "$WORK/rb/structures.csv") - 1)) frames)"

# Bad input: exit 2, the file and the line named, no output folder.
rejected() { local pattern="$1"; shift 2; analyze_rejected "$pattern" -- atoms "$@"; }
to_xyz "$F/cu_fcc_perfect.dump" Cu > "$WORK/one.xyz"
# missing positions
sed '2s/pos:R:3/position:R:3/' "$WORK/one.xyz" > "$WORK/nopos.xyz"
rejected "nopos.xyz:2: Properties=\"species:S:1:position:R:3:c_csp:R:1\" has no pos:R:3" -- "$WORK/nopos.xyz"
# a count larger than the rows (a truncated frame), in the second frame of a file
{ cat "$WORK/one.xyz"; head -100 "$WORK/one.xyz"; } > "$WORK/truncated.xyz"
rejected "truncated.xyz:359: unexpected end of file, expected atom row 99 of 256" -- "$WORK/truncated.xyz"
# a row with a value missing
awk 'NR == 40 { $5 = "" } { print }' "$WORK/one.xyz" > "$WORK/short.xyz"
rejected "short.xyz:40: expected 5 values per atom row (Properties), got 4" -- "$WORK/short.xyz"
# NaN
awk 'NR == 12 { $3 = "nan" } { print }' "$WORK/one.xyz" > "$WORK/nan.xyz"
rejected "nan.xyz:12: expected property column 'y' (a finite number), got 'nan'" -- "$WORK/nan.xyz"
# a count that is not a number
sed '1s/256/many/' "$WORK/one.xyz" > "$WORK/count.xyz"
rejected "count.xyz:1: expected the number of atoms of a frame (an integer), got 'many'" -- "$WORK/count.xyz"
# a general (not restricted) triclinic lattice, refused by name
sed '2s/Lattice="\([^ ]*\) 0 0/Lattice="\1 0.5 0/' "$WORK/one.xyz" > "$WORK/tri.xyz"
rejected "is a general triclinic cell" -- "$WORK/tri.xyz"
# duplicate ids from an id property: the frame's count line is named
awk 'NR == 2 { sub(/c_csp:R:1/, "c_csp:R:1:id:I:1") } NR > 2 { $0 = $0 " " (NR == 9 ? 1 : NR - 2) } { print }' "$WORK/one.xyz" > "$WORK/dup.xyz"
rejected "dup.xyz:1 (timestep 7): atom id 1 appears twice" -- "$WORK/dup.xyz"
# an empty frame
printf '0\nLattice="4 0 0 0 4 0 0 0 4"\n' > "$WORK/empty.xyz"
rejected "empty.xyz:1: the frame of timestep 0 has no atoms" -- "$WORK/empty.xyz"
echo "all analyze atoms extxyz checks passed"
