// Bowyer–Watson Delaunay division (Xu et al. 2015 §3.2.3, Fig. 11) with a vertex at infinity;
// see delaunay.hpp for which seed step is which function.
#include "shockfield/geometry/delaunay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/predicates.hpp"
#include "shockfield/geometry/spatial_sort.hpp"

namespace shockfield::geometry {
namespace {

constexpr std::int32_t kInfinite = -1;

template <int N>
class Triangulation {
 public:
  using Point = std::array<double, N>;
  using Cell = std::array<std::int32_t, N + 1>;

  /// Vertices are indices into `points` (given in insertion order, so that the points of
  /// neighbouring cells sit close in memory, as in CGAL's vertex storage); original[v] is the
  /// caller's index of vertex v: its rank in the perturbation and its name in the output.
  Triangulation(const std::vector<Point>& points, const std::vector<std::int32_t>& original)
      : points_(points), original_(original) {}

  /// The first simplex (positively oriented) and the N+1 cells through the vertex at infinity.
  void start(const Cell& first);
  void insert(std::int32_t p);
  DelaunayDivision<N> finish(DelaunayDivision<N> out) const;

 private:
  struct Boundary {
    std::int32_t cell, face, outside;
  };
  const double* at(std::int32_t v) const { return points_[v].data(); }
  int infinite_slot(std::int32_t c) const {
    for (int i = 0; i <= N; ++i)
      if (cells_[c][i] == kInfinite) return i;
    return -1;
  }
  /// Orientation of cell c with its vertex i replaced by p.
  int orient_replaced(std::int32_t c, int i, std::int32_t p) const {
    PointRefs<N + 1> r;
    for (int j = 0; j <= N; ++j) r[j] = j == i ? at(p) : at(cells_[c][j]);
    return orient<N>(r);
  }
  bool in_conflict(std::int32_t c, std::int32_t p) const;
  std::int32_t locate(std::int32_t p);
  std::int32_t new_cell(const Cell& v);
  void link_new_cells();

