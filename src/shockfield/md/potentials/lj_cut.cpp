#include "shockfield/md/potentials/lj_cut.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::md::potentials {

std::vector<LjCoeff> mix_lj(int ntypes, const std::vector<std::optional<LjCoeff>>& set) {
  const auto n = static_cast<std::size_t>(ntypes);
  std::vector<LjCoeff> out(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (set[i * n + j]) {
        out[i * n + j] = *set[i * n + j];
        continue;
      }
      const auto& a = set[i * n + i];
      const auto& b = set[j * n + j];
      if (!a || !b)
        throw InputError(fmt::format(
            "lj/cut: no coefficients for type pair {} {} and none for type {} to mix from", i + 1,
            j + 1, a ? j + 1 : i + 1));
      out[i * n + j] = {std::sqrt(a->epsilon * b->epsilon), std::sqrt(a->sigma * b->sigma),
                        std::sqrt(a->cutoff * b->cutoff)};
    }
  }
  return out;
}

LjCutPotential::LjCutPotential(int ntypes, const std::vector<LjCoeff>& coeff, bool shift)
    : ntypes_(ntypes) {
  for (const auto& c : coeff) {
    const double s6 = std::pow(c.sigma, 6.0), s12 = std::pow(c.sigma, 12.0);
    Terms t{c.cutoff * c.cutoff, 48.0 * c.epsilon * s12, 24.0 * c.epsilon * s6,
            4.0 * c.epsilon * s12, 4.0 * c.epsilon * s6, 0.0};
    if (shift && c.cutoff > 0.0) {
      const double ratio = c.sigma / c.cutoff;
      t.offset = 4.0 * c.epsilon * (std::pow(ratio, 12.0) - std::pow(ratio, 6.0));
    }
    terms_.push_back(t);
    cutoff_ = std::max(cutoff_, c.cutoff);
  }
}

void LjCutPotential::check_types(const Atoms& atoms) const {
  if (atoms.ntypes() != ntypes_)
    throw InputError(fmt::format("pair style lj/cut: coefficients for {} atom types, the atoms have {}",
                                 ntypes_, atoms.ntypes()));
}

void LjCutPotential::compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) {
  const Terms* terms = terms_.data();
  const int* type = atoms.type.data();
  const int n = ntypes_;
  auto kernel = [terms, type, n](int i, int j, double rsq, double& fpair, double& energy) {
    const Terms& t = terms[type[i] * n + type[j]];
    if (rsq >= t.cutsq) return false;
    const double r2inv = 1.0 / rsq;
    const double r6inv = r2inv * r2inv * r2inv;
    fpair = r6inv * (t.lj1 * r6inv - t.lj2) * r2inv;
    energy = r6inv * (t.lj3 * r6inv - t.lj4) - t.offset;
    return true;
  };
  accumulate_pair_forces(atoms, list, kernel, out, scratch_);
}

}  // namespace shockfield::md::potentials
