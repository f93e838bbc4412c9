#!/usr/bin/env bash
# `shockfield analyze atoms --burgers-*` end to end: a Cu edge dislocation from the Volterra field
# (examples/md_dislocation_burgers), relaxed by the MD minimiser with its outer shell held,
# dissociates into two Shockley partials. The Frank-scheme circuits must give: a/2[1-10] around
# both (the Volterra b, FS/RH), a/6[1-21] and a/6[2-1-1] around each partial found from the
# core-atom clusters, their sum the perfect vector; and 0 for a circuit in the perfect crystal
# before the dislocation is put in. Then bad options, each exit 2 with a message naming it.
source "$(dirname "$0")/lib.bash"
set -e
PY=/usr/bin/python3
EX="$ROOT/examples/md_dislocation_burgers"
cp "$EX/case.toml" "$EX/make_dislocation.py" "$WORK/"
(cd "$WORK" && $PY make_dislocation.py --output dislocation.data > /dev/null)
"$SF" run "$WORK/case.toml" -o "$WORK/relax" -j 1 -q > /dev/null
grep -q "force and pressure tolerances met" "$WORK/relax/log.txt" || fail "minimisation did not converge: $(grep FIRE "$WORK/relax/log.txt")"
"$SF" analyze atoms "$WORK/relax" --clusters 3.0 --cluster-select 'acna:!fcc,hcp' --cluster-min-size 10 \
  --burgers-orient '1 -1 0,1 1 1,-1 -1 2' --burgers-lattice 3.615 \
  --burgers-line 0.37,1.04,8.85:0,0,1:25 --burgers-clusters -o "$WORK/an" > "$WORK/stdout"
grep -q "3 Burgers circuits" "$WORK/stdout" || fail "circuit count: $(cat "$WORK/stdout")"
B="$WORK/an/burgers.csv"
head -1 "$B" | grep -q "^frame,timestep,circuit,source,atoms,centre_x_A" || fail "burgers.csv header: $(head -1 "$B")"
row() { awk -F, -v k="$1" 'NR > 1 && $3 == k { print $13 ";" $14 ";" $22 ";" $4 ";" $6 }' "$B"; }
[[ "$(row 1)" == "[1 -1 0]/2;perfect a/2<110>;1;line 1;"* ]] || fail "circuit around both partials: $(row 1)"
partials="$(row 2 | cut -d';' -f1-3) $(row 3 | cut -d';' -f1-3)"
[[ "$partials" == *"[1 -2 1]/6;Shockley a/6<112>;1"* && "$partials" == *"[2 -1 -1]/6;Shockley a/6<112>;1"* ]] \
  || fail "partials: $partials"
# The partials sit on either side of the core, 20-45 Å apart (Cu_u3's stacking-fault ribbon).
sep=$(awk -F, 'NR > 1 && $3 > 1 { x[$3] = $6 } END { d = x[2] - x[3]; print (d < 0 ? -d : d) }' "$B")
awk -v d="$sep" 'BEGIN { exit !(d > 20 && d < 45) }' || fail "partial separation $sep Å"
awk -F, 'NR > 1 { s1 += $15; s2 += $16; s3 += $17 } END { exit !(s1 == 6 && s2 == -6 && s3 == 0) }' "$B" \
  || fail "sum of all three rows is not 2 × [3 -3 0]/6"
grep -q "burgers_circuit" "$WORK/an/dump.0.lammpstrj" || fail "no burgers_circuit column in the dump"
echo "ok: relaxed edge dislocation: a/2[1-10] = a/6[1-21] + a/6[2-1-1], partials $sep Å apart"

# A cluster whose automatic circuit cannot close is skipped with a message, not fatal (here every
# bond is longer than the cutoff of a lattice constant given too small); a circuit the user placed
# still fails with exit 2.
"$SF" analyze atoms "$WORK/relax" --clusters 3.0 --cluster-select 'acna:!fcc,hcp' --cluster-min-size 10 \
  --burgers-lattice 2.9 --burgers-clusters -o "$WORK/skip" > "$WORK/stdout" || fail "a cluster without a circuit stopped the analysis"
grep -q "^2 clusters without a closed Burgers circuit were skipped (first: frame 0, cluster" "$WORK/stdout" \
  || fail "skip message: $(cat "$WORK/stdout")"
[ "$(wc -l < "$WORK/skip/burgers.csv")" -eq 1 ] || fail "skipped circuits wrote rows"
analyze_rejected "no closed path of bonds" -- atoms "$WORK/relax" --burgers-lattice 2.9 \
  --burgers-line 0.37,1.04,8.85:0,0,1:25
echo "ok: clusters without a closed circuit are skipped with a message; a placed circuit that fails is an error"

