#include "shockfield/analysis/block_configurations.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {
namespace {

// Levels of the cells, on a grid extended by the boundary: open adds one black (level 0) layer on
// each side, periodic repeats the first layer after the last. Blocks are then ext - 1 per axis.
struct LevelGrid {
  int dimension = 2;
  std::array<std::size_t, 3> ext{1, 1, 1};
  std::vector<std::uint16_t> level;
};

// Levels of a row of n values, `lanes` cells at a time: a binary search over the sorted thresholds
// without branches on the data, the searches of the lanes interleaved (independent chains of
// loads). std::upper_bound cell by cell spent a quarter of the 3D time in mispredictions.
void row_levels(const double* v, std::size_t n, std::span<const double> t, std::uint16_t* out) {
  constexpr std::size_t lanes = 8;
  const std::size_t m = t.size();
  for (std::size_t x0 = 0; x0 < n; x0 += lanes) {
    const std::size_t count = std::min(lanes, n - x0);
    std::array<double, lanes> value{};
    std::copy_n(v + x0, count, value.begin());
    std::array<std::size_t, lanes> k{};  // thresholds known to be <= value
    for (std::size_t step = std::bit_floor(m); step > 0; step >>= 1)
      for (std::size_t l = 0; l < lanes; ++l) {
        const std::size_t next = k[l] + step;
        k[l] +=
            step * static_cast<std::size_t>((next <= m) & (t[std::min(next, m) - 1] <= value[l]));
      }
    for (std::size_t l = 0; l < count; ++l) out[x0 + l] = static_cast<std::uint16_t>(k[l]);
  }
}

LevelGrid make_levels(const GridFieldView& field, std::span<const double> thresholds,
                      Boundary boundary) {
  LevelGrid g;
  g.dimension = field.dimension();
  const bool open = boundary == Boundary::open;
  for (int a = 0; a < g.dimension; ++a) g.ext[a] = field.n[a] + 1 + (open ? 1 : 0);
  g.level.assign(g.ext[0] * g.ext[1] * g.ext[2], 0);
  const auto source = [&](std::size_t e, int a) -> std::ptrdiff_t {
    if (open) return (e == 0 || e == field.n[a] + 1) ? -1 : static_cast<std::ptrdiff_t>(e - 1);
    return static_cast<std::ptrdiff_t>(e % field.n[a]);
  };
  const std::size_t nx = field.n[0], first = open ? 1 : 0;
  const auto rows = static_cast<std::ptrdiff_t>(g.ext[1] * g.ext[2]);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    const std::size_t y = static_cast<std::size_t>(r) % g.ext[1];
    const std::size_t z = static_cast<std::size_t>(r) / g.ext[1];
    const std::ptrdiff_t sy = source(y, 1), sz = g.dimension == 3 ? source(z, 2) : 0;
    if (sy < 0 || sz < 0) continue;
    const std::size_t i0 =
        field.index(0, static_cast<std::size_t>(sy), static_cast<std::size_t>(sz));
    std::uint16_t* out = g.level.data() + g.ext[0] * static_cast<std::size_t>(r) + first;
    row_levels(field.values.data() + i0, nx, thresholds, out);
    for (std::size_t x = 0; x < nx; ++x)
      if (field.void_at(i0 + x)) out[x] = 0;
    if (!open) out[nx] = out[0];  // the periodic image of x = 0
  }
  return g;
}

