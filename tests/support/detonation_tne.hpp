#pragma once
// The TNE measures of a detonation profile (examples/dbm_detonation/tne_study.py computes the same
// from run folders; README "TNE against viscosity"), for the tests of the detonation TNE study.
// x is measured from the pressure peak, + toward the fresh gas (the detonation runs along +x).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "shockfield/dbm/detonation.hpp"

namespace shockfield::test {

struct DetonationTne {
  double width = 0.0;        ///< shock width δ = (p_peak − p0) / max|dp/dx| ahead of the peak
  double width_cells = 0.0;  ///< δ / Δx
  double zero_cells = 0.0;   ///< where Δ*_2xx changes sign, coming back from its shock maximum
  double zero_widths = 0.0;  ///< the same in shock widths
  double local_max = 0.0;    ///< local TNE: the largest Δ*_2xx (in the shock)
  double at_peak = 0.0;      ///< Δ*_2xx at the pressure peak
  double global = 0.0;       ///< global TNE: ∫|Δ*_2xx| dx from 0.6 behind the peak to the fresh gas
};

inline DetonationTne detonation_tne(const dbm::DetonationTubeResult& r) {
  const auto& p = r.p;
  const auto& d = r.d2xx;
  const double dx = r.x[1] - r.x[0];
  const std::size_t peak = std::max_element(p.begin(), p.end()) - p.begin();
  double steepest = 0.0;
  for (std::size_t i = peak; i + 1 < p.size(); ++i) steepest = std::max(steepest, (p[i] - p[i + 1]) / dx);
  DetonationTne m;
  m.width = (p[peak] - p.back()) / steepest;
  m.width_cells = m.width / dx;
  const std::size_t top = std::max_element(d.begin(), d.end()) - d.begin();
  std::size_t j = top;
  while (j > 0 && d[j] > 0.0) --j;
  const double x_zero = r.x[j] + dx * d[j] / (d[j] - d[j + 1]);
  m.zero_cells = (x_zero - r.x[peak]) / dx;
  m.zero_widths = (x_zero - r.x[peak]) / m.width;
  m.local_max = d[top];
  m.at_peak = d[peak];
  for (std::size_t i = 0; i < d.size(); ++i)
    if (r.x[i] > r.x[peak] - 0.6) m.global += std::abs(d[i]) * dx;  // why 0.6: tne_study.py WAVE_BEHIND
  return m;
}

}  // namespace shockfield::test
