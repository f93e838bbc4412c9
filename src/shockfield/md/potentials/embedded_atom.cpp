#include "shockfield/md/potentials/embedded_atom.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/core/error.hpp"

namespace shockfield::md::potentials {

void fill_eam_density_row(const EamTables& t, int ti, int tj, std::size_t m, double* row) {
  const auto& into_j = t.rhor[static_cast<std::size_t>(t.rhor_index(ti, tj))][m];
  const auto& into_i = t.rhor[static_cast<std::size_t>(t.rhor_index(tj, ti))][m];
  std::copy(into_i.begin() + 3, into_i.end(), row);
  std::copy(into_j.begin() + 3, into_j.end(), row + 4);
}

void fill_eam_force_row(const EamTables& t, int ti, int tj, std::size_t m, double* row) {
  const auto& into_j = t.rhor[static_cast<std::size_t>(t.rhor_index(ti, tj))][m];
  const auto& into_i = t.rhor[static_cast<std::size_t>(t.rhor_index(tj, ti))][m];
  const auto& z2r = t.z2r[static_cast<std::size_t>(t.z2r_index(ti, tj))][m];
  std::copy(into_j.begin(), into_j.begin() + 3, row);
  std::copy(into_i.begin(), into_i.begin() + 3, row + 3);
  std::copy(z2r.begin(), z2r.end(), row + 6);
}

void EmbeddedAtomPotential::check_types(const Atoms& atoms) const {
  if (atoms.ntypes() != tables_.ntypes)
    throw InputError(fmt::format("pair style {}: the potential maps {} atom types, the atoms have {}",
                                 style_, tables_.ntypes, atoms.ntypes()));
  for (std::size_t t = 0; t < atoms.type_names.size() && t < type_names_.size(); ++t) {
    const auto& have = atoms.type_names[t];
    if (!have.empty() && !type_names_[t].empty() && have != type_names_[t])
      throw InputError(fmt::format("pair style {}: atom type {} is {} but the potential maps it to {}",
                                   style_, t + 1, have, type_names_[t]));
  }
}

}  // namespace shockfield::md::potentials
