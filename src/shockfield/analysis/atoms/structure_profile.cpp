#include "shockfield/analysis/atoms/structure_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

std::vector<std::pair<std::string, std::vector<ProfileBin>>> StructureProfile::per_method(
    const AtomFrame& frame, const StructureAnalysisResult& r, const std::vector<double>& value) const {
  std::vector<std::pair<std::string, std::vector<ProfileBin>>> out;
  for (const auto& [name, result] : {std::pair{"cna", &r.cna}, std::pair{"acna", &r.adaptive_cna}})
    if (*result) out.emplace_back(name, compute(frame, (*result)->structure, value));
  if (r.bond_pairs) out.emplace_back("bpa", compute(frame, r.bond_pairs->structure, value));
  if (out.empty()) out.emplace_back("", compute(frame, std::vector<Structure>(frame.size(), Structure::other), value));
  return out;
}

std::vector<ProfileBin> StructureProfile::compute(const AtomFrame& frame, const std::vector<Structure>& structure,
                                                  const std::vector<double>& value) const {
  if (axis < 0 || axis > 2) throw InputError(fmt::format("structure profile: axis {} is not 0, 1 or 2", axis));
  // In a tilted cell x and y bin the fractional coordinate s (slabs parallel to the cell face the
  // other two edges span, all of one volume; along z, s·lz = z − zlo, only c has a z component).
  const bool fractional = frame.box.triclinic() && axis != 2;
  const double length = frame.box.length()[axis];
  if (!(width > 0) || !std::isfinite(width) || length / width > 1e6)
    throw InputError(fmt::format("structure profile: the bin width must be > 0 and give at most 10^6 bins over the {:.6g} Å box "
                                 "(got {})", length, width));
  if (structure.size() != frame.size() || (!value.empty() && value.size() != frame.size()))
    throw InputError(fmt::format("structure profile: {} structures and {} values for {} atoms", structure.size(),
                                 value.size(), frame.size()));
  const std::size_t bins = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / width - 1e-9)));
  std::vector<ProfileBin> out(bins);
  for (std::size_t b = 0; b < bins; ++b) {
    out[b].lo = frame.box.lo[axis] + static_cast<double>(b) * width;
    out[b].hi = std::min(out[b].lo + width, frame.box.hi[axis]);
  }
  for (std::size_t i = 0; i < frame.size(); ++i) {
    double x = fractional ? frame.box.to_fractional(frame.positions[i])[axis] * length
                          : frame.positions[i][axis] - frame.box.lo[axis];
    if (frame.box.periodic(axis)) x -= length * std::floor(x / length);
    const auto b = static_cast<std::size_t>(std::clamp(std::floor(x / width), 0.0, static_cast<double>(bins - 1)));
    ProfileBin& bin = out[b];
    ++bin.counts.count[static_cast<std::size_t>(structure_code(structure[i]) - 1)];
    ++bin.counts.total;
    if (!value.empty()) bin.value_sum += value[i];
  }
  return out;
}

ExcessEnergy excess_energy(const std::vector<double>& pe, const std::vector<Structure>& structure, Structure crystal,
                           const double* reference) {
  if (pe.size() != structure.size())
    throw InputError(fmt::format("excess energy: {} energies for {} atoms", pe.size(), structure.size()));
  ExcessEnergy r;
  if (reference) {
    r.reference = *reference;
  } else {
    std::vector<double> crystal_pe;
    for (std::size_t i = 0; i < pe.size(); ++i)
      if (structure[i] == crystal) crystal_pe.push_back(pe[i]);
    if (crystal_pe.empty())
      throw InputError(fmt::format("excess energy: no {} atom to take the crystal's energy from; give the reference energy",
                                   structure_name(crystal)));
    const auto middle = crystal_pe.begin() + static_cast<std::ptrdiff_t>(crystal_pe.size() / 2);
    std::nth_element(crystal_pe.begin(), middle, crystal_pe.end());
    r.reference = *middle;
  }
  r.excess.resize(pe.size());
  for (std::size_t i = 0; i < pe.size(); ++i) r.excess[i] = pe[i] - r.reference;
  return r;
}

ExcessEnergy excess_energy(const std::vector<double>& pe, const StructureAnalysisResult& r, Structure crystal,
                           const double* reference) {
  const std::vector<Structure>* structures = reference_structures(r);
  return excess_energy(pe, structures ? *structures : std::vector<Structure>(pe.size(), crystal), crystal, reference);
}

}  // namespace shockfield::analysis::atoms
