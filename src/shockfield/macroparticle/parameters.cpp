#include "shockfield/macroparticle/parameters.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"

namespace shockfield::macroparticle {

namespace {
void require_positive(double v, const char* name, const char* what) {
  if (!(v > 0) || !std::isfinite(v))
    throw InputError(fmt::format("pair law: {} = {} is not a valid {} (expected a finite value > 0)", name, v, what));
}
}  // namespace

double youngs_eq15(double density, double atomic_mass, double cohesive_energy, double p, double q) {
  return std::numbers::pi * density * p * q * cohesive_energy / (72.0 * kFccPacking * atomic_mass);  // eq 15
}

PairLaw derive_pair_law(const PairLawInput& in) {
  if (in.crystal != "fcc")
    throw InputError(fmt::format("pair law: crystal \"{}\" is not modelled: eqs 10–15 are written for fcc "
                                 "(12 neighbours, packing 0.74)", in.crystal));
  if (!(in.p > 0)) throw InputError(fmt::format("pair law: p = {} gives no attraction (expected p > 0)", in.p));
  if (!(in.q > in.p))
    throw InputError(fmt::format("pair law: q = {} ≤ p = {} gives no energy minimum: the repulsion r^-q must "
                                 "fall faster than the attraction r^-p (expected q > p, as in Table 1)", in.q, in.p));
  require_positive(in.cohesive_energy, "cohesive_energy", "cohesive energy");
  PairLaw law;
  law.p = in.p;
  law.q = in.q;
  law.cohesive_energy = in.cohesive_energy;
  // fcc: four atoms per cubic cell, ρ = 4m/a0³ links the three.
  const int given = in.lattice_constant.has_value() + in.density.has_value() + in.atomic_mass.has_value();
  if (given < 2)
    throw InputError("pair law: give two of lattice_constant, density and atomic_mass (fcc: ρ = 4m/a0³)");
  if (given == 3)
    throw InputError("pair law: lattice_constant, density and atomic_mass are all given; fcc ties them "
                     "(ρ = 4m/a0³): give two");
  if (in.lattice_constant) require_positive(*in.lattice_constant, "lattice_constant", "lattice constant");
  if (in.density) require_positive(*in.density, "density", "density");
  if (in.atomic_mass) require_positive(*in.atomic_mass, "atomic_mass", "atomic mass");
  if (!in.density) {
    law.atomic_mass = *in.atomic_mass;
    law.density = 4.0 * law.atomic_mass / std::pow(*in.lattice_constant, 3);
  } else if (!in.atomic_mass) {
    law.density = *in.density;
    law.atomic_mass = law.density * std::pow(*in.lattice_constant, 3) / 4.0;
  } else {
    law.density = *in.density;
    law.atomic_mass = *in.atomic_mass;
  }
  if (in.r0.has_value() == in.atoms_per_particle.has_value())
    throw InputError("pair law: give exactly one of r0 and atoms_per_particle");
  const double pi = std::numbers::pi;
  // Eq 11: N_atom = (ρπ/6)(r0³/m)/0.74, or r0 from N_atom.
  if (in.r0) {
    require_positive(*in.r0, "r0", "particle spacing");
    law.r0 = *in.r0;
    law.atoms_per_particle = law.density * pi / 6.0 * std::pow(law.r0, 3) / law.atomic_mass / kFccPacking;
  } else {
    require_positive(*in.atoms_per_particle, "atoms_per_particle", "atom count");
    law.atoms_per_particle = *in.atoms_per_particle;
    law.r0 = std::cbrt(6.0 * kFccPacking * law.atomic_mass * law.atoms_per_particle / (law.density * pi));
  }
  law.particle_energy = law.atoms_per_particle * law.cohesive_energy;  // eq 10
  law.bond_energy = law.particle_energy / 6.0;
  law.f = law.bond_energy * law.p * law.q / (law.q - law.p);  // eq 13 (q − p: see the header)
  law.G = law.f * std::pow(law.r0, law.p);
  law.H = law.f * std::pow(law.r0, law.q);                    // eq 13, second line with r0^q
  law.particle_mass = law.atoms_per_particle * law.atomic_mass;
  law.stiffness = law.bond_energy * law.p * law.q / (law.r0 * law.r0);
  return law;
}

double PairLaw::energy(double r) const { return -G / (p * std::pow(r, p)) + H / (q * std::pow(r, q)); }  // eq 5

double PairLaw::force(double r) const { return -G / std::pow(r, p + 1) + H / std::pow(r, q + 1); }  // −dφ/dr

double PairLaw::youngs_eq14() const { return stiffness / (2.0 * r0); }

double PairLaw::youngs_eq15() const { return macroparticle::youngs_eq15(density, atomic_mass, cohesive_energy, p, q); }

double PairLaw::c11() const { return std::numbers::sqrt2 * stiffness / r0; }

double PairLaw::c12() const { return stiffness / (std::numbers::sqrt2 * r0); }

double PairLaw::youngs_lattice_001() const {
  return (c11() - c12()) * (c11() + 2.0 * c12()) / (c11() + c12());
}

double PairLaw::poisson_lattice_001() const { return c12() / (c11() + c12()); }

double PairLaw::max_frequency() const { return std::sqrt(8.0 * stiffness / particle_mass); }

double PairLaw::stable_time_step() const { return 2.0 / max_frequency(); }

}  // namespace shockfield::macroparticle
