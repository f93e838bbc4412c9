// The Burgers circuits of a frame (burgers_frame.hpp).
#include "shockfield/analysis/atoms/burgers_frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

#include "shockfield/analysis/atoms/line_stations.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {
namespace {

// The median nearest-neighbour distance × √2: the fcc lattice constant of a mostly fcc frame.
double estimated_lattice_constant(const AtomFrame& frame) {
  const NeighborTable table(frame, {density_cutoff(frame, 12), 1});
  std::vector<double> nearest;
  for (std::size_t i = 0; i < frame.size(); ++i)
    if (!table.of(i).empty()) nearest.push_back(table.delta(i, table.of(i).front()).norm());
  if (nearest.empty()) throw InputError("--burgers: the frame has no pairs of atoms to estimate the lattice constant from");
  std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2), nearest.end());
  return nearest[nearest.size() / 2] * std::numbers::sqrt2;
}

struct PlacedLine {
  AxisCircuit spec;
  std::string source;
  bool automatic = false;  ///< placed around a cluster: skipped, not fatal, when it cannot close
};

std::vector<PlacedLine> lines_of(const AtomFrame& frame, const ClusterResult* clusters, const CrystalFrame& crystal,
                                 const BurgersRequest& request) {
  const double a = crystal.lattice_constant, bond = crystal.bond_cutoff();
  const double band = request.band.value_or(0.5 * a), slab = request.slab.value_or(0.66 * a);
  std::vector<PlacedLine> lines;
  for (std::size_t k = 0; k < request.lines.size(); ++k) {
    const BurgersLine& l = request.lines[k];
    lines.push_back({{l.centre, l.axis, l.radius, band, slab, bond}, fmt::format("line {}", k + 1)});
  }
  if (!request.around_clusters || !clusters) return lines;
  std::vector<std::vector<std::size_t>> members(clusters->clusters.size());
  for (std::size_t i = 0; i < clusters->cluster_of.size(); ++i)
    if (clusters->cluster_of[i] >= 0) members[static_cast<std::size_t>(clusters->cluster_of[i])].push_back(i);
  for (std::size_t k = 0; k < clusters->clusters.size(); ++k) {
    const Cluster& c = clusters->clusters[k];
    const double radius = c.semi_axes[1] + bond;
    auto stations = line_stations(frame, members[k], request.spacing.value_or(2 * a));
    if (c.semi_axes[0] >= 1.5 * c.semi_axes[1] && stations_are_straight(stations, frame.box, c.centre, c.axes.col(0), radius)) {
      lines.push_back({{c.centre, c.axes.col(0), radius, band, slab, bond}, fmt::format("cluster {}", k + 1), true});
      continue;
    }
    orient_circulation(stations, frame.box, c.centre, c.axes.col(2));  // a loop's sense from its normal
    for (std::size_t j = 0; j < stations.size(); ++j)
      lines.push_back({{stations[j].centre, stations[j].tangent, stations[j].half_width + bond, band, slab, bond},
                       fmt::format("cluster {} station {}", k + 1, j + 1), true});
  }
  return lines;
}

}  // namespace

FrameBurgers burgers_circuits(const AtomFrame& frame, const ClusterResult* clusters, const BurgersRequest& request) {
  const CrystalFrame crystal = CrystalFrame::from_orient(
      request.orient, request.lattice ? *request.lattice : estimated_lattice_constant(frame), request.orient_name);
  const NeighborTable table(frame, {crystal.bond_cutoff(), 0});
  FrameBurgers out;
  out.on_circuit.assign(frame.size(), 0.0);
  auto add = [&](const BurgersResult& r, const std::string& source, std::optional<AxisCircuit> spec) {
    out.circuits.push_back({source, r, spec});
    for (std::size_t i : r.circuit) out.on_circuit[i] = static_cast<double>(out.circuits.size());
  };
  for (const PlacedLine& line : lines_of(frame, clusters, crystal, request)) {
    try {
      add(burgers_vector(frame, circuit_around(frame, table, line.spec), crystal), line.source, line.spec);
    } catch (const InputError& e) {
      if (!line.automatic) throw;  // a circuit the user placed: its failure is an input error
      // One cluster without a closed circuit must not stop the others.
      out.skipped.push_back(fmt::format("{}: {}", line.source, e.what()));
    }
  }
  for (std::size_t k = 0; k < request.id_circuits.size(); ++k)
    add(burgers_vector(frame, circuit_of_ids(frame, request.id_circuits[k]), crystal), fmt::format("ids {}", k + 1),
        std::nullopt);
  return out;
}

}  // namespace shockfield::analysis::atoms
