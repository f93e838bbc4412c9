#pragma once
// The Space Hierarchy Tree (SHT) of Xu et al. (2015) §3.2.1–3.2.2: an n-dimensional 2^n-tree
// (binary tree on a line, quadtree, octree) over objects with an extent — points, segments,
// triangles, tetrahedra, spheres — known only through a small adaptor over the caller's storage:
//
//   struct MyObjects {
//     std::size_t size() const;                                        // object count
//     void bounds(std::size_t i, std::array<double, N>& lo,
//                 std::array<double, N>& hi) const;                     // bounding box of object i
//   };
//
// (PointsAdaptor turns a "coordinate k of point i" accessor into one.) An object of size s (the
// longest side of its box) lives in the deepest cube of half-size h >= s that holds the centre of
// its box, so small objects sink and large ones stay high, "according to their locations and
// sizes" (Fig. 5). A cube holds at most `bucket` objects that would fit a child before it splits;
// cubes are only created where objects are, no cube is split below the resolution limit, and
// empty cubes are removed, so memory stays proportional to the objects held. The paper's three
// operations are the constructor (establish), insert and remove; the root grows when an object
// falls outside it.
//
// Searches, written once (space_tree_search.hpp): the conditional search prunes cubes with a
// may_contain(cube) test and tests objects with a condition; the minimum search ranks cubes by a
// range [m(b), M(b)] of the values their objects can take and objects by value(o).
//
// Layout for speed: a cube keeps its objects' ids together with their boxes (read from the
// adaptor once, at insertion), so a search reads one contiguous array per cube instead of the
// caller's storage in random order; condition/value may take the held object (id and box) rather
// than the id. An object whose box changes must therefore be removed and inserted again. The
// searches allocate nothing for trees of ordinary depth (their stacks and heaps live in place).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/inline_vector.hpp"

