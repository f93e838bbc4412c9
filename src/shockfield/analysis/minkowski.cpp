#include "shockfield/analysis/minkowski.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {
namespace {

constexpr double pi = std::numbers::pi;

// Crofton direction weights: fraction of the unit sphere (3D) or circle (2D) closer to a lattice
// direction class than to any other, indexed by the number m of its nonzero components.
// 3D values: Legland, Kiêu & Devaux (2007), the 13-direction spherical Voronoi areas (×2 for ±u).
constexpr std::array<double, 4> kWeight2D{0.0, 0.25, 0.25, 0.0};
constexpr std::array<double, 4> kWeight3D{0.0, 0.04577789120476 * 2, 0.03698062787608 * 2,
                                          0.03519563978232 * 2};

// 2^D × χ contribution of one block (D = 2 or 3) for the cell complex of the white cells:
// closed == true: white cells are closed squares/cubes (connectivity 8 / 26);
// closed == false: white cells are points joined by edges, squares, cubes when all their corners
// are white (connectivity 4 / 6).
// A j-dimensional face of the block's cell complex lies in 2^(D-j) blocks; summing
// (−1)^dim(cell) over the cells gives χ = V − E + F (− C). The faces are enumerated as sub-blocks:
// per axis the cell coordinate is fixed to 0, fixed to 1, or free.
int euler_times_cells(unsigned config, int dimension, bool closed) {
  int sum = 0;
  int states = 1;
  for (int a = 0; a < dimension; ++a) states *= 3;
  for (int s = 0; s < states; ++s) {
    unsigned mask = 0;
    int free = 0, code = s;
    std::array<int, 3> state{};
    for (int a = 0; a < dimension; ++a, code /= 3) state[a] = code % 3, free += state[a] == 2;
    for (unsigned cell = 0; cell < (1u << dimension); ++cell) {
      bool inside = true;
      for (int a = 0; a < dimension; ++a)
        if (state[a] != 2 && static_cast<int>((cell >> a) & 1u) != state[a]) inside = false;
      if (inside) mask |= 1u << cell;
    }
    const int weight = 1 << free;
    if (closed) {  // the dual cell at the block centre, of dimension D − free, exists if any
                   // white cell touches it
      if (config & mask) sum += ((dimension - free) % 2 ? -weight : weight);
    } else if ((config & mask) == mask) {
      sum += (free % 2 ? -weight : weight);
    }
  }
  return sum;
}

// Crossings of the lattice lines through one block: the pairs of block cells that differ, by
// direction class m (number of nonzero components of the pair's direction, 1..D).
std::array<int, 4> crossings(unsigned config, int dimension) {
  std::array<int, 4> by_class{};
  const unsigned cells = 1u << dimension;
  for (unsigned a = 0; a < cells; ++a)
    for (unsigned b = a + 1; b < cells; ++b)
      if (((config >> a) & 1u) != ((config >> b) & 1u)) ++by_class[std::popcount(a ^ b)];
  return by_class;
}

// 2D configuration of four block cells c00, c10, c01, c11 forming a (possibly sheared) square.
unsigned square_config(unsigned config, std::array<unsigned, 4> cells) {
  unsigned out = 0;
  for (unsigned i = 0; i < 4; ++i) out |= ((config >> cells[i]) & 1u) << i;
  return out;
}

// Euler characteristics of the block's part of the planar sections used by the mean breadth, for
// the three classes of plane normal u, as integers: {Σ 4χ of the axis-normal faces, Σ 4χ of the
// face-diagonal-normal rectangles, Σ 6χ of the space-diagonal-normal triangles}.
std::array<int, 3> section_euler(unsigned config, bool closed) {
  std::array<int, 3> sum{};
  // Axis normals: the block's two faces normal to the axis; each face square lies in 2 blocks.
  for (unsigned a = 0; a < 3; ++a) {
    const unsigned u = 1u << ((a + 1) % 3), v = 1u << ((a + 2) % 3);
    for (unsigned side = 0; side < 2; ++side) {
      const unsigned o = side << a;
      sum[0] += euler_times_cells(square_config(config, {o, o | u, o | v, o | u | v}), 2, closed);
    }
  }
  // Face-diagonal normals (a ± b): the plane through the block's diagonal pair in (a, b) holds
  // a 1 × √2 rectangle, which lies in one block only.
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = a + 1; b < 3; ++b) {
      const unsigned t = 1u << (3 - a - b);  // the third axis
      const std::array<std::array<unsigned, 2>, 2> pairs{
          {{0u, (1u << a) | (1u << b)}, {1u << a, 1u << b}}};
      for (const auto& p : pairs)
        sum[1] +=
            euler_times_cells(square_config(config, {p[0], p[1], p[0] | t, p[1] | t}), 2, closed);
    }
  // Space-diagonal normals (1, ±1, ±1): planes cut the block in triangles of face diagonals
  // (the level sets of n·p with three cells); the triangular lattice is self-dual, so both
  // complexes give χ_tri = [any] − ½ Σ_edges [either] + ⅙ Σ_cells [white].
  for (int s = 0; s < 4; ++s) {
    const std::array<int, 3> n{1, s & 1 ? -1 : 1, s & 2 ? -1 : 1};
    for (int level = -2; level <= 3; ++level) {
      std::array<unsigned, 3> tri{};
      int count = 0;
      for (unsigned c = 0; c < 8; ++c)
        if (n[0] * int(c & 1u) + n[1] * int((c >> 1) & 1u) + n[2] * int((c >> 2) & 1u) == level) {
          if (count < 3) tri[count] = c;
          ++count;
        }
      if (count != 3) continue;
      const auto white = [&](unsigned c) { return int((config >> c) & 1u); };
      const int any = white(tri[0]) | white(tri[1]) | white(tri[2]);
      const int points = white(tri[0]) + white(tri[1]) + white(tri[2]);
      const int either = (white(tri[0]) | white(tri[1])) + (white(tri[1]) | white(tri[2])) +
                         (white(tri[0]) | white(tri[2]));
      sum[2] += 6 * any - 3 * either + points;
    }
  }
  return sum;
}