// Calls visit(levels of the 2^D block cells, accumulator) for every block, each thread with its
// own accumulator of acc_size 32-bit integers (small enough to stay in L1), moved into 64-bit
// sums after every `flush_every` blocks (the callers' bound for no 32-bit overflow); returns their
// sum (integers: any thread count gives the same result).
template <int D, class Visit>
std::vector<std::int64_t> sum_over_blocks(const LevelGrid& g, std::size_t acc_size,
                                          std::size_t flush_every, Visit visit) {
  const std::size_t bx = g.ext[0] - 1, by = g.ext[1] - 1, bz = D == 3 ? g.ext[2] - 1 : 1;
  const std::size_t sy = g.ext[0], sz = g.ext[0] * g.ext[1];
  const auto rows = static_cast<std::ptrdiff_t>(by * bz);
  std::vector<std::int64_t> total(acc_size, 0);
#pragma omp parallel
  {
    std::vector<std::int32_t> acc(acc_size, 0);
    std::vector<std::int64_t> sum(acc_size, 0);
    std::size_t pending = 0;
    const auto flush = [&] {
      for (std::size_t i = 0; i < acc_size; ++i) sum[i] += acc[i], acc[i] = 0;
      pending = 0;
    };
#pragma omp for schedule(static)
    for (std::ptrdiff_t r = 0; r < rows; ++r) {
      const std::size_t y = static_cast<std::size_t>(r) % by, z = static_cast<std::size_t>(r) / by;
      const std::uint16_t* p0 = g.level.data() + y * sy + z * sz;
      const std::uint16_t* p1 = p0 + sy;
      const std::uint16_t* p2 = D == 3 ? p0 + sz : p0;
      const std::uint16_t* p3 = D == 3 ? p1 + sz : p1;
      std::array<std::uint16_t, (1 << D)> lv{};
      for (std::size_t x0 = 0; x0 < bx; x0 += flush_every) {
        const std::size_t x1 = std::min(bx, x0 + flush_every);
        if (pending + (x1 - x0) > flush_every) flush();
        pending += x1 - x0;
        for (std::size_t x = x0; x < x1; ++x) {
          lv[0] = p0[x], lv[1] = p0[x + 1], lv[2] = p1[x], lv[3] = p1[x + 1];
          if constexpr (D == 3) lv[4] = p2[x], lv[5] = p2[x + 1], lv[6] = p3[x], lv[7] = p3[x + 1];
          visit(lv, acc.data());
        }
      }
    }
    flush();
#pragma omp critical(shockfield_block_sum)
    for (std::size_t i = 0; i < acc_size; ++i) total[i] += sum[i];
  }
  return total;
}

// Branch-free sorting networks for 4 and 8 keys (Batcher's odd-even merge sort), unrolled with
// the keys in registers (a loop over the pairs, or a call per block, cost 40 % of the 3D time).
constexpr std::array<std::array<std::size_t, 2>, 5> kNet4{{{0, 1}, {2, 3}, {0, 2}, {1, 3}, {1, 2}}};
constexpr std::array<std::array<std::size_t, 2>, 19> kNet8{{{0, 1},
                                                            {2, 3},
                                                            {4, 5},
                                                            {6, 7},
                                                            {0, 2},
                                                            {1, 3},
                                                            {4, 6},
                                                            {5, 7},
                                                            {1, 2},
                                                            {5, 6},
                                                            {0, 4},
                                                            {3, 7},
                                                            {1, 5},
                                                            {2, 6},
                                                            {1, 4},
                                                            {3, 6},
                                                            {2, 4},
                                                            {3, 5},
                                                            {3, 4}}};

template <const auto& Net, std::size_t N, std::size_t... I>
[[gnu::always_inline]] inline void sort_with(std::array<std::uint32_t, N>& k,
                                             std::index_sequence<I...>) {
  const auto exchange = [&](std::size_t i, std::size_t j) {
    const std::uint32_t a = k[i], b = k[j], swap = (a ^ b) & (0u - std::uint32_t{b < a});
    k[i] = a ^ swap, k[j] = b ^ swap;
  };
  (exchange(Net[I][0], Net[I][1]), ...);
}

template <std::size_t N>
[[gnu::always_inline]] inline void sort_network(std::array<std::uint32_t, N>& k) {
  if constexpr (N == 4)
    sort_with<kNet4>(k, std::make_index_sequence<kNet4.size()>{});
  else
    sort_with<kNet8>(k, std::make_index_sequence<kNet8.size()>{});
}

