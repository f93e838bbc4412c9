#include "shockfield/analysis/atoms/defect_clusters.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "shockfield/analysis/atoms/coordination.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

// Thomsen's approximation of an ellipsoid's surface, p = 1.6075 (relative error <= 1.061%).
double ellipsoid_surface(const Vec3& s) {
  constexpr double p = 1.6075;
  const double ap = std::pow(s[0], p), bp = std::pow(s[1], p), cp = std::pow(s[2], p);
  return 4.0 * std::numbers::pi * std::pow((ap * bp + ap * cp + bp * cp) / 3.0, 1.0 / p);
}

}  // namespace

Cluster describe_cluster(const std::vector<Vec3>& unwrapped, const geometry::Box& box, double volume_per_atom) {
  Cluster c;
  c.size = unwrapped.size();
  for (const Vec3& x : unwrapped) c.centre += x;
  c.centre /= static_cast<double>(c.size);
  for (const Vec3& x : unwrapped) c.moment += (x - c.centre) * (x - c.centre).transpose();
  c.moment /= static_cast<double>(c.size);
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(c.moment);  // eigenvalues ascending
  for (int k = 0; k < 3; ++k) {
    c.semi_axes[k] = std::sqrt(5.0 * std::max(eigen.eigenvalues()[2 - k], 0.0));
    c.axes.col(k) = eigen.eigenvectors().col(2 - k);
  }
  c.ellipsoid_volume = 4.0 / 3.0 * std::numbers::pi * c.semi_axes.prod();
  c.ellipsoid_surface = ellipsoid_surface(c.semi_axes);
  c.atomic_volume = static_cast<double>(c.size) * volume_per_atom;
  std::array<int, 3> image{0, 0, 0};
  box.wrap(c.centre, image);
  return c;
}

ClusterResult DefectClusters::compute(const AtomFrame& frame, const NeighborTable& table,
                                      const std::vector<bool>& selected) const {
  if (!(cutoff > 0)) throw InputError(fmt::format("clusters: cutoff must be > 0 (got {})", cutoff));
  if (selected.size() != frame.size())
    throw InputError(fmt::format("clusters: {} selection flags for {} atoms", selected.size(), frame.size()));
  table.require(request(), "clusters");
  const std::size_t n = frame.size();
  const double cut2 = cutoff * cutoff;
  // Flood fill through selected neighbours; each atom's unwrapped position is its discoverer's
  // plus the bond vector, so a cluster across a periodic face is one piece.
  std::vector<int> label(n, -1);
  std::vector<std::vector<std::size_t>> members;
  std::vector<std::vector<Vec3>> unwrapped;
  std::vector<std::size_t> queue;
  std::vector<Vec3> position(n);
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (!selected[seed] || label[seed] >= 0) continue;
    const int id = static_cast<int>(members.size());
    members.emplace_back();
    unwrapped.emplace_back();
    label[seed] = id;
    position[seed] = frame.positions[seed];
    queue.assign(1, seed);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t i = queue[q];
      members.back().push_back(i);
      unwrapped.back().push_back(position[i]);
      const auto list = table.of(i);
      const std::size_t within = neighbors_within(table, i, cut2);
      for (std::size_t k = 0; k < within; ++k) {
        const auto j = static_cast<std::size_t>(table.owner(list[k]));
        if (!selected[j] || label[j] >= 0) continue;
        label[j] = id;
        position[j] = position[i] + table.delta(i, list[k]);
        queue.push_back(j);
      }
    }
  }
  // Largest first; ties by first member (the flood order already follows atom index).
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return members[a].size() > members[b].size(); });
  ClusterResult r;
  r.cluster_of.assign(n, -1);
  const double volume_per_atom = frame.box.volume() / static_cast<double>(std::max<std::size_t>(n, 1));
  for (std::size_t k : order) {
    if (members[k].size() < min_size) continue;
    const int id = static_cast<int>(r.clusters.size());
    for (std::size_t i : members[k]) r.cluster_of[i] = id;
    r.clusters.push_back(describe_cluster(unwrapped[k], frame.box, volume_per_atom));
  }
  return r;
}

}  // namespace shockfield::analysis::atoms
