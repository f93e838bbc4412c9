#pragma once
// SpaceTree's two generic searches of Xu et al. (2015)'s GISO design, the conditional search (maycontain(b)
// prunes cubes, an identification function tests objects) and the minimum search (a value with range
// bounds m(b) on cubes), on which every query and searcher is built (included by space_tree.hpp).
#include <algorithm>
#include <vector>

namespace shockfield::geometry {

template <int N, SpaceTreeAdaptor<N> A>
template <class MayContain, class Condition, class Visit>
void SpaceTree<N, A>::conditional_search(MayContain&& may_contain, Condition&& condition,
                                         Visit&& visit) const {
  if (root_ < 0 || !may_contain(nodes_[root_].cube)) return;
  InlineVector<int, 256> stack;  // cubes found to may_contain, not yet visited
  stack.push_back(root_);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    prefetch_objects(node);  // arriving while the sub-cubes are tested
    if (node.split) {
      unsigned open = 0;  // bit b: sub-cube b may contain
      if constexpr (kAllSubCubes<MayContain>)
        open = may_contain(node.cube, sub_margins(node));
      else
        for (int b = 0; b < kChildren; ++b)
          if (node.child[b] >= 0 && may_contain(child_cube(node, b))) open |= 1u << b;
      for (int b = kChildren - 1; b >= 0; --b)  // popped in Morton order
        if ((open >> b & 1) && node.child[b] >= 0) {
          prefetch(node.child[b]);
          stack.push_back(node.child[b]);
        }
    }
    for (const Object& o : node.objects)
      if (call_on(condition, o) && !visit(o.id)) return;
  }
}