  const std::vector<Point>& points_;
  const std::vector<std::int32_t>& original_;
  std::vector<Cell> cells_, nb_;
  std::vector<char> alive_;
  std::vector<std::int32_t> free_;
  std::vector<std::uint32_t> mark_;  // == stamp_: in the current cavity; == stamp_ + 1: tested, outside
  std::uint32_t stamp_ = 0;
  std::int32_t last_ = 0;
  std::vector<std::int32_t> created_, cavity_;
  std::vector<Boundary> boundary_;
  using FaceKey = std::array<std::int32_t, N>;
  struct FaceSlot {
    FaceKey key{};
    std::int32_t cell = 0;
    int slot = 0;
    std::uint32_t stamp = 0;  ///< == link_stamp_: entered by the current link_new_cells
    bool matched = false;
  };
  /// The vertices of cell v but v[i], sorted (a sorting network kept in registers).
  static FaceKey sorted_face(const Cell& v, int i) {
    FaceKey key;
    for (int j = 0, r = 0; j <= N; ++j)
      if (j != i) key[r++] = v[j];
    auto order = [&](int a, int b) {
      const std::int32_t lo = std::min(key[a], key[b]), hi = std::max(key[a], key[b]);
      key[a] = lo;
      key[b] = hi;
    };
    order(0, 1);
    if constexpr (N == 3) {
      order(1, 2);
      order(0, 1);
    }
    return key;
  }
  static bool same_face(const FaceKey& a, const FaceKey& b) {
    bool same = true;
    for (int k = 0; k < N; ++k) same &= a[k] == b[k];
    return same;
  }
  std::vector<FaceSlot> table_;
  std::uint32_t link_stamp_ = 0;
  std::minstd_rand rng_{12345};
};

template <int N>
std::int32_t Triangulation<N>::new_cell(const Cell& v) {
  std::int32_t c;
  if (!free_.empty()) {
    c = free_.back();
    free_.pop_back();
  } else {
    c = static_cast<std::int32_t>(cells_.size());
    cells_.emplace_back();
    nb_.emplace_back();
    alive_.push_back(0);
    mark_.push_back(0);
  }
  cells_[c] = v;
  nb_[c].fill(kInfinite);
  alive_[c] = 1;
  created_.push_back(c);
  return c;
}

template <int N>
void Triangulation<N>::start(const Cell& first) {
  created_.clear();
  last_ = new_cell(first);
  for (int i = 0; i <= N; ++i) {
    // Face i of the first simplex, closed by the vertex at infinity in place of vertex i; two
    // finite vertices are swapped so that the cell is positive (∞ stands beyond the face).
    Cell v = first;
    v[i] = kInfinite;
    const int a = (i + 1) % (N + 1), b = (i + 2) % (N + 1);
    std::swap(v[a], v[b]);
    const std::int32_t c = new_cell(v);
    nb_[c][i] = last_;
    nb_[last_][i] = c;
  }
  created_.erase(created_.begin());  // the finite cell's links are set; link the others
  link_new_cells();
}

/// Every face of the created cells whose neighbour is not yet set is matched with the other
/// created cell having the same face (the same vertex set): faces are entered in an
/// open-addressing hash table kept between calls, its slots of earlier calls told apart by a
/// stamp, so linking a cavity allocates nothing and costs O(faces).
template <int N>
void Triangulation<N>::link_new_cells() {
  const std::size_t faces = created_.size() * (N + 1);
  if (table_.size() < 2 * faces || link_stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::size_t size = 64;
    while (size < 2 * faces) size *= 2;
    table_.assign(size, FaceSlot{});
    link_stamp_ = 0;
  }
  ++link_stamp_;
  const std::size_t mask = table_.size() - 1;
  std::size_t unmatched = 0;
  for (const std::int32_t c : created_) {
    for (int i = 0; i <= N; ++i) {
      if (nb_[c][i] != kInfinite) continue;
      const FaceKey key = sorted_face(cells_[c], i);
      std::uint64_t h = 0;
      for (std::int32_t v : key) h = (h ^ static_cast<std::uint32_t>(v)) * 0x9E3779B97F4A7C15ull;
      for (std::size_t s = (h >> 32) & mask;; s = (s + 1) & mask) {
        FaceSlot& slot = table_[s];
        if (slot.stamp != link_stamp_) {  // free: the first of the pair
          slot.key = key;
          slot.cell = c;
          slot.slot = i;
          slot.stamp = link_stamp_;
          slot.matched = false;
          ++unmatched;
          break;
        }
        if (!same_face(slot.key, key)) continue;
        if (slot.matched)
          throw RunError("delaunay: a face of the cavity is shared by three cells (internal error)");
        slot.matched = true;
        nb_[c][i] = slot.cell;
        nb_[slot.cell][slot.slot] = c;
        --unmatched;
        break;
      }
    }
  }
  if (unmatched != 0)
    throw RunError("delaunay: the cavity of an inserted point is not a ball (internal error)");
}

template <int N>
bool Triangulation<N>::in_conflict(std::int32_t c, std::int32_t p) const {
  const int inf = infinite_slot(c);
  if (inf < 0) {
    PointRefs<N + 2> r;
    std::array<std::int64_t, N + 2> rank;
    for (int j = 0; j <= N; ++j) {
      r[j] = at(cells_[c][j]);
      rank[j] = original_[cells_[c][j]];
    }
    r[N + 1] = at(p);
    rank[N + 1] = original_[p];
    return in_sphere_perturbed<N>(r, rank) > 0;
  }
  // Through the vertex at infinity: P strictly beyond the hull face; on its plane, the answer of
  // the finite cell across the face (the limit of the same perturbed determinant).
  const int o = orient_replaced(c, inf, p);
  if (o != 0) return o > 0;
  return in_conflict(nb_[c][inf], p);
}

template <int N>
std::int32_t Triangulation<N>::locate(std::int32_t p) {
  std::int32_t c = last_;
  if (!alive_[c]) c = created_.empty() ? 0 : created_.back();
  if (int inf = infinite_slot(c); inf >= 0) c = nb_[c][inf];
  int came_from = -1;
  const std::size_t limit = 4 * cells_.size() + 100;
  for (std::size_t step = 0; step < limit; ++step) {
    const int offset = static_cast<int>(rng_() % (N + 1));
    bool moved = false;
    for (int j = 0; j <= N && !moved; ++j) {
      const int i = (offset + j) % (N + 1);
      if (i == came_from || orient_replaced(c, i, p) >= 0) continue;
      const std::int32_t next = nb_[c][i];
      if (infinite_slot(next) >= 0) return next;  // p is beyond this hull face
      came_from = static_cast<int>(std::find(nb_[next].begin(), nb_[next].end(), c) -
                                   nb_[next].begin());
      c = next;
      moved = true;
    }
    if (!moved) return c;  // p in the closed simplex c: inside its circumsphere
  }
  // Never expected (a visibility walk in a Delaunay triangulation ends): search every cell.
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(cells_.size()); ++k)
    if (alive_[k] && in_conflict(k, p)) return k;
  throw RunError("delaunay: no simplex conflicts with an inserted point (internal error)");
}

template <int N>
void Triangulation<N>::insert(std::int32_t p) {
  const std::int32_t start = locate(p);
  stamp_ += 2;
  cavity_.assign(1, start);
  boundary_.clear();
  mark_[start] = stamp_;
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const std::int32_t c = cavity_[k];
    for (int i = 0; i <= N; ++i) {
      const std::int32_t n = nb_[c][i];
      if (mark_[n] == stamp_) continue;
      if (mark_[n] != stamp_ + 1 && in_conflict(n, p)) {
        mark_[n] = stamp_;
        cavity_.push_back(n);
      } else {
        mark_[n] = stamp_ + 1;
        boundary_.push_back({c, i, n});
      }
    }
  }
  // Link each boundary face of the cavity to p (replacing the cavity vertex opposite it).
  created_.clear();
  for (const Boundary& b : boundary_) {
    Cell v = cells_[b.cell];
    v[b.face] = p;
    const std::int32_t c = new_cell(v);
    nb_[c][b.face] = b.outside;
    for (auto& back : nb_[b.outside])
      if (back == b.cell) back = c;
  }
  for (std::int32_t c : cavity_) {
    alive_[c] = 0;
    free_.push_back(c);
  }
  link_new_cells();
  last_ = created_.back();
}

