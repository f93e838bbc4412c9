#!/usr/bin/env bash
# Bad macroparticle case files (docs/macroparticle.md): each is refused before the run with
# exit code 2, a message naming the file, the key and what was expected, and no run folder.
source "$(dirname "$0")/lib.bash"
set -e
base=$(sed -n '/^method/,$p' "$ROOT/tests/cli/cases/macroparticle_tiny.toml")

# Exponents without an energy minimum (q <= p, the convention of eq 5 and Table 1).
expect_error "${base/q = 9/q = 3}" "case.toml" "pair.q" "no energy minimum"
expect_error "${base/q = 9/q = 4}" "pair.q" "no energy minimum"
expect_error "${base/p = 4/p = -4}" "pair.p" "expected a number"
# A rod too thin for its division.
expect_error "${base/n_phi = 4/n_phi = 1}" "specimen.n_phi" "too thin for its division"
# A specimen larger than the particle bound, refused before the packing is made (--check too;
# the fuzz found n_phi = 4000 building 1e9 particles for minutes).
expect_error "${base/n_phi = 4/n_phi = 4000}" "specimen.n_phi" "would hold 5.76e+08 particles; expected at most 1e+08"
# A cylinder's r0 follows from its diameter and n_phi.
expect_error "${base/q = 9/q = 9
r0 = 0.001}" "pair.r0" "follows from specimen.diameter"
# A box needs r0 (or atoms per particle), and r0 must be positive.
boxed="${base/shape = \"cylinder\"/shape = \"box\"
cells = [2, 2, 2]}"
boxed="${boxed/diameter = 0.014            # m/}"
boxed="${boxed/n_phi = 4/}"
boxed="${boxed/n_h = 8/}"
expect_error "$boxed" "pair.r0" "give exactly one of r0"
expect_error "${boxed/q = 9/q = 9
r0 = -0.001}" "pair.r0" "expected a number"
expect_error "${boxed/q = 9/q = 9
r0 = 0.0}" "pair.r0" "expected a number"
# A time step beyond the stable one.
expect_error "${base/dt = 1.0e-7                 # s/dt = 1.0e-5}" "run.dt" "beyond the stable time step"
# Material: two of density, atomic mass and lattice constant.
expect_error "${base/density = 2700.0            # kg\/m³/}" "material.density" "give two of"
expect_error "${base/atomic_mass = 26.9815       # u/atomic_mass = 26.9815
lattice_constant = 4.05e-10}" "material.lattice_constant" "give two of"
expect_error "${base/cohesive_energy = 3.39      # eV per atom (Kittel)/cohesive_energy = 0}" "material.cohesive_energy" "expected a number"
# Loading after a strain, not a step count.
expect_error "${base/dt = 1.0e-7                 # s/dt = 1.0e-7
steps = 10}" "run.steps" "follow from loading.final_strain"
expect_error "${base/seed = 7/sed = 7}" "unknown key" "langevin.sed"
# An imperfection beyond 5 % of r0 (it would no longer be an imperfection of the packing).
expect_error "${base/n_h = 8/n_h = 8
perturbation = 0.1}" "specimen.perturbation" "expected a number"
# The plastic route: 1 to 8 polynomial coefficients, h_1 in [0, 1).
expect_error "${base/hardening = \[0.1\]/hardening = []}" "plasticity.hardening" "1 to 8 polynomial coefficients"
expect_error "${base/hardening = \[0.1\]/hardening = [0.1, 0, 0, 0, 0, 0, 0, 0, 1]}" "plasticity.hardening" "1 to 8 polynomial coefficients"
expect_error "${base/hardening = \[0.1\]/hardening = [1.0, 0.5]}" "plasticity.hardening" "must be in [0, 1)"
# Saturation inside the route (0 < ε_s <= ε_limit - ε_y), a compression yield strain in (0, 0.5].
expect_error "${base/hardening = \[0.1\]/hardening = [0.1]
saturation_strain = 0.0}" "plasticity.saturation_strain" "expected a number"
expect_error "${base/hardening = \[0.1\]/hardening = [0.1]
saturation_strain = 0.5}" "plasticity.saturation_strain" "expected a number"
expect_error "${base/hardening = \[0.1\]/hardening = [0.1]
compression_yield_strain = -0.01}" "plasticity.compression_yield_strain" "expected a number"