namespace shockfield::geometry {

/// Squared distance from q to the box [lo, hi] (0 inside it).
template <int N>
double distance2_to_box(const std::array<double, N>& q, const std::array<double, N>& lo,
                        const std::array<double, N>& hi) {
  double d2 = 0.0;
  for (int k = 0; k < N; ++k) {
    const double d = std::max({lo[k] - q[k], q[k] - hi[k], 0.0});
    d2 += d * d;
  }
  return d2;
}

/// An object as the tree holds it: its id (adaptor index) and its box when it was inserted;
/// for an adaptor of points (kPoint) the box is one point, stored once (32 bytes a point in 3D
/// instead of 56, so a cube's points take half the cache lines).
template <int N, bool kPoint>
struct TreeObject {
  std::uint32_t id;
  std::array<double, N> low, high;
  const std::array<double, N>& lo() const { return low; }
  const std::array<double, N>& hi() const { return high; }
  double distance2_to(const std::array<double, N>& q) const { return distance2_to_box<N>(q, low, high); }
};
template <int N>
struct TreeObject<N, true> {
  std::uint32_t id;
  std::array<double, N> low;
  const std::array<double, N>& lo() const { return low; }
  const std::array<double, N>& hi() const { return low; }
  /// |q − p|², bitwise the box distance to the box [p, p] (max(p − q, q − p, 0)² = (p − q)²).
  double distance2_to(const std::array<double, N>& q) const {
    double d2 = 0.0;
    for (int k = 0; k < N; ++k) d2 += (low[k] - q[k]) * (low[k] - q[k]);
    return d2;
  }
};

/// A cube of the tree as the searches see it: its centre and half-side, and the region its
/// objects (those of its sub-cubes included) occupy: the cube widened by `margin` on every side.
template <int N>
struct TreeCube {
  std::array<double, N> centre{};
  double half = 0.0;
  double margin = 0.0;
  double lo(int k) const { return centre[k] - half - margin; }
  double hi(int k) const { return centre[k] + half + margin; }
  /// Squared distance from q to the region (0 inside it).
  double distance2_to(const std::array<double, N>& q) const {
    std::array<double, N> l, h;
    for (int k = 0; k < N; ++k) {
      l[k] = lo(k);
      h[k] = hi(k);
    }
    return distance2_to_box<N>(q, l, h);
  }
  /// Squared distance from q to the farthest point of the region.
  double farthest2_from(const std::array<double, N>& q) const {
    double d2 = 0.0;
    for (int k = 0; k < N; ++k) {
      const double d = std::max(q[k] - lo(k), hi(k) - q[k]);
      d2 += d * d;
    }
    return d2;
  }
  /// Sub-cube b (bit k of b set: the upper half along axis k), its region widened by sub_margin.
  TreeCube sub_cube(int b, double sub_margin) const {
    TreeCube cube;
    cube.half = 0.5 * half;
    for (int k = 0; k < N; ++k)
      cube.centre[k] = centre[k] + ((b >> k & 1) ? cube.half : -cube.half);
    cube.margin = sub_margin;
    return cube;
  }
};

/// Squared distances d2[b] from q to the regions of the 2^N sub-cubes of `cube` (sub-cube b
/// widened by margins[b]), bitwise equal to cube.sub_cube(b, margins[b]).distance2_to(q). When
/// no sub-cube has a margin (a tree of points) the distance along axis k is computed once for
/// the lower half [c − h, c] and once for the upper [c, c + h] and shared by the 2^(N−1)
/// sub-cubes on that side: 2N distances and 2^N sums of N terms instead of N·2^N distances.
/// (c ± h is exact in the dyadic tree, so the terms equal those of the sub-cube's own box.)
template <int N>
[[gnu::always_inline]] inline void sub_cube_distances2(const TreeCube<N>& cube,
                                                      const std::array<double, (1 << N)>& margins,
                                                      const std::array<double, N>& q,
                                                      std::array<double, (1 << N)>& d2) {
  constexpr int kChildren = 1 << N;
  bool margins_zero = true;
  for (double m : margins) margins_zero &= m == 0.0;
  if (!margins_zero) {
    for (int b = 0; b < kChildren; ++b) d2[b] = cube.sub_cube(b, margins[b]).distance2_to(q);
    return;
  }
  std::array<std::array<double, 2>, N> side;  // side[k][upper]: squared distance along axis k
  for (int k = 0; k < N; ++k) {
    const double c = cube.centre[k], h = cube.half;
    const double lower = std::max({(c - h) - q[k], q[k] - c, 0.0});
    const double upper = std::max({c - q[k], q[k] - (c + h), 0.0});
    side[k] = {lower * lower, upper * upper};
  }
  for (int b = 0; b < kChildren; ++b) {
    double sum = 0.0;
    for (int k = 0; k < N; ++k) sum += side[k][b >> k & 1];
    d2[b] = sum;
  }
}

/// One callable made of several lambdas (a search's range or may_contain that also offers the
/// all-sub-cubes form below).
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

/// Points given coordinate by coordinate: coordinate(i, k) of point i, count points.
template <int N, class Coordinate>
struct PointsAdaptor {
  static constexpr bool kPoints = true;  ///< every box is a point (lo == hi)
  std::size_t count;
  Coordinate coordinate;
  std::size_t size() const { return count; }
  void bounds(std::size_t i, std::array<double, N>& lo, std::array<double, N>& hi) const {
    for (int k = 0; k < N; ++k) lo[k] = hi[k] = coordinate(i, k);
  }
};
template <int N, class Coordinate>
PointsAdaptor<N, Coordinate> points_adaptor(std::size_t count, Coordinate coordinate) {
  return {count, std::move(coordinate)};
}

template <class A, int N>
concept SpaceTreeAdaptor = requires(const A& a, std::size_t i, std::array<double, N>& box) {
  { a.size() } -> std::convertible_to<std::size_t>;
  a.bounds(i, box, box);
};

struct SpaceTreeOptions {
  /// Objects fitting a child that a cube holds before it splits; 0: 64 for a tree of points, 16
  /// for objects with an extent. Points: a cube of the 2^n-tree splits into 8 (3D), so its
  /// leaves hold on average between bucket/8 and bucket points; with 64 the uniform trees of
  /// 10^4-10^6 points have leaves of ~20-30 points, and a nearest query opens fewer cubes:
  /// 1.3-1.6× the rate of bucket 16 at 10^4-10^5 uniform points (bench/delaunay_bench
  /// queries; bench/RESULTS.md).
  std::size_t bucket = 0;
  double resolution = 0.0;   ///< smallest cube half-side (at least 2^-40 of the root's)
};

template <int N, SpaceTreeAdaptor<N> Adaptor>
class SpaceTree {
 public:
  using Id = std::uint32_t;
  using Point = std::array<double, N>;
  static constexpr bool kPoints = requires { requires Adaptor::kPoints; };
  using Object = TreeObject<N, kPoints>;
  static constexpr int kChildren = 1 << N;

