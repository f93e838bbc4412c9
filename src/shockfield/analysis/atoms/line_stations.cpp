#include "shockfield/analysis/atoms/line_stations.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/analysis/atoms/defect_clusters.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

std::vector<LineStation> line_stations(const AtomFrame& frame, std::span<const std::size_t> members, double spacing,
                                       double elongation) {
  if (!(spacing > 0) || !(elongation >= 1))
    throw InputError(fmt::format("line stations: expected spacing > 0 and elongation >= 1 (got {}, {})", spacing, elongation));
  std::vector<LineStation> stations;
  if (members.empty()) return stations;
  const geometry::Box& box = frame.box;
  auto at = [&](std::size_t k) { return frame.positions[members[k]]; };
  // Farthest-point sampling: start from the member farthest from the first one's local frame
  // (an end of an open line), then add the member farthest from every station so far until all
  // lie within one spacing of a station.
  std::vector<double> nearest(members.size(), INFINITY);
  std::size_t next = 0;
  for (int sweep = 0; sweep < 2; ++sweep) {  // the farthest from member 0, then the farthest from that
    double far = -1;
    std::size_t from = next;
    for (std::size_t k = 0; k < members.size(); ++k) {
      const double d = box.minimum_image(at(k) - at(from)).norm();
      if (d > far) far = d, next = k;
    }
  }
  std::vector<std::size_t> seeds;
  while (true) {
    seeds.push_back(next);
    double far = -1;
    for (std::size_t k = 0; k < members.size(); ++k) {
      nearest[k] = std::min(nearest[k], box.minimum_image(at(k) - at(seeds.back())).norm());
      if (nearest[k] > far) far = nearest[k], next = k;
    }
    if (far < spacing) break;
  }
  // The local moments at each seed (defect_clusters.hpp: semi-axes √(5λ)).
  const double volume_per_atom = box.volume() / static_cast<double>(std::max<std::size_t>(frame.size(), 1));
  std::vector<Vec3> local;
  for (std::size_t s : seeds) {
    local.clear();
    const Vec3 origin = at(s);
    for (std::size_t k = 0; k < members.size(); ++k) {
      const Vec3 d = box.minimum_image(at(k) - origin);
      if (d.norm() <= spacing) local.push_back(origin + d);
    }
    if (local.size() < 3) continue;
    const Cluster c = describe_cluster(local, box, volume_per_atom);
    if (c.semi_axes[0] < elongation * c.semi_axes[1]) continue;  // no line direction here
    stations.push_back({c.centre, c.axes.col(0), c.semi_axes[1], local.size()});
  }
  return stations;
}

void orient_circulation(std::vector<LineStation>& stations, const geometry::Box& box, const Vec3& centre,
                        const Vec3& normal) {
  for (LineStation& s : stations)
    if (box.minimum_image(s.centre - centre).cross(s.tangent).dot(normal) < 0) s.tangent = -s.tangent;
}

bool stations_are_straight(const std::vector<LineStation>& stations, const geometry::Box& box, const Vec3& centre,
                           const Vec3& axis, double offset, double degrees) {
  const Vec3 xi = axis.normalized();
  const double cos_limit = std::cos(degrees * std::numbers::pi / 180.0);
  return std::all_of(stations.begin(), stations.end(), [&](const LineStation& s) {
    const Vec3 d = box.minimum_image(s.centre - centre);
    return std::abs(s.tangent.dot(xi)) >= cos_limit && (d - d.dot(xi) * xi).norm() <= offset;
  });
}

}  // namespace shockfield::analysis::atoms
