#pragma once
// Common statistics of a field's non-void cells (Xu et al. 2015, §3.1, scheme (i): "the mean value and
// fluctuations"): mean, standard deviation, skewness, kurtosis, histogram.
#include <cstddef>
#include <vector>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis {

struct Moments {
  std::size_t count = 0;  ///< non-void cells
  double mean = 0.0;
  double std = 0.0;       ///< population standard deviation √⟨δΘ²⟩
  double skewness = 0.0;  ///< ⟨δΘ³⟩ / σ³ (0 for a constant field)
  double kurtosis = 0.0;  ///< ⟨δΘ⁴⟩ / σ⁴, not excess: 3 for a Gaussian (0 for a constant field)
};

/// Moments of the non-void cells (two passes, in cell order: independent of threads).
Moments moments(const GridFieldView& field);

struct Histogram {
  std::vector<double> edges;        ///< bins + 1 increasing edges
  std::vector<std::size_t> counts;  ///< cells per bin; the last bin includes its upper edge
};

/// `bins` equal bins over [lo, hi] (lo < hi); values outside are not counted.
Histogram histogram(const GridFieldView& field, std::size_t bins, double lo, double hi);
/// `bins` equal bins over the range of the non-void values.
Histogram histogram(const GridFieldView& field, std::size_t bins);

}  // namespace shockfield::analysis
