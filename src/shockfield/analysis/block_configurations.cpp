#include "shockfield/analysis/block_configurations.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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

LevelGrid make_levels(const GridField& field, std::span<const double> thresholds,
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
  const auto ez = static_cast<std::ptrdiff_t>(g.ext[2]);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t z = 0; z < ez; ++z) {
    const std::ptrdiff_t sz = g.dimension == 3 ? source(z, 2) : 0;
    if (sz < 0) continue;
    for (std::size_t y = 0; y < g.ext[1]; ++y) {
      const std::ptrdiff_t sy = source(y, 1);
      if (sy < 0) continue;
      for (std::size_t x = 0; x < g.ext[0]; ++x) {
        const std::ptrdiff_t sx = source(x, 0);
        if (sx < 0) continue;
        const std::size_t i = field.index(sx, sy, sz);
        if (field.void_at(i)) continue;
        const auto k = std::upper_bound(thresholds.begin(), thresholds.end(), field.values[i]) -
                       thresholds.begin();
        g.level[x + g.ext[0] * (y + g.ext[1] * z)] = static_cast<std::uint16_t>(k);
      }
    }
  }
  return g;
}

// Calls visit(levels of the 2^D block cells, accumulator) for every block, each thread with its
// own accumulator of acc_size 32-bit integers (small enough to stay in cache; a thread sees fewer
// than 2^31 blocks, checked by the callers); returns their sum (integers: any thread count gives
// the same result).
template <int D, class Visit>
std::vector<std::int64_t> sum_over_blocks(const LevelGrid& g, std::size_t acc_size, Visit visit) {
  const std::size_t bx = g.ext[0] - 1, by = g.ext[1] - 1, bz = D == 3 ? g.ext[2] - 1 : 1;
  const std::size_t sy = g.ext[0], sz = g.ext[0] * g.ext[1];
  const auto rows = static_cast<std::ptrdiff_t>(by * bz);
  std::vector<std::int64_t> total(acc_size, 0);
#pragma omp parallel
  {
    std::vector<std::int32_t> acc(acc_size, 0);
#pragma omp for schedule(static)
    for (std::ptrdiff_t r = 0; r < rows; ++r) {
      const std::size_t y = static_cast<std::size_t>(r) % by, z = static_cast<std::size_t>(r) / by;
      const std::uint16_t* p0 = g.level.data() + y * sy + z * sz;
      const std::uint16_t* p1 = p0 + sy;
      const std::uint16_t* p2 = D == 3 ? p0 + sz : p0;
      const std::uint16_t* p3 = D == 3 ? p1 + sz : p1;
      std::array<std::uint16_t, (1 << D)> lv{};
      for (std::size_t x = 0; x < bx; ++x) {
        lv[0] = p0[x], lv[1] = p0[x + 1], lv[2] = p1[x], lv[3] = p1[x + 1];
        if constexpr (D == 3) lv[4] = p2[x], lv[5] = p2[x + 1], lv[6] = p3[x], lv[7] = p3[x + 1];
        visit(lv, acc.data());
      }
    }
#pragma omp critical(shockfield_block_sum)
    for (std::size_t i = 0; i < acc_size; ++i) total[i] += acc[i];
  }
  return total;
}

// Branch-free sorting networks for 4 and 8 keys (Batcher's odd-even merge sort).
template <std::size_t N>
void sort_network(std::array<std::uint32_t, N>& k) {
  constexpr std::array<std::array<int, 2>, 5> net4{{{0, 1}, {2, 3}, {0, 2}, {1, 3}, {1, 2}}};
  constexpr std::array<std::array<int, 2>, 19> net8{{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2},
                                                      {1, 3}, {4, 6}, {5, 7}, {1, 2}, {5, 6},
                                                      {0, 4}, {3, 7}, {1, 5}, {2, 6}, {1, 4},
                                                      {3, 6}, {2, 4}, {3, 5}, {3, 4}}};
  const auto exchange = [&](const std::array<int, 2>& p) {
    const std::uint32_t a = k[p[0]], b = k[p[1]];
    k[p[0]] = std::min(a, b), k[p[1]] = std::max(a, b);
  };
  if constexpr (N == 4) for (const auto& p : net4) exchange(p);
  else for (const auto& p : net8) exchange(p);
}