template <int N, SpaceTreeAdaptor<N> A>
template <class Range, class Value, class Best>
void SpaceTree<N, A>::minimum_search_into(std::size_t k, Range&& range, Value&& value,
                                          Best& best) const {
  best.clear();  // a max-heap on value, at most k
  if (root_ < 0 || k == 0) return;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Ties in value go to the lower id: (value, id) compared lexicographically.
  auto worse = [](const Found& a, const Found& b) {
    return a.value < b.value || (a.value == b.value && a.id < b.id);
  };
  double upper = kInf;  // min M(b) seen, used when k == 1
  // A cube is opened when m(b) <= bound(): m(b) > the k-th value found (or, k = 1, > a cube's
  // M) rules it out.
  auto bound = [&] { return best.size() == k ? std::min(upper, best.front().value) : upper; };
  // Depth first, as a recursive kd-tree search: one frame per split cube on the path from the
  // root, holding its sub-cubes from the one of least m(b) outwards (b = nearest ^ c, c along
  // kFarthestFirst read backwards) with their m(b) (NaN where there is no sub-cube or m(b) is
  // +inf, so that no bound opens it). A frame's next sub-cube is the first one not yet taken
  // with m(b) <= bound() at the moment it is taken: all 2^N tested at once, so a cube whose
  // remaining sub-cubes the values found so far rule out is left at once.
  struct Frame {
    std::array<double, kChildren> m;
    std::array<int, kChildren> child;
    unsigned taken;  ///< positions below this one were taken or passed over (no default
                     ///< value: the frames in place would all be written per search)
  };
  InlineVector<Frame, 48> path;
  // The values of a cube's objects, a chunk at a time: from the coordinate columns when the
  // value offers that form and they are valid (a loop the compiler vectorises), else one object
  // at a time.
  constexpr std::size_t kChunk = 64;
  std::array<double, kChunk> values;
  auto measure = [&](const Node& node) {
    const std::size_t count = node.objects.size();
    for (std::size_t from = 0; from < count; from += kChunk) {
      const std::size_t size = std::min(kChunk, count - from);
      const Object* objects = node.objects.data() + from;
      bool from_columns = false;
      if constexpr (kPoints && kColumnsValue<Value>) {
        if (columns_valid_) {
          std::array<const double*, N> axes;
          for (int axis = 0; axis < N; ++axis)
            axes[axis] = columns_[axis].data() + node.first + from;
          value(axes, size, values.data());
          from_columns = true;
        }
      }
      if (!from_columns)
        for (std::size_t i = 0; i < size; ++i) values[i] = call_on(value, objects[i]);
      if (k == 1) {  // the heap of one: the chunk's least value, then the lowest id having it
        const double low = least_of(values.data(), size);
        if (!(low < kInf) || (!best.empty() && low > best.front().value)) continue;
        Found least = best.empty() || low < best.front().value
                          ? Found{low, std::numeric_limits<Id>::max()}
                          : best.front();
        for (std::size_t i = 0; i < size; ++i)
          if (values[i] == low && objects[i].id < least.id) least.id = objects[i].id;
        best.clear();
        best.push_back(least);
        continue;
      }
      for (std::size_t i = 0; i < size; ++i) {
        const Found f{values[i], objects[i].id};
        if (!(f.value < kInf)) continue;
        if (best.size() < k) {
          best.push_back(f);
          std::push_heap(best.begin(), best.end(), worse);
        } else if (worse(f, best.front())) {
          std::pop_heap(best.begin(), best.end(), worse);
          best.back() = f;
          std::push_heap(best.begin(), best.end(), worse);
        }
      }
    }
  };
  // Opens cube n and goes on down into the sub-cube of least m(b) while it is within the bound
  // (the first sub-cube a frame gives: taken at once, without testing the frame again).
  auto descend = [&](int n) {
    while (n >= 0) {
      const Node& node = nodes_[n];
      prefetch_objects(node);  // arriving while the sub-cubes are ranked
      double least = kInf;
      int nearest = -1;
      if (node.split) {
        std::array<double, kChildren> m;
        if constexpr (kAllSubCubes<Range>) range(node.cube, sub_margins(node), m);
        for (int b = 0; b < kChildren; ++b) {
          if constexpr (!kAllSubCubes<Range>) {
            double M = kInf;
            m[b] = kInf;
            if (node.child[b] >= 0) std::tie(m[b], M) = range(child_cube(node, b));
            if (k == 1) upper = std::min(upper, M);
          }
          if (node.child[b] < 0 || !(m[b] < kInf)) m[b] = std::numeric_limits<double>::quiet_NaN();
          nearest = m[b] < least ? b : nearest;
          least = m[b] < least ? m[b] : least;
        }
        if (nearest >= 0) {
          for (int b = 0; b < kChildren; ++b)  // the ones that may be opened
            if (m[b] < kInf) prefetch(node.child[b]);
          path.push_back({});  // written in place (a frame copied just after its fields were
          Frame& f = path.back();  // written would stall on store forwarding)
          f.taken = 1;  // the first, the sub-cube of least m(b), is opened next (or none is)
          for (int p = 0; p < kChildren; ++p) {
            const int b = nearest ^ kFarthestFirst[kChildren - 1 - p];
            f.m[p] = m[b];
            f.child[p] = node.child[b];
          }
        }
      }
      measure(node);
      if (nearest < 0) return;
      if (!(least <= bound())) {  // nor any other sub-cube: m(b) >= least for all
        path.pop_back();
        return;
      }
      n = node.child[nearest];
    }
  };
  {
    const auto [m, M] = range(nodes_[root_].cube);
    if (!(m < kInf)) return;  // no finite value inside
    if (k == 1) upper = M;
    descend(root_);
  }
  while (!path.empty()) {
    Frame& f = path.back();
    const unsigned open = at_most_mask(f.m, bound()) & (~0u << f.taken);
    if (open == 0) {
      path.pop_back();
      continue;
    }
    const int p = std::countr_zero(open);
    f.taken = p + 1;
    descend(f.child[p]);  // may push frames: f is not used after this
  }
  std::sort_heap(best.begin(), best.end(), worse);
}

}  // namespace shockfield::geometry