// Columns of the integer weight table (per block configuration); the functionals are fixed
// combinations of their sums over blocks. 2D uses the first five.
namespace col {
constexpr std::size_t white = 0;  // white cells of the block (each cell lies in 2^D blocks)
constexpr std::size_t euler(bool closed) {
  return closed ? 1 : 2;
}  // 2^D χ
constexpr std::size_t crossings(int m) {
  return 2 + std::size_t(m);
}  // m = 1..D
constexpr std::size_t section(std::size_t kind, bool closed) {  // 3D: section_euler[kind]
  return kind == 2 ? 10 : 6 + 2 * kind + (closed ? 0 : 1);
}
constexpr std::size_t width(int dimension) {
  return dimension == 3 ? 11 : 5;
}
}  // namespace col

BlockWeights make_weights(int d) {
  BlockWeights w{d, col::width(d), std::vector<std::int32_t>(configurations(d) * col::width(d))};
  for (unsigned c = 0; c < configurations(d); ++c) {
    std::int32_t* row = w.values.data() + c * w.width;
    row[col::white] = std::popcount(c);
    const auto crossed = crossings(c, d);
    for (int m = 1; m <= d; ++m) row[col::crossings(m)] = crossed[m];
    for (const bool closed : {false, true}) {
      row[col::euler(closed)] = euler_times_cells(c, d, closed);
      if (d != 3) continue;
      const auto sections = section_euler(c, closed);
      for (std::size_t kind = 0; kind < 3; ++kind) row[col::section(kind, closed)] = sections[kind];
    }
  }
  return w;
}

// Crofton's formula in grid units: boundary length (2D, factor π/2) or surface (3D, factor 2)
// from the crossings, each divided by the number of blocks holding the pair (2^(D−m)) and the
// line density |u| = √m.
double crofton(std::span<const std::int64_t> row, int dimension) {
  const double factor = dimension == 2 ? pi / 2.0 : 2.0;
  const auto& weight = dimension == 2 ? kWeight2D : kWeight3D;
  double sum = 0.0;
  for (int m = 1; m <= dimension; ++m)
    sum += weight[m] / (double(1 << (dimension - m)) * std::sqrt(double(m))) *
           double(row[col::crossings(m)]);
  return factor * sum;
}

// Mean breadth in grid units: Σ over the 13 plane normals u of w_u × (plane spacing 1/|u|) × χ
// of the sections (axis faces lie in 2 blocks; 4χ and 6χ are stored).
double mean_breadth(std::span<const std::int64_t> row, bool closed) {
  return kWeight3D[1] * 0.5 * double(row[col::section(0, closed)]) / 4.0 +
         kWeight3D[2] / std::sqrt(2.0) * double(row[col::section(1, closed)]) / 4.0 +
         kWeight3D[3] / std::sqrt(3.0) * double(row[col::section(2, closed)]) / 6.0;
}

double isotropic_spacing(const GridFieldView& field) {
  for (int a = 1; a < field.dimension(); ++a)
    if (field.spacing[a] != field.spacing[0])
      throw InputError(fmt::format(
          "Minkowski functionals need a square/cubic lattice; the grid spacing is ({}, {}, {})",
          field.spacing[0], field.spacing[1], field.spacing[2]));
  return field.spacing[0];
}

// Common part: white cells, area/volume fraction and eq. (33)'s normalisation.
struct Common {
  std::int64_t white = 0, euler = 0;
  double fraction = 0.0, per_black = 0.0;
};