// acc[q] += after[q] − before[q] for the W (a multiple of 4) or, W = 0, `width` columns; with W,
// four columns at a time in a 128-bit vector (GCC/Clang vector extension: SSE2 on x86-64, NEON on
// ARM; GCC left the plain loop scalar).
using Int32x4 = std::int32_t __attribute__((vector_size(16)));

template <std::size_t W>
[[gnu::always_inline]] inline void add_difference(std::int32_t* acc, const std::int32_t* after,
                                                  const std::int32_t* before, std::size_t width) {
  if constexpr (W > 0) {
    static_assert(W % 4 == 0);
    for (std::size_t q = 0; q < W; q += 4) {
      Int32x4 a, b, sum;
      std::memcpy(&a, after + q, sizeof a), std::memcpy(&b, before + q, sizeof b);
      std::memcpy(&sum, acc + q, sizeof sum);
      sum += a - b;
      std::memcpy(acc + q, &sum, sizeof sum);
    }
  } else {
    for (std::size_t q = 0; q < width; ++q) acc[q] += after[q] - before[q];
  }
}

// Blocks between flushes of the 32-bit accumulators: a block changes an entry by at most
// 2 max|w| at any moment (its differences at one level telescope to w(c_j) − w(c_i); in the
// one-threshold route it adds w once).
std::size_t flush_interval(const BlockWeights& w) {
  if (w.width == 0 || w.values.size() != configurations(w.dimension) * w.width)
    throw std::invalid_argument("BlockWeights: values must hold configurations x width entries");
  std::int64_t largest = 1;
  for (const std::int32_t v : w.values) largest = std::max<std::int64_t>(largest, std::abs(v));
  if (largest > (1 << 15)) throw std::invalid_argument("BlockWeights: entries beyond +-2^15");
  return static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / (2 * largest));
}

template <int D>
std::vector<std::int64_t> sum_one(const LevelGrid& g, const BlockWeights& w) {
  return sum_over_blocks<D>(g, w.width, flush_interval(w), [&](const auto& lv, std::int32_t* acc) {
    unsigned config = 0;
    for (std::size_t b = 0; b < lv.size(); ++b) config |= (lv[b] > 0 ? 1u : 0u) << b;
    const std::int32_t* row = w.values.data() + config * w.width;
    for (std::size_t q = 0; q < w.width; ++q) acc[q] += row[q];
  });
}

// W: the width rounded up to a multiple of 4 (rows of whole SIMD registers, zero padded), or 0
// for a width only known at run time.
template <int D, std::size_t W>
std::vector<std::int64_t> sum_all(const LevelGrid& g, const BlockWeights& w,
                                  std::size_t n_thresholds, std::int64_t n_blocks) {
  constexpr std::size_t cells = 1 << D;
  constexpr unsigned full = (1u << cells) - 1u;
  const std::size_t width = W > 0 ? W : w.width;
  std::vector<std::int32_t> table(configurations(D) * width, 0);
  for (std::size_t c = 0; c < configurations(D); ++c)
    std::copy_n(w.values.begin() + c * w.width, w.width, table.begin() + c * width);
  // diff[K]: change of the sums at threshold index K.
  std::vector<std::int64_t> diff = sum_over_blocks<D>(
      g, (n_thresholds + 1) * width, flush_interval(w), [&](const auto& lv, std::int32_t* acc) {
        std::array<std::uint32_t, cells> key{};  // level << 3 | cell, sorted by level below
        for (std::size_t b = 0; b < cells; ++b)
          key[b] = (std::uint32_t{lv[b]} << 3) | static_cast<std::uint32_t>(b);
        sort_network(key);
        // Cells turn black in level order; equal levels need no merging: their differences
        // telescope (integers, exact), and branching on them would cost mispredictions.
        unsigned config = full;
        const std::int32_t* before = table.data() + full * width;
        for (std::size_t i = 0; i < cells; ++i) {
          config &= ~(1u << (key[i] & 7u));
          const std::int32_t* after = table.data() + config * width;
          add_difference<W>(acc + (key[i] >> 3) * width, after, before, width);
          before = after;
        }
      });
  // Below every cell's level, a block is all white.
  std::vector<std::int64_t> sums(n_thresholds * w.width), running(w.width);
  for (std::size_t q = 0; q < w.width; ++q) running[q] = n_blocks * w.values[full * w.width + q];
  for (std::size_t k = 0; k < n_thresholds; ++k)
    for (std::size_t q = 0; q < w.width; ++q)
      sums[k * w.width + q] = running[q] += diff[k * width + q];
  return sums;
}

