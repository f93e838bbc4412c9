#pragma once
// SpaceTree's establish/insert/remove and invariant checker (included by space_tree.hpp; the
// searches are in space_tree_search.hpp).
#include <cmath>
#include <string>
#include <tuple>

#include <fmt/format.h>

namespace shockfield::geometry {

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::make_root(const Point& lo, const Point& hi) {
  // A dyadic root: its half-side a power of two, its centre a multiple of half/64 (a power of
  // two), so that every sub-cube's centre (centre ± half/2, ± half/4, ...) is exact down to the
  // resolution limit and a point's cube by the comparisons c >= centre always holds it by
  // |c − centre| <= half. The smallest such cube that holds the box (half-sides from about a
  // quarter of the box's longest side up; a half-side of at least the longest side always
  // does), so that no search walks through cubes of one sub-cube above the objects and the
  // leaves fit the data (the unit cube: root [0, 1]³, not [−2, 2]³; a crystal from −0.1 to 62.9:
  // [−0.5, 63.5]³, not [−64, 64]³).
  double extent = 0.0;
  for (int k = 0; k < N; ++k) extent = std::max(extent, hi[k] - lo[k]);
  double half = std::ldexp(1.0, std::ilogb(extent > 0.0 ? extent : 1.0) - 1);
  Point centre;
  for (;; half *= 2.0) {
    bool holds = true;
    const double grid = std::ldexp(half, -6);
    for (int k = 0; k < N; ++k) {
      centre[k] = std::round(0.5 * (lo[k] + hi[k]) / grid) * grid;
      holds &= lo[k] >= centre[k] - half && hi[k] <= centre[k] + half;
    }
    if (holds) break;
  }
  root_ = new_node(centre, half, -1);
  update_resolution(centre, half);
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::update_resolution(const Point& centre, double half) {
  // No cube below 2^-40 of the root, nor so small that centre ± half/2 would round (2^-50 of the
  // largest centre coordinate).
  double biggest = 0.0;
  for (int k = 0; k < N; ++k) biggest = std::max(biggest, std::abs(centre[k]));
  min_half_ = std::max({options_.resolution, std::ldexp(half, -40), std::ldexp(biggest, -50)});
}

template <int N, SpaceTreeAdaptor<N> A>
int SpaceTree<N, A>::new_node(const Point& centre, double half, int parent) {
  int n;
  if (!free_.empty()) {
    n = free_.back();
    free_.pop_back();
    nodes_[n] = Node{};
  } else {
    n = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
  }
  Node& node = nodes_[n];
  node.cube.centre = centre;
  node.cube.half = half;
  node.parent = parent;
  node.child.fill(-1);
  return n;
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::free_node(int n) {
  nodes_[n].objects.clear();
  nodes_[n].objects.shrink_to_fit();
  nodes_[n].count = 0;
  free_.push_back(n);
}

template <int N, SpaceTreeAdaptor<N> A>
int SpaceTree<N, A>::ensure_child(int n, int b) {
  if (nodes_[n].child[b] >= 0) return nodes_[n].child[b];
  const double h = 0.5 * nodes_[n].cube.half;
  Point c = nodes_[n].cube.centre;
  for (int k = 0; k < N; ++k) c[k] += (b >> k & 1) ? h : -h;
  const int child = new_node(c, h, n);  // may reallocate nodes_
  nodes_[child].slot = b;
  nodes_[n].child[b] = child;
  nodes_[n].child_margin[b] = 0.0;
  return child;
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::grow_root_towards(const Point& c) {
  // The old root becomes the child, on the side away from c, of a root twice its size.
  const Node& old = nodes_[root_];
  const double h = old.cube.half;
  Point centre = old.cube.centre;
  int b = 0;
  for (int k = 0; k < N; ++k) {
    if (c[k] >= centre[k]) {
      centre[k] += h;  // old root is the lower child along k
    } else {
      centre[k] -= h;
      b |= 1 << k;
    }
  }
  const int old_root = root_;
  root_ = new_node(centre, 2.0 * h, -1);
  Node& root = nodes_[root_];
  root.split = true;
  root.child[b] = old_root;
  root.count = nodes_[old_root].count;
  root.cube.margin = nodes_[old_root].cube.margin;
  root.child_margin[b] = root.cube.margin;
  nodes_[old_root].parent = root_;
  nodes_[old_root].slot = b;
  update_resolution(centre, 2.0 * h);
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::place(const Object& o, int n) {
  Node& node = nodes_[n];
  where_[o.id] = Where{n, static_cast<std::uint32_t>(node.objects.size())};
  node.objects.push_back(o);
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::insert(Id id) {
  if (id >= objects_->size())
    throw InputError(fmt::format("space tree: object {} is not in the adaptor ({} objects)", id,
                                 objects_->size()));
  if (contains(id)) throw InputError(fmt::format("space tree: object {} is already held", id));
  columns_valid_ = false;
  Object o{};
  o.id = id;
  {
    Point lo, hi;
    objects_->bounds(id, lo, hi);
    o.low = lo;
    if constexpr (!kPoints) o.high = hi;
  }
  Point c;
  double size;
  centre_and_size(o, c, size);
  for (int k = 0; k < N; ++k)
    if (!std::isfinite(c[k]) || !std::isfinite(size))
      throw InputError(fmt::format("space tree: object {} has a non-finite coordinate", id));
  if (where_.size() <= id) where_.resize(std::max<std::size_t>(objects_->size(), id + 1));
  if (root_ < 0) make_root(c, c);
  auto inside = [&](const Node& node) {
    for (int k = 0; k < N; ++k)
      if (std::abs(c[k] - node.cube.centre[k]) > node.cube.half) return false;
    return true;
  };
  while (!inside(nodes_[root_]) || size > nodes_[root_].cube.half) grow_root_towards(c);
  int n = root_;
  for (;;) {
    Node& node = nodes_[n];
    ++node.count;
    widen(n, size);
    if (!node.split || !fits_child(node, size)) break;
    n = ensure_child(n, child_of(node, c));
  }
  place(o, n);
  ++held_;
  const Node& leaf = nodes_[n];
  if (!leaf.split && leaf.objects.size() > options_.bucket) split(n);
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::split(int n) {
  // Count the objects that would go down; split only when they exceed the bucket.
  std::size_t movable = 0;
  Point c;
  double size;
  for (const Object& o : nodes_[n].objects) {
    centre_and_size(o, c, size);
    movable += fits_child(nodes_[n], size);
  }
  if (movable <= options_.bucket) return;
  nodes_[n].split = true;
  std::vector<Object> all = std::move(nodes_[n].objects);
  nodes_[n].objects.clear();
  for (const Object& o : all) {
    centre_and_size(o, c, size);
    if (!fits_child(nodes_[n], size)) {
      place(o, n);
      continue;
    }
    const int child = ensure_child(n, child_of(nodes_[n], c));
    ++nodes_[child].count;
    widen(child, size);
    place(o, child);
  }
  for (int b = 0; b < kChildren; ++b) {
    const int child = nodes_[n].child[b];
    if (child >= 0 && nodes_[child].objects.size() > options_.bucket) split(child);
  }
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::lay_out_depth_first() {
  if (root_ < 0) return;
  std::vector<int> order, renumbered(nodes_.size(), -1), stack{root_};
  order.reserve(cube_count());
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    renumbered[n] = static_cast<int>(order.size());
    order.push_back(n);
    for (int b = kChildren - 1; b >= 0; --b)
      if (nodes_[n].child[b] >= 0) stack.push_back(nodes_[n].child[b]);
  }
  std::vector<Node> laid(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    Node& node = laid[i];
    const Node& old = nodes_[order[i]];
    node.cube = old.cube;
    node.parent = old.parent < 0 ? -1 : renumbered[old.parent];
    node.slot = old.slot;
    node.split = old.split;
    node.child_margin = old.child_margin;
    for (int b = 0; b < kChildren; ++b)
      node.child[b] = old.child[b] < 0 ? -1 : renumbered[old.child[b]];
    node.count = old.count;
    node.objects.assign(old.objects.begin(), old.objects.end());  // allocated in this order
    for (const Object& o : node.objects) where_[o.id].node = static_cast<int>(i);
  }
  nodes_ = std::move(laid);
  free_.clear();
  root_ = renumbered[root_];
  if constexpr (kPoints) {
    for (auto& column : columns_) {
      column.clear();
      column.reserve(held_);
    }
    for (Node& node : nodes_) {
      node.first = static_cast<std::uint32_t>(columns_[0].size());
      for (const Object& o : node.objects)
        for (int k = 0; k < N; ++k) columns_[k].push_back(o.low[k]);
    }
    columns_valid_ = true;
  }
}

template <int N, SpaceTreeAdaptor<N> A>
bool SpaceTree<N, A>::remove(Id id) {
  if (!contains(id)) return false;
  columns_valid_ = false;
  const Where w = where_[id];
  Node& node = nodes_[w.node];
  const Object moved = node.objects.back();
  node.objects[w.slot] = moved;
  where_[moved.id].slot = w.slot;
  node.objects.pop_back();
  where_[id] = Where{};
  --held_;
  // Walk up: fix counts, drop empty cubes, and remember the highest split cube that has become
  // small enough to hold its whole subtree again.
  int collapse_at = -1;
  for (int n = w.node; n >= 0;) {
    Node& cur = nodes_[n];
    --cur.count;
    const int parent = cur.parent;
    if (cur.count == 0 && parent >= 0) {
      for (int& c : nodes_[parent].child)
        if (c == n) c = -1;
      free_node(n);  // its children, empty too, were unlinked on the way up
    } else if (cur.split && cur.count <= options_.bucket / 2) {
      collapse_at = n;
    }
    n = parent;
  }
  if (collapse_at >= 0 && nodes_[collapse_at].count > 0) collapse(collapse_at);
  if (held_ == 0) {
    nodes_.clear();
    free_.clear();
    root_ = -1;
  }
  return true;
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::gather(int n, std::vector<Object>& out) {
  Node& node = nodes_[n];
  out.insert(out.end(), node.objects.begin(), node.objects.end());
  for (int c : node.child)
    if (c >= 0) {
      gather(c, out);
      free_node(c);
    }
}

template <int N, SpaceTreeAdaptor<N> A>
void SpaceTree<N, A>::collapse(int n) {
  std::vector<Object> all;
  gather(n, all);
  Node& node = nodes_[n];
  node.objects.clear();
  node.child.fill(-1);
  node.split = false;
  for (const Object& o : all) place(o, n);
}

template <int N, SpaceTreeAdaptor<N> A>
std::string SpaceTree<N, A>::check_node(int n, std::size_t& counted) const {
  const Node& node = nodes_[n];
  std::size_t sub = node.objects.size(), movable = 0;
  for (std::size_t s = 0; s < node.objects.size(); ++s) {
    const Object& o = node.objects[s];
    const Id id = o.id;
    if (id >= where_.size() || where_[id].node != n || where_[id].slot != s)
      return fmt::format("object {} in cube {} has a wrong locator", id, n);
    Point lo, hi;
    objects_->bounds(id, lo, hi);
    if (lo != o.lo() || hi != o.hi())
      return fmt::format("object {} in cube {} holds a box other than the adaptor's", id, n);
    if constexpr (kPoints)
      for (int k = 0; k < N && columns_valid_; ++k)
        if (columns_[k].size() <= node.first + s || columns_[k][node.first + s] != o.low[k])
          return fmt::format("object {} in cube {}: its coordinate columns differ", id, n);
    Point c;
    double size;
    centre_and_size(o, c, size);
    for (int k = 0; k < N; ++k)
      if (std::abs(c[k] - node.cube.centre[k]) > node.cube.half)
        return fmt::format("object {} lies outside its cube {}", id, n);
    if (0.5 * size > node.cube.margin) return fmt::format("cube {} margin too small", n);
    if (n != root_ && size > node.cube.half)
      return fmt::format("object {} is too large for cube {}", id, n);
    if (node.split && fits_child(node, size))
      return fmt::format("object {} in split cube {} fits a child", id, n);
    movable += fits_child(node, size);
  }
  if (!node.split && movable > options_.bucket)
    return fmt::format("leaf cube {} holds {} objects that fit a child (bucket {})", n, movable,
                       options_.bucket);
  if (!node.split && n != root_ && node.objects.empty())
    return fmt::format("leaf cube {} is empty", n);
  for (int b = 0; b < kChildren; ++b) {
    const int c = node.child[b];
    if (c < 0) continue;
    if (!node.split) return fmt::format("leaf cube {} has children", n);
    const Node& ch = nodes_[c];
    if (ch.parent != n || ch.cube.half != 0.5 * node.cube.half)
      return fmt::format("cube {} is linked wrongly to parent {}", c, n);
    if (ch.count == 0) return fmt::format("cube {} is empty", c);
    if (ch.cube.margin > node.cube.margin) return fmt::format("cube {} margin exceeds parent", c);
    if (ch.slot != b || node.child_margin[b] != ch.cube.margin)
      return fmt::format("cube {}: its parent {} records a wrong slot or margin", c, n);
    sub += ch.count;
    if (std::string e = check_node(c, counted); !e.empty()) return e;
  }
  if (sub != node.count)
    return fmt::format("cube {} counts {} objects, holds {}", n, node.count, sub);
  counted += node.objects.size();
  return {};
}

template <int N, SpaceTreeAdaptor<N> A>
std::string SpaceTree<N, A>::check() const {
  if (root_ < 0) return held_ == 0 ? std::string{} : "no root but objects held";
  std::size_t counted = 0;
  if (std::string e = check_node(root_, counted); !e.empty()) return e;
  if (counted != held_) return fmt::format("{} objects found, {} held", counted, held_);
  return {};
}

}  // namespace shockfield::geometry
