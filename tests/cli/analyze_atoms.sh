#!/usr/bin/env bash
# `shockfield analyze atoms`: per-atom columns appended to the dump (equal to LAMMPS's on the
# shocked Cu fixture), structures.csv, a dump series, a data file and an MD run folder; then bad
# input, each refused with one message naming the file, exit code 2 and no output left behind.
source "$(dirname "$0")/lib.bash"
set -e
F="$ROOT/tests/fixtures/lammps_structure"

# The shocked Cu sample: cna and coord columns equal LAMMPS's c_cna and c_coord, row by row.
"$SF" analyze atoms "$F/cu_shocked.dump" --cna 3.0858 --coordination 3.0858 --csp fcc --adaptive-cna \
  --bond-pairs 3.0858 -o "$WORK/shock" > "$WORK/stdout"
grep -q "analysed 1 frames (3000 atoms)" "$WORK/stdout" || fail "summary line: $(cat "$WORK/stdout")"
out="$WORK/shock/cu_shocked.dump"
[ -s "$out" ] || fail "no annotated dump"
grep -q "ITEM: ATOMS id type x y z c_cna c_csp c_coord coord cna acna csp bpa" "$out" || fail "columns: $(sed -n 9p "$out")"
awk 'NR > 9 && ($6 != $10 || $8 != $9) { bad++ } END { exit bad > 0 }' "$out" || fail "cna/coord columns differ from LAMMPS's"
head -1 "$WORK/shock/structures.csv" | grep -q "^frame,timestep,atoms,cna_fcc_count,cna_hcp_count,cna_bcc_count,cna_ico_count,cna_other_count," \
  || fail "structures.csv header: $(head -1 "$WORK/shock/structures.csv")"
lammps_fcc=$(awk 'NR > 9 && $6 == 1' "$F/cu_shocked.dump" | wc -l)
awk -F, -v n="$lammps_fcc" 'NR == 2 && ($3 != 3000 || $4 != n) { exit 1 }' "$WORK/shock/structures.csv" \
  || fail "structures.csv counts: $(sed -n 2p "$WORK/shock/structures.csv") (LAMMPS fcc $lammps_fcc)"
echo "ok: shocked Cu, columns and counts equal LAMMPS's ($lammps_fcc fcc)"

# A series of two dumps: one row per frame, default analysis adaptive CNA.
"$SF" analyze atoms "$F/cu_fcc_perfect.dump" "$F/fe_bcc_perfect.dump" -o "$WORK/series" > /dev/null
[ "$(wc -l < "$WORK/series/structures.csv")" -eq 3 ] || fail "series rows: $(cat "$WORK/series/structures.csv")"
awk -F, 'NR == 2 && $4 != 256 { exit 1 } NR == 3 && $6 != 128 { exit 1 }' "$WORK/series/structures.csv" \
  || fail "series a-CNA counts: $(cat "$WORK/series/structures.csv")"
echo "ok: series, adaptive CNA 256 fcc then 128 bcc"

# A gzip-compressed dump gives the same annotated frame.
gzip -c "$F/cu_fcc_perfect.dump" > "$WORK/cu.dump.gz"
"$SF" analyze atoms "$WORK/cu.dump.gz" "$F/cu_fcc_perfect.dump" -o "$WORK/gz" > /dev/null
cmp "$WORK/gz/cu.dump" "$WORK/gz/cu_fcc_perfect.dump" || fail ".gz input annotated differently"
echo "ok: .gz input"

# A data file (atom style atomic) made from the perfect fcc dump becomes <stem>.dump.
{
  echo "fcc Cu from the fixture"; echo; echo "256 atoms"; echo "1 atom types"; echo
  sed -n 6,8p "$F/cu_fcc_perfect.dump" | awk '{ print $1, $2, substr("xyz", NR, 1) "lo", substr("xyz", NR, 1) "hi" }'
  echo; echo "Masses"; echo; echo "1 63.546"; echo; echo "Atoms # atomic"; echo
  awk 'NR > 9 { print $1, $2, $3, $4, $5 }' "$F/cu_fcc_perfect.dump"
} > "$WORK/cu.data"
"$SF" analyze atoms "$WORK/cu.data" --cna 3.0858 -o "$WORK/data" > /dev/null
[ -s "$WORK/data/cu.dump" ] || fail "no cu.dump from the data file"
awk -F, 'NR == 2 && $4 != 256 { exit 1 }' "$WORK/data/structures.csv" || fail "data file counts: $(cat "$WORK/data/structures.csv")"
echo "ok: data file"

