#pragma once
// The Burgers circuits of one frame as `shockfield analyze atoms --burgers-*` places them
// (burgers_circuit.hpp has the circuit and the Frank scheme, Xu et al. (2015) §3.2.3): around
// lines given by a centre, axis and radius, through atoms given by their ids, and around the
// line of each defect cluster — one circuit for a straight cluster, one per station along a
// curved one (line_stations.hpp). The command line writes them to burgers.csv,
// shockfield.analysis.structure returns them.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/atoms/burgers_circuit.hpp"
#include "shockfield/analysis/atoms/defect_clusters.hpp"

namespace shockfield::analysis::atoms {

struct BurgersLine {
  Vec3 centre = Vec3::Zero();  ///< Å
  Vec3 axis = Vec3::UnitZ();   ///< line sense ξ, non-zero
  double radius = 0;           ///< Å, > 0
};

struct BurgersRequest {
  std::array<Vec3i, 3> orient{Vec3i(1, 0, 0), Vec3i(0, 1, 0), Vec3i(0, 0, 1)};  ///< crystal directions of x, y, z
  std::string orient_name = "--burgers-orient";  ///< how errors about `orient` name it
  std::optional<double> lattice;  ///< Å; default √2 × the median nearest-neighbour distance
  std::optional<double> band, slab;  ///< Å; defaults 0.5 a and 0.66 a
  std::optional<double> spacing;  ///< Å between circuits along a curved cluster; default 2 a
  std::vector<BurgersLine> lines;
  std::vector<std::vector<std::int64_t>> id_circuits;
  bool around_clusters = false;  ///< needs the frame's clusters
};

struct BurgersCircuit {
  std::string source;               ///< "line 1", "cluster 2", "cluster 2 station 3", "ids 1"
  BurgersResult result;
  std::optional<AxisCircuit> spec;  ///< the placed circuit (none for ids)
};

struct FrameBurgers {
  std::vector<BurgersCircuit> circuits;
  std::vector<double> on_circuit;     ///< per atom: the number (1, 2, ...) of the circuit through it, else 0
  std::vector<std::string> skipped;   ///< "SOURCE: why" for each automatic circuit that could not close
};

/// The circuits of a frame and their Burgers vectors. InputError for a circuit the request placed
/// (a line, ids) that cannot be made; an automatic one (around a cluster) is skipped instead.
FrameBurgers burgers_circuits(const AtomFrame& frame, const ClusterResult* clusters, const BurgersRequest& request);

}  // namespace shockfield::analysis::atoms