template <int D>
std::vector<std::int64_t> sum_all(const LevelGrid& g, const BlockWeights& w,
                                  std::size_t n_thresholds, std::int64_t n_blocks) {
  switch ((w.width + 3) / 4) {
    case 1:
      return sum_all<D, 4>(g, w, n_thresholds, n_blocks);
    case 2:
      return sum_all<D, 8>(g, w, n_thresholds, n_blocks);
    case 3:
      return sum_all<D, 12>(g, w, n_thresholds, n_blocks);
    case 4:
      return sum_all<D, 16>(g, w, n_thresholds, n_blocks);
    default:
      return sum_all<D, 0>(g, w, n_thresholds, n_blocks);
  }
}

void require_matching(const GridFieldView& field, const BlockWeights& w) {
  if (w.dimension != field.dimension())
    throw std::invalid_argument("BlockWeights: table dimension differs from the field's");
}

}  // namespace

void require_increasing(std::span<const double> thresholds) {
  if (thresholds.empty()) throw InputError("thresholds: none given; expected at least one");
  if (thresholds.size() > std::numeric_limits<std::uint16_t>::max())
    throw InputError(fmt::format("thresholds: {} given; at most {} are supported",
                                 thresholds.size(), std::numeric_limits<std::uint16_t>::max()));
  for (std::size_t k = 0; k < thresholds.size(); ++k) {
    if (!std::isfinite(thresholds[k]))
      throw InputError(
          fmt::format("thresholds: value {} at position {} is not finite", thresholds[k], k + 1));
    if (k > 0 && !(thresholds[k] > thresholds[k - 1]))
      throw InputError(fmt::format(
          "thresholds out of order: {} at position {} follows {}; expected strictly increasing "
          "thresholds",
          thresholds[k], k + 1, thresholds[k - 1]));
  }
}

std::int64_t block_count(const GridFieldView& field, Boundary boundary) {
  std::int64_t blocks = 1;
  for (int a = 0; a < field.dimension(); ++a)
    blocks *= static_cast<std::int64_t>(field.n[a] + (boundary == Boundary::open ? 1 : 0));
  return blocks;
}

BlockSums sum_block_weights(const GridFieldView& field, double threshold, Boundary boundary,
                            const BlockWeights& weights) {
  const std::array<double, 1> t{threshold};
  require_increasing(t);
  validate(field, "field");
  require_matching(field, weights);
  const LevelGrid g = make_levels(field, t, boundary);
  return {{threshold},
          weights.width,
          g.dimension == 3 ? sum_one<3>(g, weights) : sum_one<2>(g, weights)};
}

BlockSums sum_block_weights(const GridFieldView& field, std::span<const double> thresholds,
                            Boundary boundary, const BlockWeights& weights) {
  require_increasing(thresholds);
  validate(field, "field");
  require_matching(field, weights);
  const LevelGrid g = make_levels(field, thresholds, boundary);
  const std::int64_t blocks = block_count(field, boundary);
  return {{thresholds.begin(), thresholds.end()},
          weights.width,
          g.dimension == 3 ? sum_all<3>(g, weights, thresholds.size(), blocks)
                           : sum_all<2>(g, weights, thresholds.size(), blocks)};
}

}  // namespace shockfield::analysis