# An MD run folder: dumps/dump.<step>.lammpstrj in step order (10 before 2 alphabetically).
mkdir -p "$WORK/run/dumps"
cp "$F/cu_fcc_perfect.dump" "$WORK/run/dumps/dump.2.lammpstrj"
cp "$F/cu_stacking_fault.dump" "$WORK/run/dumps/dump.10.lammpstrj"
"$SF" analyze atoms "$WORK/run" --cna 3.0858 -o "$WORK/runout" > /dev/null
awk -F, 'NR == 2 && $3 != 256 { exit 1 } NR == 3 && ($3 != 432 || $5 != 96) { exit 1 }' "$WORK/runout/structures.csv" \
  || fail "run folder rows: $(cat "$WORK/runout/structures.csv")"
echo "ok: run folder in step order"

# Clusters: the non-fcc (a-CNA) atoms around the 6 Å void of the 300 K fixture are one shell of
# 122 atoms centred on the void's centre (the box centre, 14.46 Å), within 0.1 Å.
"$SF" analyze atoms "$F/cu_void_300K.dump" --clusters 3.0858 --cluster-select 'acna:!fcc' --cluster-min-size 5 \
  -o "$WORK/void" > /dev/null
[ "$(wc -l < "$WORK/void/clusters.csv")" -eq 2 ] || fail "void clusters: $(cat "$WORK/void/clusters.csv")"
awk -F, 'NR == 2 { d = 0; for (k = 5; k <= 7; ++k) d += ($k - 14.46) ^ 2; exit !($4 == 122 && d < 0.01) }' \
  "$WORK/void/clusters.csv" || fail "void cluster: $(sed -n 2p "$WORK/void/clusters.csv")"
grep -q "ITEM: ATOMS id type x y z c_cna c_csp c_coord acna cluster" "$WORK/void/cu_void_300K.dump" || fail "no cluster column"
echo "ok: void-surface cluster"

# Clusters by excess energy: pe = -3.54 eV (Cu_u3's cohesive energy) everywhere but 0.24 eV more
# on the atoms within 3 Å of the box centre; excess>0.1 clusters exactly those (auto e0: the median
# pe of the fcc atoms), excess>0.3 none.
awk 'NR == 9 { print $0, "pe"; next } NR > 9 { d = ($3 - 7.23) ^ 2 + ($4 - 7.23) ^ 2 + ($5 - 7.23) ^ 2;
  print $0, (d < 9 ? -3.30 : -3.54); next } { print }' "$F/cu_fcc_perfect.dump" > "$WORK/pe.dump"
hot=$(awk 'NR > 9 && $NF == -3.30' "$WORK/pe.dump" | wc -l)
[ "$hot" -gt 5 ] || fail "the hot ball has $hot atoms"
"$SF" analyze atoms "$WORK/pe.dump" --excess-energy auto --clusters 3.0858 --cluster-select 'excess>0.1' -o "$WORK/ex" > /dev/null
awk -F, -v n="$hot" 'END { exit !(NR == 2 && $4 == n) }' "$WORK/ex/clusters.csv" || fail "excess clusters: $(cat "$WORK/ex/clusters.csv") ($hot hot atoms)"
awk '/^ITEM: ATOMS/ { for (k = 1; k <= NF; ++k) if ($k == "excess") e = k - 2; else if ($k == "cluster") c = k - 2; next }
  e && ($e > 0.1) != ($c == 1) { bad++ } END { exit bad > 0 || !e }' "$WORK/ex/pe.dump" || fail "excess and cluster columns disagree"
