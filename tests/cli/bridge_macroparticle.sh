#!/usr/bin/env bash
# `shockfield bridge eam-to-macroparticle` (docs/bridges.md): the [atoms] of a material file from
# the relaxed EAM crystal (Cu_u3: e0 = 3.54 eV, a0 = 3.615 Å, equal to LAMMPS, docs/md-validation.md),
# the moduli beside each other in the provenance, a macroparticle case that reads the file resolving
# the same pair law as one that types the numbers, the case's keys winning, and bad input.
source "$(dirname "$0")/lib.bash"
set -e
export OMP_NUM_THREADS=1
value() { python3 -c "import tomllib,sys; d=tomllib.load(open(sys.argv[1],'rb'))
for k in sys.argv[2].split('.'): d=d[k]
print(d)" "$1" "$2"; }
# close A B REL: |A − B| <= REL·|B|
close() { python3 -c "import sys; a,b,r=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=r*abs(b) else 1)" "$@"; }

"$SF" bridge --help | grep -q "eam-to-macroparticle" || fail "bridge --help lacks eam-to-macroparticle"
f="$WORK/cu_atoms.toml"
"$SF" bridge eam-to-macroparticle --potential Cu_u3.eam --a0 3.6 -o "$f" --name cu_u3 > "$WORK/out.txt"
cat "$WORK/out.txt"
eV=1.602176634e-19; amu=1.66053906660e-27
e0=$(value "$f" atoms.cohesive_energy); a0=$(value "$f" atoms.lattice_constant); m=$(value "$f" atoms.atomic_mass)
# Cu_u3 relaxed: E/N = −3.54 eV and a0 = 3.615 Å to the relaxation's tolerance (LAMMPS: 3.614999976 Å).
close "$e0" "$(python3 -c "print(3.54*$eV)")" 1e-6 || fail "cohesive energy $e0 J is not 3.54 eV"
close "$a0" 3.615e-10 1e-6 || fail "lattice constant $a0 m is not 3.615 Å"
close "$m" "$(python3 -c "print(63.55*$amu)")" 1e-9 || fail "atomic mass $m kg is not Cu_u3's 63.55 u"
[ "$(value "$f" atoms.crystal)" = fcc ] || fail "the crystal is not recorded"
grep -qF "$(sha256sum /usr/share/lammps/potentials/Cu_u3.eam | cut -d' ' -f1)" "$f" || fail "provenance lacks the potential's SHA-256"

fit=provenance.eam_to_macroparticle.fit
c11=$(value "$f" $fit.c11_GPa); c12=$(value "$f" $fit.c12_GPa)
e_md=$(value "$f" $fit.md_youngs_001_Pa); e15=$(value "$f" $fit.pair_law_youngs_eq15_Pa)
e_law=$(value "$f" $fit.pair_law_youngs_001_Pa); pq=$(value "$f" $fit.pq_matching_md_youngs_001)
# The LAMMPS elastic constants of Cu_u3 (tests/fixtures/lammps_elastic): 167.26, 124.15 GPa.
close "$c11" 167.2646 1e-4 || fail "C11 = $c11 GPa"
close "$e_md" "$(python3 -c "print(($c11-$c12)*($c11+2*$c12)/($c11+$c12)*1e9)")" 1e-12 || fail "E[001] of the crystal"
# Eq 15 by hand: E = πρ pq e0/(72·0.74 m) with ρ = 4m/a0³ (p, q = 4, 9).
close "$e15" "$(python3 -c "import math; print(math.pi*4/($a0)**3*36*$e0/(72*0.74))")" 1e-12 || fail "eq 15 = $e15 Pa"
# The perfect packing's [001] modulus is 4√2/3 of eq 15 (docs/theory/macroparticle.md).
close "$e_law" "$(python3 -c "import math; print(4*math.sqrt(2)/3*$e15)")" 1e-12 || fail "packing E[001] = $e_law Pa"
close "$pq" "$(python3 -c "print(36*$e_md/$e_law)")" 1e-12 || fail "pq matching E[001] = $pq"
echo "Cu_u3: E[001] MD $e_md Pa, packing (4, 9) $e_law Pa, pq to match $pq"

# A case reading the file resolves the same pair law as one that types the numbers (in eV, m, u).
box() {  # box MATERIAL_LINES: a small loaded box of the fcc packing
  cat <<CASE
method = "macroparticle"
[material]
$1
[pair]
p = 4
q = 9
r0 = 0.001
[specimen]
shape = "box"
cells = [2, 2, 3]
[loading]
mode = "tension"
strain_rate = 1000.0
final_strain = 0.0001
[run]
CASE
}
cp "$f" "$WORK/atoms.toml"
box 'file = "atoms.toml"' > "$WORK/from_file.toml"
typed_e0=$(python3 -c "print(repr($e0/$eV))"); typed_m=$(python3 -c "print(repr($m/$amu))")
box "cohesive_energy = $typed_e0
lattice_constant = $a0
atomic_mass = $typed_m" > "$WORK/typed.toml"
"$SF" run "$WORK/from_file.toml" --check --write-resolved "$WORK/file.resolved.toml" > /dev/null
"$SF" run "$WORK/typed.toml" --check --write-resolved "$WORK/typed.resolved.toml" > /dev/null
for key in derived.youngs_eq15 derived.dt derived.particle_mass derived.bond_energy derived.G derived.H; do
  a=$(value "$WORK/file.resolved.toml" "$key" 2>/dev/null || echo missing)
  b=$(value "$WORK/typed.resolved.toml" "$key" 2>/dev/null || echo missing)
  [ "$a" != missing ] || fail "no $key in the resolved case"
  close "$a" "$b" 1e-12 || fail "$key from the file $a differs from the typed $b"
done
close "$(value "$WORK/file.resolved.toml" material.cohesive_energy)" 3.54 1e-6 || fail "resolved e0 is not in eV"
grep -q "sha256" "$WORK/file.resolved.toml" || fail "the resolved case lacks the material file's hash"
"$SF" run "$WORK/from_file.toml" -o "$WORK/run" -q > /dev/null
grep -q "material file: .*atoms.toml" "$WORK/run/log.txt" || fail "log.txt does not name the material file"

# The case's own keys win: e0 from the case, a0 and m still from the file.
box 'file = "atoms.toml"
cohesive_energy = 3.0' > "$WORK/override.toml"
"$SF" run "$WORK/override.toml" --check --write-resolved "$WORK/override.resolved.toml" > /dev/null
close "$(value "$WORK/override.resolved.toml" material.cohesive_energy)" 3.0 1e-15 || fail "the case's e0 did not win"
close "$(value "$WORK/override.resolved.toml" material.lattice_constant)" "$a0" 1e-15 || fail "a0 not from the file"

# Bad input: a file value outside the model's physical range, a non-fcc lattice, no minimum.
sed 's/^cohesive_energy = .*/cohesive_energy = 1e-30/' "$f" > "$WORK/atoms.toml"
set +e
"$SF" run "$WORK/from_file.toml" --check > /dev/null 2> "$WORK/err.txt"; code=$?
set -e
[ $code -eq 2 ] || fail "a 1e-30 J cohesive energy: exit $code"
grep -q "atoms.toml: key 'atoms.cohesive_energy'" "$WORK/err.txt" || fail "message: $(cat "$WORK/err.txt")"
for args in "--lattice bcc" "--p 9 --q 4"; do
  set +e
  "$SF" bridge eam-to-macroparticle --potential Cu_u3.eam --a0 3.6 -o "$WORK/bad.toml" $args > /dev/null 2> "$WORK/err.txt"
  code=$?
  set -e
  [ $code -eq 2 ] || fail "$args: exit $code"
  [ ! -e "$WORK/bad.toml" ] || fail "$args: a refused bridge wrote a file"
  echo "ok: $(cat "$WORK/err.txt")"
done
echo "bridge eam-to-macroparticle: ok"