  /// An empty tree over `objects` (nothing inserted).
  SpaceTree(const Adaptor& objects, SpaceTreeOptions options = {})
      : objects_(&objects), options_(options) {
    if (options_.bucket == 0) options_.bucket = kPoints ? 64 : 16;
  }

  /// Establishes the tree holding every object of the adaptor.
  static SpaceTree with_all(const Adaptor& objects, SpaceTreeOptions options = {}) {
    SpaceTree tree(objects, options);
    tree.insert_all();
    return tree;
  }

  void insert_all() {
    Point lo, hi, blo, bhi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < objects_->size(); ++i) {
      objects_->bounds(i, blo, bhi);
      for (int k = 0; k < N; ++k) {
        lo[k] = std::min(lo[k], blo[k]);
        hi[k] = std::max(hi[k], bhi[k]);
      }
    }
    if (objects_->size() > 0 && nodes_.empty()) make_root(lo, hi);
    for (std::size_t i = 0; i < objects_->size(); ++i) insert(static_cast<Id>(i));
    lay_out_depth_first();
  }

  /// Renumbers the cubes in depth-first order and moves each cube's objects to a fresh array in
  /// that order, so that a search walks memory forwards (done by insert_all; worth calling
  /// again after many inserts and removes). Changes nothing a search returns.
  void lay_out_depth_first();

  /// Adds object `id` (an index into the adaptor). Throws InputError for a box with NaN or
  /// infinite coordinates, or an object already held.
  void insert(Id id);
  /// Removes object `id`; false when it is not held.
  bool remove(Id id);
  bool contains(Id id) const { return id < where_.size() && where_[id].node >= 0; }
  std::size_t size() const { return held_; }
  std::size_t cube_count() const { return nodes_.size() - free_.size(); }
  const Adaptor& objects() const { return *objects_; }

  /// Checks every invariant (counts, placement by position and size, margins, locators, links,
  /// no empty cube, splitting rule); returns "" or a description of the first violation.
  std::string check() const;

  /// Conditional search (§3.2.2): visits, from the largest cube to the smallest (depth first,
  /// sub-cubes in Morton order), the cubes for which may_contain(cube) is true, skipping the
  /// others with everything below them, and calls visit(id) for each object of a visited cube
  /// with condition(object) true; visit returns false to stop the search. condition (and value
  /// below) take either the id or the held Object (id and box). may_contain may also offer the
  /// test of all sub-cubes of a cube at once, may_contain(cube, sub_margins) -> unsigned with
  /// bit b set when sub-cube b (cube.sub_cube(b, sub_margins[b])) may contain; the search then
  /// asks that once per opened cube instead of once per sub-cube (the same cubes are visited).
  template <class MayContain, class Condition, class Visit>
  void conditional_search(MayContain&& may_contain, Condition&& condition, Visit&& visit) const;