"$SF" analyze atoms "$WORK/pe.dump" --excess-energy -3.54 --clusters 3.0858 --cluster-select 'excess>0.3' -o "$WORK/ex3" > /dev/null
[ "$(wc -l < "$WORK/ex3/clusters.csv")" -eq 1 ] || fail "excess>0.3 found clusters: $(cat "$WORK/ex3/clusters.csv")"
echo "ok: clusters by excess energy ($hot atoms at 0.24 eV)"

# Diamond: cubic diamond Si (3x3x3 cells, 216 atoms) all "cubic" (dia = 1), and no diamond in fcc Cu.
awk 'BEGIN { a = 5.431; n = 0
  split("0 0 0 0 .5 .5 .5 0 .5 .5 .5 0 .25 .25 .25 .25 .75 .75 .75 .25 .75 .75 .75 .25", b, " ")
  for (i = 0; i < 3; ++i) for (j = 0; j < 3; ++j) for (k = 0; k < 3; ++k) for (s = 0; s < 8; ++s)
    row[++n] = sprintf("%d 1 %.10g %.10g %.10g", n, (i + b[3*s+1]) * a, (j + b[3*s+2]) * a, (k + b[3*s+3]) * a)
  printf "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS pp pp pp\n", n
  for (d = 0; d < 3; ++d) printf "0 %.10g\n", 3 * a
  print "ITEM: ATOMS id type x y z"; for (m = 1; m <= n; ++m) print row[m] }' > "$WORK/si.dump"
"$SF" analyze atoms "$WORK/si.dump" "$F/cu_fcc_perfect.dump" --diamond --adaptive-cna -o "$WORK/dia" > /dev/null
head -1 "$WORK/dia/structures.csv" | grep -q ",dia_cubic_count,dia_cubic_first_count,dia_cubic_second_count,dia_hexagonal_count,dia_hexagonal_first_count,dia_hexagonal_second_count,dia_other_count," \
  || fail "dia columns: $(head -1 "$WORK/dia/structures.csv")"
awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) c[$k] = k; next }
  NR == 2 && !($c["dia_cubic_count"] == 216 && $c["acna_other_count"] == 216) { exit 1 }
  NR == 3 && !($c["dia_other_count"] == 256 && $c["acna_fcc_count"] == 256) { exit 1 }' "$WORK/dia/structures.csv" \
  || fail "diamond counts: $(cat "$WORK/dia/structures.csv")"
awk 'NR > 9 && $NF != 1 { bad++ } END { exit bad > 0 }' "$WORK/dia/si.dump" || fail "si.dump: dia column not all 1"
# A vacancy in Si: --cluster-select 'dia:!cubic' (connected within 4 Å, past the second-neighbour
# distance 3.84 Å) gives one cluster, exactly the atoms not cubic.
awk 'NR == 4 { print $1 - 1; next } NR > 9 && $1 == 100 { next } { print }' "$WORK/si.dump" > "$WORK/si_vacancy.dump"
"$SF" analyze atoms "$WORK/si_vacancy.dump" --clusters 4 --cluster-select 'dia:!cubic' -o "$WORK/diavac" > /dev/null
noncubic=$(awk 'NR == 9 { for (k = 3; k <= NF; ++k) if ($k == "dia") c = k - 2 } NR > 9 && $c != 1' "$WORK/diavac/si_vacancy.dump" | wc -l)
awk -F, -v n="$noncubic" 'END { exit !(NR == 2 && $4 == n && n >= 4) }' "$WORK/diavac/clusters.csv" \
  || fail "vacancy cluster: $(cat "$WORK/diavac/clusters.csv") ($noncubic non-cubic atoms)"
echo "ok: diamond: 216 cubic-diamond Si atoms, no diamond in fcc Cu; a vacancy: one cluster of $noncubic non-cubic atoms"