template <int D>
std::vector<std::int64_t> count_one(const LevelGrid& g) {
  return sum_over_blocks<D>(g, std::size_t{1} << (1 << D), [](const auto& lv, std::int32_t* acc) {
    unsigned config = 0;
    for (std::size_t b = 0; b < lv.size(); ++b) config |= (lv[b] > 0 ? 1u : 0u) << b;
    ++acc[config];
  });
}

template <int D>
std::vector<std::int64_t> count_all(const LevelGrid& g, std::size_t n_thresholds,
                                    std::int64_t n_blocks) {
  constexpr std::size_t cells = 1 << D;
  constexpr unsigned full = (1u << cells) - 1u;
  constexpr std::size_t nc = std::size_t{1} << cells;
  // diff[K][c]: change of the count of configuration c at threshold index K.
  std::vector<std::int64_t> diff = sum_over_blocks<D>(
      g, (n_thresholds + 1) * nc, [](const auto& lv, std::int32_t* acc) {
        std::array<std::uint32_t, cells> key{};  // level << 3 | cell, sorted by level below
        for (std::size_t b = 0; b < cells; ++b)
          key[b] = (std::uint32_t{lv[b]} << 3) | static_cast<std::uint32_t>(b);
        sort_network(key);
        unsigned config = full;
        for (std::size_t i = 0; i < cells;) {
          const std::uint32_t level = key[i] >> 3;
          acc[level * nc + config] -= 1;
          for (; i < cells && (key[i] >> 3) == level; ++i) config &= ~(1u << (key[i] & 7u));
          acc[level * nc + config] += 1;
        }
      });
  diff[full] += n_blocks;  // below every cell's level, a block is all white
  std::vector<std::int64_t> counts(n_thresholds * nc);
  std::vector<std::int64_t> running(nc, 0);
  for (std::size_t k = 0; k < n_thresholds; ++k)
    for (std::size_t c = 0; c < nc; ++c) counts[k * nc + c] = running[c] += diff[k * nc + c];
  return counts;
}

}  // namespace

void require_increasing(std::span<const double> thresholds) {
  if (thresholds.empty()) throw InputError("thresholds: none given; expected at least one");
  if (thresholds.size() > std::numeric_limits<std::uint16_t>::max())
    throw InputError(fmt::format("thresholds: {} given; at most {} are supported",
                                 thresholds.size(), std::numeric_limits<std::uint16_t>::max()));
  for (std::size_t k = 0; k < thresholds.size(); ++k) {
    if (!std::isfinite(thresholds[k]))
      throw InputError(fmt::format("thresholds: value {} at position {} is not finite",
                                   thresholds[k], k + 1));
    if (k > 0 && !(thresholds[k] > thresholds[k - 1]))
      throw InputError(fmt::format(
          "thresholds out of order: {} at position {} follows {}; expected strictly increasing "
          "thresholds",
          thresholds[k], k + 1, thresholds[k - 1]));
  }
}

std::int64_t block_count(const GridField& field, Boundary boundary) {
  std::int64_t blocks = 1;
  for (int a = 0; a < field.dimension(); ++a)
    blocks *= static_cast<std::int64_t>(field.n[a] + (boundary == Boundary::open ? 1 : 0));
  if (blocks > std::numeric_limits<std::int32_t>::max())
    throw InputError(fmt::format("field of {} x {} x {} cells: more than 2^31 blocks are not "
                                 "supported", field.n[0], field.n[1], field.n[2]));
  return blocks;
}

ConfigurationCounts count_configurations(const GridField& field, double threshold,
                                         Boundary boundary) {
  const std::array<double, 1> t{threshold};
  require_increasing(t);
  validate(field, "field");
  block_count(field, boundary);
  const LevelGrid g = make_levels(field, t, boundary);
  return {g.dimension, {threshold}, g.dimension == 3 ? count_one<3>(g) : count_one<2>(g)};
}

ConfigurationCounts count_configurations(const GridField& field,
                                         std::span<const double> thresholds, Boundary boundary) {
  require_increasing(thresholds);
  validate(field, "field");
  const LevelGrid g = make_levels(field, thresholds, boundary);
  const std::int64_t blocks = block_count(field, boundary);
  return {g.dimension,
          {thresholds.begin(), thresholds.end()},
          g.dimension == 3 ? count_all<3>(g, thresholds.size(), blocks)
                           : count_all<2>(g, thresholds.size(), blocks)};
}

}  // namespace shockfield::analysis