  struct Found {
    double value;
    Id id;
  };
  /// Minimum search (§3.2.2): the k objects of smallest value(id), in increasing value (fewer
  /// when fewer objects have a finite value). range(cube) returns {m, M}: bounds of the values
  /// of the objects in the cube's region, m(b) <= value <= M(b) (M = +inf when unknown). Cubes
  /// are opened depth first, as a recursive kd-tree search does, the sub-cubes of a cube from the
  /// one of least m(b) outwards (kFarthestFirst read backwards; the paper's order by m(b) over
  /// all cubes needs a heap and finds the same objects); a sub-cube is tested when its turn comes
  /// and skipped when m(b) exceeds the k-th value found by then, or (k = 1) the smallest M(b)
  /// of a cube seen (every cube holds an object); a cube with m(b) = +inf is never opened. Ties in value are resolved by the lower id (a cube whose m(b)
  /// equals the k-th value is still opened), so the result does not depend on the tree's shape.
  /// range may also offer the lower bounds of all sub-cubes of a cube at once,
  /// range(cube, sub_margins, m) filling m[b] for sub-cube b (cube.sub_cube(b, sub_margins[b]));
  /// the search then asks that once per opened cube and takes M(b) = +inf for sub-cubes (the
  /// root is ranked by range(cube)). Worth it when M(b) prunes little, as for distances, where
  /// the nearest-first order finds a good k-th value in the first leaf.
  template <class Range, class Value>
  std::vector<Found> minimum_search(std::size_t k, Range&& range, Value&& value) const {
    std::vector<Found> best;
    minimum_search_into(k, range, value, best);
    return best;
  }
  /// The same into `best` (cleared first; a std::vector or an InlineVector, which lets a
  /// nearest-point query run without allocating).
  template <class Range, class Value, class Best>
  void minimum_search_into(std::size_t k, Range&& range, Value&& value, Best& best) const;

