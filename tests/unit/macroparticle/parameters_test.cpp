// The pair law derived from the atoms (macroparticle/parameters): the consistent eqs 5, 10–15 of
// Saitoh et al., Table 1 from eq 15, and the elastic constants of the nearest-neighbour fcc
// packing (docs/theory/macroparticle.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/macroparticle/parameters.hpp"

namespace shockfield::macroparticle {
namespace {

using units::si::amu;
using units::si::eV;

// Kittel, Introduction to Solid State Physics (8th ed.), Table 3.1 (cohesive energies) and
// Table 1.3/CRC (densities): Al 3.39 eV, 2.70 g/cm³, 26.9815 u; Cu 3.49 eV, 8.96 g/cm³, 63.546 u.
struct Metal {
  double e0_eV, density, mass_u;
};
constexpr Metal kAl{3.39, 2700.0, 26.9815};
constexpr Metal kCu{3.49, 8960.0, 63.546};

PairLawInput input(const Metal& m, double p, double q, double r0 = 1e-3) {
  PairLawInput in;
  in.cohesive_energy = m.e0_eV * eV;
  in.density = m.density;
  in.atomic_mass = m.mass_u * amu;
  in.r0 = r0;
  in.p = p;
  in.q = q;
  return in;
}

// Table 1 of Saitoh et al. as printed: p, q, E_Al, E_Cu (GPa).
struct Row {
  double p, q, al, cu;
};
constexpr Row kTable1[] = {{3, 9, 51.6, 76.2}, {4, 8, 61.1, 90.4}, {4, 9, 68.8, 101.6}, {4, 10, 76.4, 112.9},
                           {5, 9, 95.5, 117.2}};

// The e0 that fits rows 1–4 of one column best (least squares of E = c·pq·e0: e0 ∝ Σ E pq / Σ (pq)²).
double fitted_e0(const Metal& m, bool copper) {
  double num = 0, den = 0;
  for (int k = 0; k < 4; ++k) {
    const Row& r = kTable1[k];
    const double per_e0 = youngs_eq15(m.density, m.mass_u * amu, 1.0, r.p, r.q);
    num += (copper ? r.cu : r.al) * 1e9 * per_e0;
    den += per_e0 * per_e0;
  }
  return num / den;
}

TEST(MacroparticleTable1, Eq15WithKittelCohesiveEnergiesGivesRowsOneToFourWithinTwoPercent) {
  // Tolerance 1.5%: the paper does not say which e0, ρ and m it used; Kittel's e0 puts Al 1.0%
  // above and Cu 0.8% below the printed rows (a ~1% difference in e0/m).
  for (int k = 0; k < 4; ++k) {
    const Row& r = kTable1[k];
    EXPECT_NEAR(youngs_eq15(kAl.density, kAl.mass_u * amu, kAl.e0_eV * eV, r.p, r.q) / 1e9 / r.al, 1.0, 0.015) << k;
    EXPECT_NEAR(youngs_eq15(kCu.density, kCu.mass_u * amu, kCu.e0_eV * eV, r.p, r.q) / 1e9 / r.cu, 1.0, 0.015) << k;
  }
}

TEST(MacroparticleTable1, OneCohesiveEnergyPerMetalReproducesRowsOneToFourToTheirPrintedDigits) {
  const double e0_al = fitted_e0(kAl, false), e0_cu = fitted_e0(kCu, true);
  EXPECT_NEAR(e0_al / eV, 3.355, 0.005);  // the e0 the printed Al column implies
  EXPECT_NEAR(e0_cu / eV, 3.518, 0.005);
  for (int k = 0; k < 4; ++k) {
    const Row& r = kTable1[k];
    // 0.2%: the printed values have three significant digits (half a unit in the last is 0.1%).
    EXPECT_NEAR(youngs_eq15(kAl.density, kAl.mass_u * amu, e0_al, r.p, r.q) / 1e9 / r.al, 1.0, 0.002) << k;
    EXPECT_NEAR(youngs_eq15(kCu.density, kCu.mass_u * amu, e0_cu, r.p, r.q) / 1e9 / r.cu, 1.0, 0.002) << k;
  }
}

TEST(MacroparticleTable1, TheFifthRowCannotComeFromEq15) {
  // Eq 15 makes E_Cu/E_Al = (ρ e0/m)_Cu/(ρ e0/m)_Al the same for every (p, q); rows 1–4 give
  // 1.477–1.480, row 5 gives 117.2/95.5 = 1.227: no pair of e0 values and no (p, q) fit it.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(kTable1[k].cu / kTable1[k].al, 1.478, 0.002) << k;
  EXPECT_NEAR(kTable1[4].cu / kTable1[4].al, 1.227, 0.001);
  // The Al entry 95.5 is pq = 50 (p = 5, q = 10) with the column's e0, not pq = 45.
  const double e0_al = fitted_e0(kAl, false);
  EXPECT_NEAR(youngs_eq15(kAl.density, kAl.mass_u * amu, e0_al, 5, 10) / 1e9 / 95.5, 1.0, 0.002);
  EXPECT_GT(std::abs(youngs_eq15(kAl.density, kAl.mass_u * amu, e0_al, 5, 9) / 1e9 / 95.5 - 1.0), 0.09);
  // The Cu entry 117.2 would need pq = 41.5 with the Cu column's e0: no integer pair.
  const double per_pq = youngs_eq15(kCu.density, kCu.mass_u * amu, fitted_e0(kCu, true), 1, 1) / 1e9;
  EXPECT_NEAR(117.2 / per_pq, 41.5, 0.1);
}

TEST(MacroparticlePairLaw, EnergyMinimumAtR0WithDepthOneSixthOfTheParticleEnergy) {
  const PairLaw law = derive_pair_law(input(kAl, 4, 9, 0.592e-3));
  const double scale = law.G / std::pow(law.r0, law.p + 1);  // the size of either force term at r0
  EXPECT_LT(std::abs(law.force(law.r0)) / scale, 1e-13);
  EXPECT_NEAR(law.energy(law.r0) / law.bond_energy, -1.0, 1e-13);
  EXPECT_NEAR(law.particle_energy / law.bond_energy, 6.0, 1e-13);
  EXPECT_GT(law.force(0.99 * law.r0), 0.0);  // repulsive inside r0
  EXPECT_LT(law.force(1.01 * law.r0), 0.0);  // attractive outside
  // Eq 11: a particle holds ρ·(π r0³/6)/0.74 of matter.
  EXPECT_NEAR(law.particle_mass / (kAl.density * std::numbers::pi * std::pow(law.r0, 3) / 6.0 / 0.74), 1.0, 1e-13);
  EXPECT_NEAR(law.atoms_per_particle, 8.85e18, 0.01e18);
}

TEST(MacroparticlePairLaw, ForceIsMinusTheEnergyDerivative) {
  const PairLaw law = derive_pair_law(input(kCu, 3, 9));
  for (double s : {0.9, 0.97, 1.0, 1.03, 1.15, 1.3}) {
    const double r = s * law.r0, h = 1e-6 * law.r0;
    const double fd = -(law.energy(r + h) - law.energy(r - h)) / (2 * h);
    // Central difference: error O(h² φ''') ≈ 1e-12 relative; 1e-7 leaves room for round-off
    // of φ (≈ 1e-16·D/h·r0 ≈ 1e-10 relative to the force scale D/r0).
    EXPECT_NEAR(fd, law.force(r), 1e-7 * law.bond_energy / law.r0) << s;
  }
  // And the curvature at r0 is k = D pq/r0².
  const double h = 1e-4 * law.r0;
  const double k_fd = (law.energy(law.r0 + h) - 2 * law.energy(law.r0) + law.energy(law.r0 - h)) / (h * h);
  EXPECT_NEAR(k_fd / law.stiffness, 1.0, 1e-6);
}

TEST(MacroparticlePairLaw, Eq14AndEq15AreTheSameYoungsModulus) {
  for (const Row& r : kTable1) {
    const PairLaw law = derive_pair_law(input(kAl, r.p, r.q, 2e-3));
    EXPECT_NEAR(law.youngs_eq14() / law.youngs_eq15(), 1.0, 1e-12);
  }
}

TEST(MacroparticlePairLaw, AtomsPerParticleAndLatticeConstantRoutesAgree) {
  PairLawInput in = input(kAl, 4, 9, 0.7e-3);
  const PairLaw a = derive_pair_law(in);
  in.r0.reset();
  in.atoms_per_particle = a.atoms_per_particle;
  const PairLaw b = derive_pair_law(in);
  EXPECT_NEAR(b.r0 / a.r0, 1.0, 1e-13);
  // ρ from a0 and m (fcc: ρ = 4m/a0³): Al a0 = 4.0495 Å gives 2699 kg/m³.
  in.density.reset();
  in.lattice_constant = 4.0495e-10;
  const PairLaw c = derive_pair_law(in);
  EXPECT_NEAR(c.density, 2698.8, 0.5);
}

TEST(MacroparticlePairLaw, CubicConstantsObeyTheCauchyRelationAndGiveOneThirdAlongACubeAxis) {
  const PairLaw law = derive_pair_law(input(kAl, 4, 9));
  EXPECT_DOUBLE_EQ(law.c12(), law.c44());
  EXPECT_NEAR(law.c11() / law.c12(), 2.0, 1e-14);
  EXPECT_NEAR(law.poisson_lattice_001(), 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(law.youngs_lattice_001() / law.youngs_eq15(), 4.0 * std::numbers::sqrt2 / 3.0, 1e-12);
}

TEST(MacroparticlePairLaw, RefusesInputWithoutAMinimumOrSize) {
  auto refuses = [](PairLawInput in, const char* word) {
    try {
      derive_pair_law(in);
      ADD_FAILURE() << "accepted input that should be refused: " << word;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  refuses(input(kAl, 9, 4), "no energy minimum");
  refuses(input(kAl, 4, 4), "no energy minimum");
  refuses(input(kAl, 0, 4), "p = 0");
  refuses(input(kAl, 4, 9, 0.0), "r0");
  refuses(input(kAl, 4, 9, -1e-3), "r0");
  PairLawInput bcc = input(kAl, 4, 9);
  bcc.crystal = "bcc";
  refuses(bcc, "fcc");
  PairLawInput both = input(kAl, 4, 9);
  both.atoms_per_particle = 1e18;
  refuses(both, "exactly one of r0");
}

}  // namespace
}  // namespace shockfield::macroparticle