# Excess energy and profiles on the same relaxed run: e0 (median pe of the fcc atoms) is Cu_u3's
# cohesive energy −3.54 eV within the relaxed elastic field's 0.005 eV; across y (the glide-plane
# normal) the hcp fraction is non-zero only in the bins of the two faulted (111) layers, the
# fractions of each bin sum to 1, and the bins hold every atom.
"$SF" analyze atoms "$WORK/relax" --excess-energy auto --profile y:2.087 -o "$WORK/prof" > "$WORK/stdout"
e0=$(sed -n 's/.*e0 = \([-0-9.e]*\) eV.*/\1/p' "$WORK/stdout")
awk -v e="$e0" 'BEGIN { exit !(e > -3.545 && e < -3.535) }' || fail "e0 = $e0: $(cat "$WORK/stdout")"
P="$WORK/prof/profiles.csv"
awk -F, 'NR > 1 { n += $7; s = $8 + $9 + $10 + $11 + $12; if ($7 > 0 && (s < 0.999999 || s > 1.000001)) bad++;
                  if ($9 > 0 && ($6 < -3 || $6 > 4)) far++ }
         END { exit !(n == 9556 && bad == 0 && far == 0) }' "$P" || fail "profiles.csv: $(head -3 "$P")"
grep -q " excess$" <(sed -n 9p "$WORK/prof/dump.0.lammpstrj") || fail "no excess column"
echo "ok: excess energy e0 = $e0 eV; hcp only in the faulted layers of the y profile"

# A curved loop: the first stacking fault of examples/md_cu_tension_partials (Cu under tension
# along [110], strain 0.115; fixture and regenerate.sh in tests/fixtures/cu_tension_loop) is bounded
# by a curved Shockley partial loop. Its core cluster is not straight, so --burgers-clusters puts
# a circuit at stations along it; oriented by the loop's normal, every reliable non-zero one must
# give the same a/6<112> (one loop, one Burgers vector: what a circuit about the cluster's principal
# axis cannot find), and no reliable circuit anywhere in the frame anything but 0 or a Shockley
# vector (the example's by-hand circuits at this frame find a/6[1 1 2] on all four).
"$SF" analyze atoms "$ROOT/tests/fixtures/cu_tension_loop/dump.6750.lammpstrj.gz" --clusters 3.0 \
  --cluster-select 'acna:!fcc,hcp' --cluster-min-size 10 --burgers-clusters --burgers-orient '1 1 0,-1 1 0,0 0 1' \
  -o "$WORK/loop" > "$WORK/stdout"
L="$WORK/loop/burgers.csv"
loop=$(awk -F, 'NR > 1 && $4 ~ / station / && $22 == 1 && $13 != "0" { split($4, w, " "); print w[2] }' "$L" | sort | uniq -c | sort -rn | head -1)
set -- $loop
[ "${1:-0}" -ge 5 ] || fail "fewer than 5 reliable non-zero stations on one cluster: $(cat "$L")"
vectors=$(awk -F, -v k="$2" 'NR > 1 && $4 ~ ("^cluster " k " station") && $22 == 1 && $13 != "0" { print $13 }' "$L" | sort -u)
[ "$(echo "$vectors" | wc -l)" -eq 1 ] && [[ "$vectors" == "[1 1 2]/6" || "$vectors" == "[-1 -1 -2]/6" ]] \
  || fail "stations along the loop of cluster $2 give $vectors"
awk -F, 'NR > 1 && $22 == 1 && $13 != "0" && $14 != "Shockley a/6<112>" { bad++ } END { exit bad > 0 }' "$L" \
  || fail "a reliable circuit that is neither 0 nor a Shockley vector: $(cat "$L")"
echo "ok: curved partial loop: $1 stations along cluster $2 give $vectors"

# A circuit through given atom ids in the perfect crystal closes: b = 0.
{
  echo "fcc"; echo; echo "4 atoms"; echo "1 atom types"; echo
  echo "0 3.615 xlo xhi"; echo "0 3.615 ylo yhi"; echo "0 3.615 zlo zhi"; echo
  echo "Atoms # atomic"; echo
  echo "1 1 0 0 0"; echo "2 1 1.8075 1.8075 0"; echo "3 1 1.8075 0 1.8075"; echo "4 1 0 1.8075 1.8075"
} > "$WORK/fcc.data"
"$SF" analyze atoms "$WORK/fcc.data" --burgers-ids 1,2,3 --burgers-ids 1,2,4,3 -o "$WORK/ids" > /dev/null
awk -F, 'NR > 1 && $13 != "0" { bad++ } END { exit bad > 0 || NR != 3 }' "$WORK/ids/burgers.csv" \
  || fail "id circuits in a perfect crystal: $(cat "$WORK/ids/burgers.csv")"
echo "ok: id circuits in perfect fcc give 0"

# bad PATTERN ARGS...: analyze atoms of the fcc data file with ARGS exits 2 with PATTERN, no output.
bad() { local pattern="$1"; shift; analyze_rejected "$pattern" -- atoms "$WORK/fcc.data" "$@"; }
bad "--burgers-line '1,2:0,0,1:5'" --burgers-line 1,2:0,0,1:5
bad "the axis is the zero vector" --burgers-line 1,2,3:0,0,0:5
bad "not orthogonal" --burgers-orient '1 0 0,1 1 0,0 0 1' --burgers-ids 1,2,3
bad "needs --clusters" --burgers-clusters
bad "burgers-spacing" --burgers-spacing -1
bad "no atom with id 9" --burgers-ids 1,2,9
bad "not a finite number" --burgers-line 1,2,nan:0,0,1:5
bad "needs a per-atom potential energy column" --excess-energy auto
bad "expected AXIS:WIDTH" --profile q:5
bad "bin width must be a number > 0" --profile z:-1
bad "is not a finite number" --profile z:abc
bad "expected auto or a reference energy in eV): 'cohesive' is not a finite number" --excess-energy cohesive