 private:
  /// The centre and size (longest side) of an object's box.
  static void centre_and_size(const Object& o, Point& centre, double& size) {
    size = 0.0;
    for (int k = 0; k < N; ++k) {
      centre[k] = 0.5 * (o.lo()[k] + o.hi()[k]);
      size = std::max(size, o.hi()[k] - o.lo()[k]);
    }
  }
  /// The sub-cubes b ^ c of a cube, c in this order, from the sub-cube across every axis from b
  /// to b itself (c in decreasing number of set bits). The minimum search takes a cube's
  /// sub-cubes in the reverse order from b, the one of least m(b): b, then those across one
  /// axis, two, ... — near the order of m(b) (a sub-cube across more axes from q's is never
  /// nearer than the sub-cubes between) without sorting.
  static constexpr std::array<int, kChildren> kFarthestFirst = [] {
    std::array<int, kChildren> order{};
    int at = 0;
    for (int bits = N; bits >= 0; --bits)
      for (int c = 0; c < kChildren; ++c)
        if (std::popcount(unsigned(c)) == bits) order[at++] = c;
    return order;
  }();
  /// Whether a range or may_contain offers the form over all sub-cubes of a cube at once.
  template <class F>
  static constexpr bool kAllSubCubes =
      std::is_invocable_v<F&, const TreeCube<N>&, const std::array<double, kChildren>&,
                          std::array<double, kChildren>&> ||
      std::is_invocable_r_v<unsigned, F&, const TreeCube<N>&, const std::array<double, kChildren>&>;
  /// Bit p set where m[p] <= limit (NaN: never): SSE2 compares two at a time where there is
  /// SSE2 (every x86-64), the same bits one at a time elsewhere.
  static unsigned at_most_mask(const std::array<double, kChildren>& m, double limit) {
#if defined(__SSE2__)
    if constexpr (kChildren % 2 == 0) {
      const __m128d l = _mm_set1_pd(limit);
      unsigned mask = 0;
      for (int p = 0; p < kChildren; p += 2)
        mask |= unsigned(_mm_movemask_pd(_mm_cmple_pd(_mm_loadu_pd(&m[p]), l))) << p;
      return mask;
    }
#endif
    unsigned mask = 0;
    for (int p = 0; p < kChildren; ++p) mask |= unsigned(m[p] <= limit) << p;
    return mask;
  }
  /// Whether a value offers the form over coordinate columns of points,
  /// value(axes, count, out): out[i] for the point (axes[0][i], ..., axes[N-1][i]).
  template <class F>
  static constexpr bool kColumnsValue =
      std::is_invocable_v<F&, const std::array<const double*, N>&, std::size_t, double*>;
  /// The least of v[0..n) (+inf for none; a NaN never wins), two lanes at a time.
  static double least_of(const double* v, std::size_t n) {
    double a = std::numeric_limits<double>::infinity(), b = a;
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2) {
      a = v[i] < a ? v[i] : a;
      b = v[i + 1] < b ? v[i + 1] : b;
    }
    if (i < n) a = v[i] < a ? v[i] : a;
    return a < b ? a : b;
  }
  /// condition/value of a search called with the held object, or with its id.
  template <class F>
  static decltype(auto) call_on(F& f, const Object& o) {
    if constexpr (std::is_invocable_v<F&, const Object&>)
      return f(o);
    else
      return f(o.id);
  }

  /// A cube's record; what a search reads of a leaf (objects, split, child) comes first, in
  /// the first cache line (3D), what it reads of a split cube next.
  struct alignas(64) Node {
    std::vector<Object> objects;
    std::array<int, kChildren> child;
    bool split = false;
    TreeCube<N> cube;
    /// The children's margins, copied here so that a search ranks a child without reading it.
    std::array<double, kChildren> child_margin{};
    int parent = -1;
    int slot = 0;  ///< which child of the parent this cube is
    std::size_t count = 0;  ///< objects in this cube and its sub-cubes
    std::uint32_t first = 0;  ///< where its objects' coordinates start in columns_ (points)
  };
  struct Where {
    int node = -1;
    std::uint32_t slot = 0;
  };

  void make_root(const Point& lo, const Point& hi);
  void update_resolution(const Point& centre, double half);
  void grow_root_towards(const Point& c);
  int new_node(const Point& centre, double half, int parent);
  void free_node(int n);
  int child_of(const Node& node, const Point& c) const {
    int b = 0;
    for (int k = 0; k < N; ++k)
      if (c[k] >= node.cube.centre[k]) b |= 1 << k;
    return b;
  }
  /// Child b of a cube as the searches see it (from the parent's record alone).
  static TreeCube<N> child_cube(const Node& node, int b) {
    return node.cube.sub_cube(b, node.child_margin[b]);
  }
  /// Asks the processor to bring the first line of cube n's record into cache: a search pushes
  /// the sub-cubes it will open, and their loads then overlap instead of following one another.
  void prefetch(int n) const {
    __builtin_prefetch(&nodes_[n]);
    __builtin_prefetch(&nodes_[n].cube);
    if constexpr (!kPoints) __builtin_prefetch(&nodes_[n].child_margin.back());
  }
  /// The margins of a cube's sub-cubes as the searches rank them: all 0 in a tree of points
  /// (known when compiling, so that the searches neither read nor test them).
  static const std::array<double, kChildren>& sub_margins(const Node& node) {
    static constexpr std::array<double, kChildren> kNone{};
    if constexpr (kPoints)
      return kNone;
    else
      return node.child_margin;
  }
  void prefetch_objects(const Node& node) const {
    const char* first = reinterpret_cast<const char*>(node.objects.data());
    const std::size_t bytes = node.objects.size() * sizeof(Object);
    for (std::size_t at = 0; at < bytes && at < 512; at += 64) __builtin_prefetch(first + at);
  }
  /// Widens cube n's margin (and its parent's copy of it) to hold an object of this size.
  void widen(int n, double size) {
    Node& node = nodes_[n];
    node.cube.margin = std::max(node.cube.margin, 0.5 * size);
    if (node.parent >= 0) nodes_[node.parent].child_margin[node.slot] = node.cube.margin;
  }
  bool fits_child(const Node& node, double size) const {
    const double h = 0.5 * node.cube.half;
    return size <= h && h >= min_half_;
  }
  int ensure_child(int n, int b);
  void place(const Object& o, int n);
  void split(int n);
  void collapse(int n);
  void gather(int n, std::vector<Object>& out);
  std::string check_node(int n, std::size_t& counted) const;

  const Adaptor* objects_;
  SpaceTreeOptions options_;
  std::vector<Node> nodes_;
  std::vector<int> free_;
  std::vector<Where> where_;
  int root_ = -1;
  /// A tree of points: the coordinates of every held point, axis by axis, cube after cube in
  /// the depth-first order of lay_out_depth_first (which fills them); a search reads a cube's
  /// points as columns from there while no insert or remove has happened since.
  std::array<std::vector<double>, N> columns_;
  bool columns_valid_ = false;
  double min_half_ = 0.0;  ///< the resolution limit in force
  std::size_t held_ = 0;
};

}  // namespace shockfield::geometry

#include "shockfield/geometry/space_tree_impl.hpp"
#include "shockfield/geometry/space_tree_search.hpp"
