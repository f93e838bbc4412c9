#!/usr/bin/env bash
# pair_style adp in a case file: a 4x4x4 Ni crystal (256 atoms) on Ni.adp started at 600 K runs
# 2000 NVE steps (dt 2 fs, it settles near 280 K), and its total energy must neither drift nor
# wander: drift (least-squares slope over steps 100..2000, times the 3.8 ps) below 2e-5 eV/atom
# and spread below 1e-4 eV/atom (measured 3.1e-6 and 2.6e-5; the same cell on NiAlH_jea.eam.alloy
# with eam/alloy, run beside it: 1.0e-6 and 1.7e-5; step 0 is left out, the jump from the perfect
# lattice to Verlet's shadow energy). Bad ADP files and keys are refused before the run (exit 2):
# a file without its u(r) and w(r) tables, an element line with a wrong count, an element the file
# does not have.
source "$(dirname "$0")/lib.bash"
set -e
case="method = \"md\"

[system.lattice]
style = \"fcc\"
a0 = 3.52
repeat = [4, 4, 4]
boundary = \"ppp\"
elements = [\"Ni\"]

[potential]
style = \"adp\"
file = \"Ni.adp\"
elements = [\"Ni\"]

[md]
timestep = 0.002
skin = 1.0

[velocity]
temperature = 600.0

[output]
thermo_every = 100
thermo_full_precision = true

[[stage]]
name = \"nve\"
steps = 2000"

# drift_and_spread THERMO_CSV: prints the total-energy drift over the run and its spread, eV/atom.
drift_and_spread() {
  awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "etotal_eV") c = k }
           NR > 2 { t = $2; e = $c / 256; n++; st += t; se += e; stt += t * t; ste += t * e
                    if (n == 1 || e > mx) mx = e; if (n == 1 || e < mn) mn = e; tl = t; if (n == 1) t0 = t }
           END { b = (n * ste - st * se) / (n * stt - st * st); d = b * (tl - t0); printf "%.3e %.3e\n", (d < 0 ? -d : d), mx - mn }' "$1"
}
check_energy() {  # label
  read -r drift spread < <(drift_and_spread "$WORK/out/thermo.csv")
  echo "$1: energy drift $drift eV/atom over 2000 steps, spread $spread eV/atom"
  awk -v d="$drift" -v s="$spread" 'BEGIN { exit !(d < 2e-5 && s < 1e-4) }' || fail "$1 does not conserve energy"
}

run_expecting 0 "$case"
grep -q "input file: .*Ni.adp" "$WORK/out/log.txt" || fail "Ni.adp is not in the run's provenance"
[ "$(wc -l < "$WORK/out/thermo.csv")" -eq 22 ] || fail "expected 21 thermo rows"
check_energy "adp (Ni.adp)"
run_expecting 0 "${case/style = \"adp\"
file = \"Ni.adp\"/style = \"eam/alloy\"
file = \"NiAlH_jea.eam.alloy\"}"
check_energy "eam/alloy (NiAlH_jea.eam.alloy)"

adp=/usr/share/lammps/potentials/Ni.adp
head -n 23007 "$adp" > "$WORK/no_uw.adp"  # the setfl part only
expect_error "${case/file = \"Ni.adp\"/file = \"$WORK/no_uw.adp\"}" "case.toml" "potential.file" \
  "no_uw.adp:23007:" "ADP dipole function u(r) of Ni-Ni"
sed '4s/^1 Ni/2 Ni/' "$adp" > "$WORK/count.adp"
expect_error "${case/file = \"Ni.adp\"/file = \"$WORK/count.adp\"}" "count.adp:4:" "N = 2 and 1 names"
expect_error "${case//\"Ni\"\]/\"Cu\"]}" "potential.elements" "'Cu' is not in" "Ni.adp (it has: Ni)"
echo "md_adp: ok"
