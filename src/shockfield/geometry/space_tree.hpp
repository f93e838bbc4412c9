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
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "shockfield/core/error.hpp"

namespace shockfield::geometry {

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
    double d2 = 0.0;
    for (int k = 0; k < N; ++k) {
      const double d = std::max({lo(k) - q[k], q[k] - hi(k), 0.0});
      d2 += d * d;
    }
    return d2;
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
};

/// Points given coordinate by coordinate: coordinate(i, k) of point i, count points.
template <int N, class Coordinate>
struct PointsAdaptor {
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
  std::size_t bucket = 16;   ///< objects fitting a child that a cube holds before it splits
  double resolution = 0.0;   ///< smallest cube half-side (at least 2^-40 of the root's)
};

template <int N, SpaceTreeAdaptor<N> Adaptor>
class SpaceTree {
 public:
  using Id = std::uint32_t;
  using Point = std::array<double, N>;
  static constexpr int kChildren = 1 << N;

  /// An empty tree over `objects` (nothing inserted).
  SpaceTree(const Adaptor& objects, SpaceTreeOptions options = {})
      : objects_(&objects), options_(options) {}

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
  }

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
  /// with condition(id) true; visit returns false to stop the search.
  template <class MayContain, class Condition, class Visit>
  void conditional_search(MayContain&& may_contain, Condition&& condition, Visit&& visit) const;

  struct Found {
    double value;
    Id id;
  };
  /// Minimum search (§3.2.2): the k objects of smallest value(id), in increasing value (fewer
  /// when fewer objects have a finite value). range(cube) returns {m, M}: bounds of the values
  /// of the objects in the cube's region, m(b) <= value <= M(b) (M = +inf when unknown). Cubes
  /// are opened in increasing m(b); a cube is skipped when m(b) exceeds the k-th value found, or
  /// (k = 1) the smallest M(b) of a cube seen (every cube holds an object); a cube with
  /// m(b) = +inf is never opened. Ties in value are resolved by the lower id (a cube whose m(b)
  /// equals the k-th value is still opened), so the result does not depend on the tree's shape.
  template <class Range, class Value>
  std::vector<Found> minimum_search(std::size_t k, Range&& range, Value&& value) const;

  /// The centre and size (longest side) of an object's box.
  void centre_and_size(Id id, Point& centre, double& size) const {
    Point lo, hi;
    objects_->bounds(id, lo, hi);
    size = 0.0;
    for (int k = 0; k < N; ++k) {
      centre[k] = 0.5 * (lo[k] + hi[k]);
      size = std::max(size, hi[k] - lo[k]);
    }
  }

 private:
  struct Node {
    TreeCube<N> cube;
    int parent = -1;
    bool split = false;
    std::array<int, kChildren> child;
    std::size_t count = 0;  ///< objects in this cube and its sub-cubes
    std::vector<Id> objects;
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
  bool fits_child(const Node& node, double size) const {
    const double h = 0.5 * node.cube.half;
    return size <= h && h >= min_half_;
  }
  int ensure_child(int n, int b);
  void place(Id id, int n);
  void split(int n);
  void collapse(int n);
  void gather(int n, std::vector<Id>& out);
  std::string check_node(int n, std::size_t& counted) const;

  const Adaptor* objects_;
  SpaceTreeOptions options_;
  std::vector<Node> nodes_;
  std::vector<int> free_;
  std::vector<Where> where_;
  int root_ = -1;
  double min_half_ = 0.0;  ///< the resolution limit in force
  std::size_t held_ = 0;
};

}  // namespace shockfield::geometry

#include "shockfield/geometry/space_tree_impl.hpp"
