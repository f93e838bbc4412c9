#pragma once
// Thermodynamic non-equilibrium (TNE) measures of the DBM (Xu et al. 2015, §2.3.4, §4.3):
//   Δ_n  = M_n(f) − M_n^eq(f^eq)        (eq. 27), moments with v,
//   Δ*_n = M*_n(f) − M*_n^eq(f^eq)       central moments with v − u (TNE only),
// for n = 2, 3, (3,1), (4,2), as fields and domain averages, and the TNE strength
//   D = sqrt(|Δ*_2|² + |Δ*_3|² + |Δ*_(3,1)|² + |Δ*_(4,2)|²)   (eq. 35),
// with |·| the Frobenius norm of the full symmetric tensor. The measures are linear in f − g for
// any reference g, so the same kernel gives Δ^F = M(τI) (eq. 29) and Δ^G (eq. 31) of the
// multiphase model.
#include <array>
#include <string>
#include <vector>

#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

/// Independent components: Δ2 xx xy yy, Δ3 xxx xxy xyy yyy, Δ(3,1) x y, Δ(4,2) xx xy yy.
inline constexpr int kTneComponents = 12;
extern const std::array<std::string, kTneComponents> kTneNames;

struct TneFields {
  /// [component][interior cell i + nx·j]
  std::array<std::vector<double>, kTneComponents> raw, central;
  std::vector<double> strength;  // D per cell from the central measures (eq. 35)
  std::array<double, kTneComponents> mean_raw{}, mean_central{};
  double mean_strength = 0.0;  // domain average of D
};

/// TNE measures of d = f − g (Q arrays of lattice.cells(), interior cells used) with the flow
/// velocity of each interior cell (macro[i + nx·j]).
TneFields tne_measures(const VelocityModel& model, const Lattice& lattice,
                       const std::vector<double>& difference,
                       const std::vector<Macro>& macro);

class Simulation;
/// Δ and Δ* of a simulation's current state (g = f^eq).
TneFields tne_measures(const Simulation& simulation);

}  // namespace shockfield::dbm