# rejected PATTERN -- ARGS...: must exit 2 with PATTERN in the message and leave no output folder.
rejected() { local pattern="$1"; shift 2; analyze_rejected "$pattern" -- atoms "$@"; }
head -9 "$F/cu_fcc_perfect.dump" > "$WORK/header"
# missing position columns
{ sed 's/^ITEM: ATOMS .*/ITEM: ATOMS id type c_cna/' "$WORK/header"; awk 'NR > 9 { print $1, $2, $6 }' "$F/cu_fcc_perfect.dump"; } > "$WORK/nopos.dump"
rejected "nopos.dump: dump frame of timestep 0 has no positions (x y z, xu yu zu or xs ys zs)" -- "$WORK/nopos.dump"
# duplicate ids
{ cat "$WORK/header"; awk 'NR > 9 { if ($1 == 7) $1 = 3; print }' "$F/cu_fcc_perfect.dump"; } > "$WORK/dup.dump"
rejected "dup.dump (timestep 0): atom id 3 appears twice" -- "$WORK/dup.dump"
# an atom outside a fixed box
{ sed 's/^ITEM: BOX BOUNDS pp pp pp/ITEM: BOX BOUNDS ff ff ff/' "$WORK/header"; awk 'NR > 9 { if ($1 == 5) $3 = 99; print }' "$F/cu_fcc_perfect.dump"; } > "$WORK/outside.dump"
rejected "outside.dump (timestep 0): atom id 5 at x = 99 is outside the fixed box" -- "$WORK/outside.dump"
# an empty frame
sed 's/^256$/0/' "$WORK/header" > "$WORK/empty.dump"
rejected "has no atoms" -- "$WORK/empty.dump"
# a truncated file: the second frame stops half-way; no output at all, not even the first frame's
{ cat "$F/cu_fcc_perfect.dump"; head -100 "$F/cu_fcc_perfect.dump"; } > "$WORK/truncated.dump"
rejected "truncated.dump" -- "$WORK/truncated.dump"
# a triclinic box tilted beyond LAMMPS's limit (xy = 10 in bounds 14.46 wide: lx = 4.46), refused by name
sed 's/^ITEM: BOX BOUNDS pp pp pp/ITEM: BOX BOUNDS xy xz yz pp pp pp/' "$F/cu_fcc_perfect.dump" |
  awk 'NR == 6 { print $0, 10; next } NR >= 7 && NR <= 8 { print $0, 0; next } { print }' > "$WORK/triclinic.dump"
rejected "tilt xy = 10 is beyond LAMMPS's limit" -- "$WORK/triclinic.dump"
head -c 800 "$WORK/cu.dump.gz" > "$WORK/cut.dump.gz"  # the whole file is ~1.7 kB
rejected "cut.dump.gz: gzip -dc failed: not a gzip file, or a truncated or corrupt one" -- "$WORK/cut.dump.gz"
rejected "--csp: expected fcc, bcc or an even neighbour count" -- "$F/cu_fcc_perfect.dump" --csp 7
rejected "--cluster-select 'cna:hcp': selecting by cna needs --cna" -- "$F/cu_fcc_perfect.dump" --clusters 3 --cluster-select cna:hcp
rejected "expected cna|acna|bpa:[!]TYPE[,TYPE...] (TYPE fcc hcp bcc ico other), dia:[!]TYPE" -- "$F/cu_fcc_perfect.dump" --clusters 3 --cluster-select acna:diamond
rejected "(TYPE cubic cubic_first cubic_second hexagonal hexagonal_first hexagonal_second other)" -- "$F/cu_fcc_perfect.dump" --clusters 3 --cluster-select dia:fcc
rejected "--cluster-select 'excess>0.1': selecting by excess needs --excess-energy" -- "$F/cu_fcc_perfect.dump" --clusters 3 --cluster-select 'excess>0.1'
rejected "--cluster-select 'excess>hot': expected excess>NUMBER (eV)" -- "$WORK/pe.dump" --excess-energy auto --clusters 3 --cluster-select 'excess>hot'
rejected "--clusters and --cluster-select go together" -- "$F/cu_fcc_perfect.dump" --clusters 3
mkdir -p "$WORK/notrun"
rejected "notrun: a folder but not a shockfield MD run folder" -- "$WORK/notrun"
echo "all analyze atoms checks passed"
