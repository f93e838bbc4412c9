// BRIO rounds sorted along a Hilbert curve (see spatial_sort.hpp).
#include "shockfield/geometry/spatial_sort.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

namespace shockfield::geometry {

template <int N>
std::uint64_t hilbert_index(std::array<std::uint32_t, N> x, int bits) {
  // Skilling (2004), "Programming the Hilbert curve", AxestoTranspose: undo the excess work
  // (invert or exchange low bits, from the top bit down), then Gray-encode.
  const std::uint32_t top = std::uint32_t{1} << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t low = q - 1;
    for (int i = 0; i < N; ++i) {
      if (x[i] & q) {
        x[0] ^= low;
      } else {
        const std::uint32_t t = (x[0] ^ x[i]) & low;
        x[0] ^= t;
        x[i] ^= t;
      }
    }
  }
  for (int i = 1; i < N; ++i) x[i] ^= x[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[N - 1] & q) t ^= q - 1;
  for (int i = 0; i < N; ++i) x[i] ^= t;
  // The transposed form holds the index's bits round-robin over the axes, top bits first.
  std::uint64_t index = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < N; ++i) index = index << 1 | (x[i] >> b & 1u);
  return index;
}

template <int N>
std::vector<std::int32_t> brio_hilbert_order(const std::vector<std::array<double, N>>& points,
                                             std::vector<std::int32_t> ids) {
  constexpr int kBits = 64 / N;
  std::array<double, N> lo, scale;
  for (int k = 0; k < N; ++k) {
    double hi = -std::numeric_limits<double>::infinity();
    lo[k] = std::numeric_limits<double>::infinity();
    for (std::int32_t i : ids) {
      lo[k] = std::min(lo[k], points[i][k]);
      hi = std::max(hi, points[i][k]);
    }
    // Cells 0 .. 2^bits − 1 across the box (a little under 2^bits so the top edge stays inside).
    scale[k] = hi > lo[k] ? std::ldexp(1.0, kBits) * (1.0 - 0x1p-40) / (hi - lo[k]) : 0.0;
  }
  std::mt19937_64 rng(20030607);
  std::shuffle(ids.begin(), ids.end(), rng);
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed(ids.size());
  for (std::size_t j = 0; j < ids.size(); ++j) {
    std::array<std::uint32_t, N> cell;
    for (int k = 0; k < N; ++k)
      cell[k] = static_cast<std::uint32_t>((points[ids[j]][k] - lo[k]) * scale[k]);
    keyed[j] = {hilbert_index<N>(cell, kBits), ids[j]};
  }
  // Rounds: the last half of the shuffled points, then the last half of the rest, ...
  for (std::size_t end = keyed.size(); end > 0;) {
    const std::size_t begin = end > 64 ? end / 2 : 0;
    std::sort(keyed.begin() + static_cast<std::ptrdiff_t>(begin),
              keyed.begin() + static_cast<std::ptrdiff_t>(end));
    end = begin;
  }
  for (std::size_t j = 0; j < ids.size(); ++j) ids[j] = keyed[j].second;
  return ids;
}

template std::uint64_t hilbert_index<2>(std::array<std::uint32_t, 2>, int);
template std::uint64_t hilbert_index<3>(std::array<std::uint32_t, 3>, int);
template std::vector<std::int32_t> brio_hilbert_order<2>(
    const std::vector<std::array<double, 2>>&, std::vector<std::int32_t>);
template std::vector<std::int32_t> brio_hilbert_order<3>(
    const std::vector<std::array<double, 3>>&, std::vector<std::int32_t>);

}  // namespace shockfield::geometry
