#pragma once
// Ordinary peridynamic force laws, each a small type with its parameters and one evaluation
// function for the scalar bond force t per unit neighbour volume (LPS: `force`; PMB, linear in
// the stretch: `bond_constant`, see LinearInStretch): point i feels
// t·V_j·β·(y_j − y_i)/|y_j − y_i| from bond i→j. Written to match LAMMPS peri/pmb and peri/lps
// (pair_peri_pmb.cpp, pair_peri_lps.cpp) term by term.
//
//   PMB (Silling & Askari 2005):   t = c·s,  s = (|Y| − r0)/r0
//   LPS (Silling et al. 2007, linear peridynamic solid), with weighted volume
//   m_i = Σ ω r0² V β and dilatation θ_i = (3/m_i) Σ ω r0 e V β (e = |Y| − r0):
//       t = (3K − 5G)(ω θ_i/m_i + ω θ_j/m_j)·r0 + 15G(ω/m_i + ω/m_j)·e
//   in 3D, with its 2D (plane strain) and 1D (uniaxial strain) forms below.
//
// Critical-stretch damage (LAMMPS semantics): bond i→j breaks when s > min(s0_i, s0_j), with
// s0 from the previous step; then s0_i = s00 − α·min_j s over i's intact bonds (max of
// s00 − α·s). s0 starts infinite and becomes s00 at the setup force evaluation.
#include <cmath>
#include <concepts>
#include <numbers>