template <int N>
DelaunayDivision<N> Triangulation<N>::finish(DelaunayDivision<N> out) const {
  std::vector<std::int32_t> index(cells_.size(), -1);
  for (std::size_t c = 0; c < cells_.size(); ++c)
    if (alive_[c] && infinite_slot(static_cast<std::int32_t>(c)) < 0) {
      index[c] = static_cast<std::int32_t>(out.simplices.size());
      Cell named;
      for (int i = 0; i <= N; ++i) named[i] = original_[cells_[c][i]];
      out.simplices.push_back(named);
    }
  out.neighbours.resize(out.simplices.size());
  for (std::size_t c = 0; c < cells_.size(); ++c)
    if (index[c] >= 0)
      for (int i = 0; i <= N; ++i) out.neighbours[index[c]][i] = index[nb_[c][i]];
  return out;
}

/// Points on one line (2D) or plane (3D): finds N+1 affinely independent points, in the order given.
template <int N>
bool first_simplex(const std::vector<std::array<double, N>>& pts,
                   const std::vector<std::int32_t>& order, std::array<std::int32_t, N + 1>& s) {
  s[0] = order[0];
  std::size_t k = 1;
  s[1] = order[k++];  // distinct from s[0]: duplicates are gone
  auto collinear = [&](std::int32_t c) {
    // Three points on one line: every coordinate-plane projection is collinear (exact).
    for (int a = 0; a < N; ++a)
      for (int b = a + 1; b < N; ++b) {
        const std::array<double, 2> p{pts[s[0]][a], pts[s[0]][b]}, q{pts[s[1]][a], pts[s[1]][b]},
            r{pts[c][a], pts[c][b]};
        if (orient<2>({p.data(), q.data(), r.data()}) != 0) return false;
      }
    return true;
  };
  while (k < order.size() && collinear(order[k])) ++k;
  if (k == order.size()) return false;
  s[2] = order[k++];
  if constexpr (N == 3) {
    auto flat = [&](std::int32_t c) {
      return orient<3>({pts[s[0]].data(), pts[s[1]].data(), pts[s[2]].data(), pts[c].data()}) == 0;
    };
    while (k < order.size() && flat(order[k])) ++k;
    if (k == order.size()) return false;
    s[3] = order[k];
  }
  PointRefs<N + 1> r;
  for (int j = 0; j <= N; ++j) r[j] = pts[s[j]].data();
  if (orient<N>(r) < 0) std::swap(s[0], s[1]);
  return true;
}

}  // namespace

