#!/usr/bin/env bash
# `shockfield plot structures` and `plot slice` on the output of `analyze atoms` over a small
# series (three LAMMPS fixtures given timesteps 100, 200, 300): each writes a PNG, says what it
# drew, and what it drew is what the CSV and the annotated dump hold. Skipped (saying so) when no
# Python with numpy and matplotlib is found.
source "$(dirname "$0")/lib.bash"
set -e
F="$ROOT/tests/fixtures/lammps_structure"
if ! "$SF" plot structures "$WORK" > /dev/null 2> "$WORK/probe"; then
  if grep -q "SHOCKFIELD_PYTHON" "$WORK/probe"; then echo "skip: no Python with numpy and matplotlib"; exit 0; fi
fi
step=100
for f in cu_fcc_perfect cu_stacking_fault cu_thermal_600K; do
  awk -v s=$step 'NR == 2 { print s; next } { print }' "$F/$f.dump" > "$WORK/$f.dump"
  step=$((step + 100))
done
"$SF" analyze atoms "$WORK/cu_fcc_perfect.dump" "$WORK/cu_stacking_fault.dump" "$WORK/cu_thermal_600K.dump" \
  --cna 3.0858 --adaptive-cna -o "$WORK/a" > /dev/null
png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$1 is not a PNG"; }

"$SF" plot structures "$WORK/a" > "$WORK/out"
grep -q "^structures: 3 frames, methods cna acna$" "$WORK/out" || fail "structures: $(cat "$WORK/out")"
png "$WORK/a/structures.png"
echo "ok: structures.png (3 frames, cna and acna)"

# The slice: |y - 8.85| < 1.5 Å of the stacking fault, by acna; the counts printed must be the
# dump's own (awk over the same rows).
dump="$WORK/a/cu_stacking_fault.dump"
"$SF" plot slice "$dump" --axis y --at 8.85 --thickness 3 -o "$WORK/slice.png" > "$WORK/out"
png "$WORK/slice.png"
want=$(awk '/^ITEM: ATOMS/ { for (k = 3; k <= NF; ++k) { if ($k == "y") y = k - 2; if ($k == "acna") c = k - 2 }; next }
  y && ($y - 8.85 < 1.5 && 8.85 - $y < 1.5) { n++; t[$c]++ }
  END { printf "%d atoms by acna: fcc %d, hcp %d, bcc %d, ico %d, other %d", n, t[1], t[2], t[3], t[4], t[5] }' "$dump")
grep -qF "slice: timestep 200, $want" "$WORK/out" || fail "slice: $(cat "$WORK/out") (expected $want)"
grep -q "hcp [1-9]" <<< "$want" || fail "the slice through the fault has no hcp atoms: $want"
echo "ok: slice.png ($want)"
# default output name, another column, the first frame
"$SF" plot slice "$dump" --column cna --frame 0 > "$WORK/out"
[ -s "$WORK/a/cu_stacking_fault_slice.png" ] || fail "no default <dump>_slice.png"
grep -q "by cna" "$WORK/out" || fail "--column cna: $(cat "$WORK/out")"

# Refusals: exit 2 before Python runs, or the helper's own message.
set +e
"$SF" plot slice "$WORK/a" > /dev/null 2> "$WORK/err"; code=$?
set -e
[ $code -eq 2 ] && grep -q "is not a file: plot slice draws an annotated dump" "$WORK/err" || fail "slice of a folder: $code $(cat "$WORK/err")"
set +e
"$SF" plot slice "$WORK/cu_fcc_perfect.dump" --column acna > /dev/null 2> "$WORK/err"; code=$?
set -e
[ $code -ne 0 ] && grep -q "no structure column (acna)" "$WORK/err" || fail "slice without the column: $code $(cat "$WORK/err")"
echo "all plot atoms checks passed"
