#pragma once
// Structure fractions along an axis — what a shock run turns into, bin by bin behind the front:
// the atoms of a frame binned by their coordinate along `axis` (bins of `width` from the box's lo
// face; atoms outside a shrink-wrapped box fall into the end bins), and per bin the count of each
// structure type, optionally with the mean of a per-atom value (excess energy, CSP).
#include <string>
#include <utility>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/analysis/atoms/structure_types.hpp"

namespace shockfield::analysis::atoms {

struct ProfileBin {
  double lo = 0, hi = 0;  ///< Å
  StructureCounts counts;
  double value_sum = 0;   ///< sum of the per-atom value over the bin's atoms
  double mean_value() const { return counts.total == 0 ? 0.0 : value_sum / static_cast<double>(counts.total); }
};

struct StructureProfile {
  int axis = 2;          ///< 0 x, 1 y, 2 z
  double width = 0;      ///< Å, > 0

  /// InputError when the width is not > 0 or gives more than 10⁶ bins over the box.
  std::vector<ProfileBin> compute(const AtomFrame& frame, const std::vector<Structure>& structure,
                                  const std::vector<double>& value = {}) const;
  /// compute() for the structures of each structure method that ran, in profiles.csv's order
  /// (cna, acna, bpa), with its name; when none ran, one profile of every atom as "other",
  /// named "" (its bins still give the atom counts and the mean value).
  std::vector<std::pair<std::string, std::vector<ProfileBin>>> per_method(const AtomFrame& frame,
                                                                          const StructureAnalysisResult& r,
                                                                          const std::vector<double>& value = {}) const;
};

/// Per-atom excess energy pe − e0 (eV), the defect measure of Xu et al. (2015) §3.2.3: e0 is the
/// given reference or, when absent, the median pe of the atoms whose structure is `crystal`
/// (the crystal's energy at the frame's temperature and pressure). InputError when no atom has
/// that structure or the sizes differ.
ExcessEnergy excess_energy(const std::vector<double>& pe, const std::vector<Structure>& structure, Structure crystal,
                           const double* reference = nullptr);
/// excess_energy with the structures of the frame's first structure method (reference_structures:
/// cna, acna, bpa), or every atom counted as `crystal` when none ran (then a `reference` is needed).
ExcessEnergy excess_energy(const std::vector<double>& pe, const StructureAnalysisResult& r, Structure crystal,
                           const double* reference = nullptr);

}  // namespace shockfield::analysis::atoms