template <int N>
DelaunayDivision<N> delaunay_division(std::vector<std::array<double, N>> points,
                                      const std::string& source) {
  DelaunayDivision<N> out;
  const std::size_t n = points.size();
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 2))
    throw InputError(fmt::format("{}: {} points are more than the division can index", source, n));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < N; ++k)
      if (!std::isfinite(points[i][k]))
        throw InputError(fmt::format("{}: point {} has a non-finite coordinate ({})", source,
                                     i + 1, points[i][k]));
  out.points = std::move(points);
  const auto& pts = out.points;
  // Duplicates: equal points next to each other in lexicographic order.
  std::vector<std::int32_t> sorted(n);
  std::iota(sorted.begin(), sorted.end(), 0);
  std::sort(sorted.begin(), sorted.end(), [&](std::int32_t a, std::int32_t b) {
    return pts[a] < pts[b] || (pts[a] == pts[b] && a < b);
  });
  out.representative.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t i = sorted[k];
    const bool dup = k > 0 && pts[sorted[k - 1]] == pts[i];
    out.representative[i] = dup ? out.representative[sorted[k - 1]] : i;
    out.duplicates += dup;
  }
  const std::size_t distinct = n - out.duplicates;
  if (distinct < N + 1)
    throw InputError(fmt::format("{}: {} distinct points; a {}D Delaunay division needs at least {}",
                                 source, distinct, N, N + 1));
  // The order of insertion: BRIO rounds along a Hilbert curve (spatial_sort.hpp), where the
  // paper takes the points off its point tree tp.
  std::vector<std::int32_t> unique;
  unique.reserve(distinct);
  for (std::size_t i = 0; i < n; ++i)
    if (out.representative[i] == static_cast<std::int32_t>(i))
      unique.push_back(static_cast<std::int32_t>(i));
  const std::vector<std::int32_t> order = brio_hilbert_order<N>(pts, std::move(unique));
  // The points copied in that order: vertex v of the triangulation is point order[v].
  std::vector<std::array<double, N>> ordered(order.size());
  std::vector<std::int32_t> vertices(order.size());
  for (std::size_t v = 0; v < order.size(); ++v) {
    ordered[v] = pts[order[v]];
    vertices[v] = static_cast<std::int32_t>(v);
  }
  std::array<std::int32_t, N + 1> first;
  if (!first_simplex<N>(ordered, vertices, first))
    throw InputError(fmt::format("{}: all {} distinct points lie on one {}; a {}D Delaunay "
                                 "division needs points spanning the {}",
                                 source, distinct, N == 2 ? "line" : "plane", N,
                                 N == 2 ? "plane" : "space"));
  Triangulation<N> t(ordered, order);
  t.start(first);
  for (std::int32_t v : vertices)
    if (std::find(first.begin(), first.end(), v) == first.end()) t.insert(v);
  return t.finish(std::move(out));
}

template DelaunayDivision<2> delaunay_division<2>(std::vector<std::array<double, 2>>,
                                                  const std::string&);
template DelaunayDivision<3> delaunay_division<3>(std::vector<std::array<double, 3>>,
                                                  const std::string&);

}  // namespace shockfield::geometry
