#pragma once
// Influence function ω⟨ξ⟩ of the bond weights (Liu et al. 2025, eqs. 6-8), chosen by name:
//   constant  ω = 1
//   inverse   ω = 1/|ξ|          (LAMMPS peri/lps; units 1/m, which cancel in K⁻¹ and in m)
//   conical   ω = 1 − |ξ|/δ
//   gaussian  ω = exp(−|ξ|²/δ²)
#include <string>
#include <vector>

namespace shockfield::pd {

class Influence {
 public:
  enum class Kind { constant, inverse, conical, gaussian };
  static const std::vector<std::string>& names();
  /// InputError listing the known names when `name` is not one.
  static Influence from_name(const std::string& name);
  explicit Influence(Kind kind = Kind::constant) : kind_(kind) {}

  Kind kind() const { return kind_; }
  /// ω for a bond of reference length r within horizon δ.
  double operator()(double r, double horizon) const;

 private:
  Kind kind_;
};

}  // namespace shockfield::pd