Common common(std::span<const std::int64_t> row, const GridFieldView& field, bool closed) {
  const std::int64_t cells_per_block = std::int64_t{1} << field.dimension();
  Common c;
  c.white = row[col::white] / cells_per_block;
  c.euler = row[col::euler(closed)] / cells_per_block;  // eq. (32)
  const auto total = static_cast<std::int64_t>(field.size());
  c.fraction = static_cast<double>(c.white) / static_cast<double>(total);
  const std::int64_t black = total - c.white;  // void cells are black
  c.per_black = black > 0 ? static_cast<double>(c.euler) / static_cast<double>(black)
                          : std::numeric_limits<double>::quiet_NaN();  // eq. (33)
  return c;
}

void require_dimension(const GridFieldView& field, int dimension) {
  if (field.dimension() != dimension)
    throw InputError(fmt::format("expected a {}D field, got {} x {} x {} cells", dimension,
                                 field.n[0], field.n[1], field.n[2]));
}

// Sums every threshold in one pass, then evaluates `row(sums, k)` per threshold.
template <class Row>
auto for_all_thresholds(const GridFieldView& field, std::span<const double> thresholds,
                        Boundary boundary, int dimension, Row row) {
  require_dimension(field, dimension);
  isotropic_spacing(field);
  const BlockSums sums =
      sum_block_weights(field, thresholds, boundary, minkowski_weights(dimension));
  std::vector<decltype(row(sums, std::size_t{0}))> out;
  for (std::size_t k = 0; k < thresholds.size(); ++k) out.push_back(row(sums, k));
  return out;
}

}  // namespace

const BlockWeights& minkowski_weights(int dimension) {
  static const std::array<BlockWeights, 2> tables{make_weights(2), make_weights(3)};
  return tables.at(static_cast<std::size_t>(dimension - 2));
}

Functionals2D functionals_2d(const BlockSums& sums, std::size_t k, const GridFieldView& field,
                             Connectivity2D connectivity) {
  require_dimension(field, 2);
  const double h = isotropic_spacing(field);
  const auto row = sums.row(k);
  const Common c = common(row, field, connectivity == Connectivity2D::eight);
  Functionals2D f;
  f.threshold = sums.thresholds[k];
  f.area_fraction = c.fraction;
  f.boundary_length = crofton(row, 2) * h;
  f.euler = c.euler;
  f.euler_per_black_node = c.per_black;
  f.white_cells = c.white;
  return f;
}

Functionals3D functionals_3d(const BlockSums& sums, std::size_t k, const GridFieldView& field,
                             Adjacency3D adjacency) {
  require_dimension(field, 3);
  const double h = isotropic_spacing(field);
  const auto row = sums.row(k);
  const bool closed = adjacency == Adjacency3D::twentysix_6;
  const Common c = common(row, field, closed);
  Functionals3D f;
  f.threshold = sums.thresholds[k];
  f.volume_fraction = c.fraction;
  f.surface_area = crofton(row, 3) * h * h;
  f.mean_breadth = mean_breadth(row, closed) * h;
  f.integral_mean_curvature = 2.0 * pi * f.mean_breadth;
  f.euler = c.euler;
  f.euler_per_black_node = c.per_black;
  f.white_cells = c.white;
  return f;
}

std::vector<Functionals2D> minkowski_2d(const GridFieldView& field, std::span<const double> thresholds,
                                        const MinkowskiOptions& options) {
  return for_all_thresholds(field, thresholds, options.boundary, 2, [&](const auto& sums, auto k) {
    return functionals_2d(sums, k, field, options.connectivity2d);
  });
}

std::vector<Functionals3D> minkowski_3d(const GridFieldView& field, std::span<const double> thresholds,
                                        const MinkowskiOptions& options) {
  return for_all_thresholds(field, thresholds, options.boundary, 3, [&](const auto& sums, auto k) {
    return functionals_3d(sums, k, field, options.adjacency3d);
  });
}

namespace {

struct ValueRange {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();

  void extend(const GridFieldView& field) {
    validate(field, "field");
    for (std::size_t i = 0; i < field.size(); ++i)
      if (!field.void_at(i)) lo = std::min(lo, field.values[i]), hi = std::max(hi, field.values[i]);
  }

  std::vector<double> spread(std::size_t count) const {
    if (!(hi > lo) || count == 0)
      throw InputError(fmt::format(
          "cannot spread {} thresholds over the fields' values [{}, {}]; give thresholds explicitly",
          count, lo, hi));
    std::vector<double> t(count);
    for (std::size_t k = 0; k < count; ++k)
      t[k] = count == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * double(k) / double(count - 1);
    return t;
  }
};

}  // namespace

std::vector<double> linear_thresholds(std::span<const GridFieldView> fields, std::size_t count) {
  ValueRange range;
  for (const GridFieldView& field : fields) range.extend(field);
  return range.spread(count);
}

std::vector<double> linear_thresholds(const GridFieldView& field, std::size_t count) {
  ValueRange range;
  range.extend(field);
  return range.spread(count);
}

}  // namespace shockfield::analysis