namespace shockfield::pd {

/// What a bond law sees of one bond i→j.
struct BondTerms {
  double r0;       ///< reference length [m]
  double e;        ///< extension |Y| − r0 [m]
  double omega;    ///< ω⟨ξ⟩
  double theta_i;  ///< dilatation of i (LPS)
  double theta_j;
  double m_i;      ///< weighted volume of i (LPS)
  double m_j;
};

struct PmbModel {
  static constexpr bool uses_dilatation = false;
  double micromodulus = 0.0;  ///< c [N/m^6 in 3D]
  /// t = c·s is evaluated as t·V_j·β = k_b·s, s = e/r0, with the per-bond constant
  /// k_b = (c·V_j)·β fixed at construction: LAMMPS's rk = (kspring·vfrac[j])·vfrac_scale·stretch
  /// with its roundings (pair_peri_pmb.cpp).
  double bond_constant(double neighbor_volume, double volume_scale) const {
    return micromodulus * neighbor_volume * volume_scale;
  }
  /// ∂t/∂e of the bond alone (for the stable step).
  double stiffness(const BondTerms& b) const { return micromodulus / b.r0; }
  /// Energy density at i: ¼·c·s²·r0 per unit neighbour volume from each bond (half the pair
  /// micropotential ½·c·s²·r0, whose derivative in |Y| is t), nothing from the point.
  double bond_energy(const BondTerms& b) const { return 0.25 * micromodulus * b.e * b.e / b.r0; }
  double point_energy(double /*theta*/) const { return 0.0; }
  /// c of the short-range contact force 15c (contact.hpp): LAMMPS peri/pmb uses the bond's own.
  double contact_micromodulus(double /*horizon*/) const { return micromodulus; }
};

// LPS in d = 1, 2, 3 dimensions, one construction: W = (κ_d/2)θ² + (α_d/2) Σ ω (e^d)² V β with
// θ = (d/m) Σ ω x e V β and e^d = e − θx/d, so that the scalar force state of i is
//   t_i = (d·κ_d − B_d/d)·θ_i·ω·x/m_i + B_d·ω·e/m_i,   B_d = m·α_d,
// and the bond force is t_i + t_j (the two terms of `force`). Homogeneous strain gives e^d = 0 and
// the local energy, so κ_d is the d-dimensional bulk modulus of the body's constraint:
//   3D: κ = K, B = 15G (Silling et al. 2007; LAMMPS peri/lps): A = 3K − 5G;
//   2D plane strain (the pd convention: the missing direction held): κ = K + G/3 = λ + G and
//       B = 8G (the 2D LPS of Le, Chan & Schwartz, IJNME 98 (2014) 547): A = 2K − 10G/3;
//       longitudinal waves then travel at √((K + 4G/3)/ρ) and shear waves at √(G/ρ);
//   2D plane stress (`plane = "stress"`): κ = 9KG/(3K + 4G) = E/(2(1 − ν)), the same B = 8G:
//       longitudinal waves at √(E/((1 − ν²)ρ)), the plate speed;
//   1D uniaxial strain: κ = K + 4G/3 (there is no shear to carry) and B = 3G, the d(d+2)G
//       pattern of 15G and 8G (our choice: it vanishes on homogeneous strain, so the wave speed
//       is √((K + 4G/3)/ρ) whatever B is, and it stiffens the zig-zag mode u_j = (−1)^j, which
//       has θ = 0 at every point and would otherwise cost no energy): A = K + 4G/3 − 3G.
struct LpsModel {
  static constexpr bool uses_dilatation = true;
  double bulk = 0.0;   ///< K [Pa]
  double shear = 0.0;  ///< G [Pa]
  int dim = 3;         ///< d of the body
  bool plane_stress = false;  ///< 2D only: κ_2 = 9KG/(3K + 4G) (plane stress) instead of K + G/3
  /// d of θ = (d/m) Σ ω x e V β.
  double dilatation_factor() const { return static_cast<double>(dim); }
  /// A = d·κ_d − B_d/d.
  double dilatation_modulus() const {
    if (dim == 3) return 3.0 * bulk - 5.0 * shear;
    if (dim == 2) {  // 2κ_2 − B_2/2 = 2κ_2 − 4G, κ_2 the 2D bulk modulus of the constraint
      const double kappa = plane_stress ? 9.0 * bulk * shear / (3.0 * bulk + 4.0 * shear) : bulk + shear / 3.0;
      return 2.0 * kappa - 4.0 * shear;
    }
    return bulk + 4.0 / 3.0 * shear - 3.0 * shear;
  }
  /// B_d.
  double deviatoric_modulus() const { return dim == 3 ? 15.0 * shear : dim == 2 ? 8.0 * shear : 3.0 * shear; }
  double force(const BondTerms& b) const {
    return dilatation_modulus() * (b.omega * b.theta_i / b.m_i + b.omega * b.theta_j / b.m_j) * b.r0 +
           deviatoric_modulus() * (b.omega / b.m_i + b.omega / b.m_j) * b.e;
  }
  double stiffness(const BondTerms& b) const { return deviatoric_modulus() * (b.omega / b.m_i + b.omega / b.m_j); }
  /// W_i = (κ_d/2)θ_i² + Σ_j (B_d/(2m_i)) ω (e − θ_i x/d)² V_j β: the bond part per unit neighbour
  /// volume, then the point part (κ_d = (A + B_d/d)/d).
  double bond_energy(const BondTerms& b) const {
    const double ed = b.e - b.theta_i * b.r0 / dim;
    return 0.5 * deviatoric_modulus() * b.omega * ed * ed / b.m_i;
  }
  double point_energy(double theta) const {
    const double kappa = (dilatation_modulus() + deviatoric_modulus() / dim) / dim;
    return 0.5 * kappa * theta * theta;
  }
  /// c of the short-range contact force 15c (contact.hpp). LAMMPS peri/lps: the PMB micromodulus
  /// of the same bulk modulus, 18K/(πδ⁴) (Silling & Askari 2005), i.e. the bond-based body whose
  /// longitudinal modulus is M = c·πδ⁴/10 = 9K/5. In 1D and 2D (not in LAMMPS) the micromodulus
  /// with the same M = 9K/5: M = c·πδ³/8 (2D), c·δ²/2 (1D), so 14.4K/(πδ³) and 3.6K/δ².
  double contact_micromodulus(double horizon) const {
    const double d = horizon;
    if (dim == 3) return 18.0 * bulk / (std::numbers::pi * d * d * d * d);
    if (dim == 2) return 14.4 * bulk / (std::numbers::pi * d * d * d);
    return 3.6 * bulk / (d * d);
  }
  /// Coefficient of the dilatation coupling (for the stable step).
  double dilatation_coupling() const { return std::abs(dilatation_modulus()); }
};

/// A law whose t·V_j·β is a per-bond constant times the stretch (PMB): the bond loop precomputes
/// the constants and runs its divisions packed (bond_force.cpp).
template <class Model>
concept LinearInStretch = requires(const Model& model, double v) {
  { model.bond_constant(v, v) } -> std::convertible_to<double>;
};

struct CriticalStretch {
  double s00 = 0.0;    ///< critical stretch; <= 0 disables breaking
  double alpha = 0.0;  ///< α, s0 = s00 − α·s_min
  bool enabled() const { return s00 > 0.0; }
};

}  // namespace shockfield::pd
