#pragma once
// The macroscopic pair law of Saitoh et al. derived from the atoms (docs/theory/macroparticle.md):
// a particle of equilibrium spacing r0 on an fcc packing holds N_atom atoms (eq 11), their
// cohesive energy P_atom = N_atom e0 (eq 10) is shared by its 6 bonds (12 neighbours, each bond
// shared by two particles), so each bond is a well of depth D = P_atom/6 at r0. The potential is
// eq 5 with the exponents of the energy, p (attraction) < q (repulsion) as in Table 1:
//   φ(r) = −G/(p r^p) + H/(q r^q),   G = f r0^p,  H = f r0^q,  f = (P_atom/6)·pq/(q − p)
// (eq 13 with its two printing slips mended: H carries r0^q, and f has q − p so that f > 0),
// φ(r0) = −D, φ'(r0) = 0 (the consistent eq 12), φ''(r0) = k = D pq/r0².
// Eq 14 then gives E = k/(2 r0) = πρ pq e0/(72·0.74 m), eq 15. Everything is SI.
#include <optional>
#include <string>

namespace shockfield::macroparticle {

/// The fcc packing fraction the paper uses in eq 11 (π/(3√2) = 0.74048 rounded).
inline constexpr double kFccPacking = 0.74;

/// What derive_pair_law() needs: the atoms' cohesive energy, their crystal and its lattice
/// constant with either the density or the atomic mass (fcc: ρ = 4m/a0³), the particle size as
/// r0 or as atoms per particle, and the two exponents.
struct PairLawInput {
  double cohesive_energy = 0;             ///< e0, J per atom (> 0: the binding energy)
  std::string crystal = "fcc";            ///< the atoms' crystal; only "fcc" is modelled
  std::optional<double> lattice_constant; ///< a0 of the atoms, m
  std::optional<double> density;          ///< ρ, kg/m³
  std::optional<double> atomic_mass;      ///< m, kg
  std::optional<double> r0;               ///< particle spacing, m
  std::optional<double> atoms_per_particle;  ///< N_atom (alternative to r0)
  double p = 4, q = 9;                    ///< attraction and repulsion exponents of φ (eq 5)
};

struct PairLaw {
  double p = 0, q = 0;
  double density = 0;             ///< ρ, kg/m³
  double atomic_mass = 0;         ///< m, kg
  double cohesive_energy = 0;     ///< e0, J
  double r0 = 0;                  ///< m
  double atoms_per_particle = 0;  ///< N_atom, eq 11
  double particle_energy = 0;     ///< P_atom = N_atom e0, eq 10, J
  double bond_energy = 0;         ///< D = P_atom/6, J
  double f = 0;                   ///< eq 13, J
  double G = 0, H = 0;            ///< eq 13, J·m^p and J·m^q
  double particle_mass = 0;       ///< M = N_atom m, kg (eq 1 with eq 11's volume per particle)
  double stiffness = 0;           ///< k = φ''(r0) = D pq/r0², N/m

  /// φ(r), J (eq 5) and −dφ/dr, N (positive: repulsion).
  double energy(double r) const;
  double force(double r) const;
  /// E from eq 14, k/(2 r0), and from eq 15; the same number (eq 15 is eq 14 with eqs 10–13).
  double youngs_eq14() const;
  double youngs_eq15() const;
  /// The cubic elastic constants of the perfect fcc packing with nearest-neighbour bonds only
  /// (central forces at equilibrium, so the Cauchy relation C12 = C44 holds):
  ///   C11 = √2 k/r0, C12 = C44 = k/(√2 r0).
  double c11() const;
  double c12() const;
  double c44() const { return c12(); }
  /// Young's modulus and Poisson's ratio for uniaxial stress along a cube axis [001] (the rod
  /// axis here): E = (C11 − C12)(C11 + 2C12)/(C11 + C12) = (2√2/3) k/r0, ν = C12/(C11 + C12) = 1/3.
  double youngs_lattice_001() const;
  double poisson_lattice_001() const;
  /// Angular frequency of the fastest lattice mode, √(8k/M) (the X-point longitudinal phonon of
  /// the nearest-neighbour fcc lattice), and the velocity-Verlet stability limit 2/ω_max, s.
  double max_frequency() const;
  double stable_time_step() const;
};

/// Derives the pair law; throws InputError naming the parameter when the input has no minimum
/// (q ≤ p or p ≤ 0), a non-positive size or energy, a crystal other than fcc, or gives both or
/// neither of r0 and atoms_per_particle, or neither density nor atomic mass with a0.
PairLaw derive_pair_law(const PairLawInput& in);

/// Eq 15 alone: E = πρ pq e0/(72·0.74 m), Pa.
double youngs_eq15(double density, double atomic_mass, double cohesive_energy, double p, double q);

}  // namespace shockfield::macroparticle
