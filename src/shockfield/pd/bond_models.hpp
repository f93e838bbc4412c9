#pragma once
// Ordinary peridynamic force laws, each a small type with its parameters and one evaluation
// function returning the scalar bond force t per unit neighbour volume: point i feels
// t·V_j·β·(y_j − y_i)/|y_j − y_i| from bond i→j. Written to match LAMMPS peri/pmb and peri/lps
// (pair_peri_pmb.cpp, pair_peri_lps.cpp) term by term.
//
//   PMB (Silling & Askari 2005):   t = c·s,  s = (|Y| − r0)/r0
//   LPS (Silling et al. 2007, linear peridynamic solid), with weighted volume
//   m_i = Σ ω r0² V β and dilatation θ_i = (3/m_i) Σ ω r0 e V β (e = |Y| − r0):
//       t = (3K − 5G)(ω θ_i/m_i + ω θ_j/m_j)·r0 + 15G(ω/m_i + ω/m_j)·e
//
// Critical-stretch damage (LAMMPS semantics): bond i→j breaks when s > min(s0_i, s0_j), with
// s0 from the previous step; then s0_i = s00 − α·min_j s over i's intact bonds (max of
// s00 − α·s). s0 starts infinite and becomes s00 at the setup force evaluation.
#include <cmath>

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
  double force(const BondTerms& b) const { return micromodulus * b.e / b.r0; }
  /// ∂t/∂e of the bond alone (for the stable step).
  double stiffness(const BondTerms& b) const { return micromodulus / b.r0; }
};

struct LpsModel {
  static constexpr bool uses_dilatation = true;
  double bulk = 0.0;   ///< K [Pa]
  double shear = 0.0;  ///< G [Pa]
  double force(const BondTerms& b) const {
    return (3.0 * bulk - 5.0 * shear) * (b.omega * b.theta_i / b.m_i + b.omega * b.theta_j / b.m_j) * b.r0 +
           15.0 * shear * (b.omega / b.m_i + b.omega / b.m_j) * b.e;
  }
  double stiffness(const BondTerms& b) const { return 15.0 * shear * (b.omega / b.m_i + b.omega / b.m_j); }
  /// Coefficient of the dilatation coupling (for the stable step).
  double dilatation_coupling() const { return std::abs(3.0 * bulk - 5.0 * shear); }
};

struct CriticalStretch {
  double s00 = 0.0;    ///< critical stretch; <= 0 disables breaking
  double alpha = 0.0;  ///< α, s0 = s00 − α·s_min
  bool enabled() const { return s00 > 0.0; }
};

}  // namespace shockfield::pd
