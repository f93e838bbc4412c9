#pragma once
// A peridynamic body on the MPI rank grid (docs/parallel.md, "Peridynamics under mpirun"), on the
// particle layer MD uses (parallel/particle_exchange.hpp). The body's bounding box (each point's
// cell of ΔX included) is cut into equal pieces; a rank owns the points whose *reference* position
// lies in its piece, for the whole run: families are fixed in the reference configuration (bonds
// only break), so nothing migrates and the ghosts — every point within the horizon δ of the piece,
// edges and corners of the up to 26 neighbours included — are made once (no skin is needed).
// Each step the owners' positions and velocities are forwarded to their ghosts through the kept
// swaps, and BondForce forwards the per-point values its bonds read of a neighbour (weighted
// volume, dilatation, critical stretch: bond_force.hpp).
//
// Local points: the owned ones in increasing global index, then the ghosts in the order the swaps
// brought them. The local family of a point is its family in the whole body restricted to local
// points, in the whole family's order: an owned point keeps every bond (its partners lie within δ),
// so its sums add the same terms in the same order as in a serial run — the same bits. A ghost's
// family is cut short; nothing reads what is computed from it.
#include <array>
#include <cstddef>
#include <vector>

#include "shockfield/parallel/particle_exchange.hpp"
#include "shockfield/parallel/rank_grid.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/point_cloud.hpp"

namespace shockfield::pd {

/// The rank grid of `ranks` ranks over the body of `cloud` (given by --rank-grid, or {0, 0, 0}:
/// the one with the least halo), every cut axis's pieces at least the horizon long. InputError
/// otherwise, naming the largest rank count that fits.
parallel::Dims3 pd_rank_grid(const PointCloud& cloud, double horizon, int ranks, const parallel::Dims3& given);

class Decomposition {
 public:
  /// Collective over `world`: the Cartesian grid `dims` over the whole body `cloud` with its
  /// `family` (both the same on every rank).
  Decomposition(const parallel::Communicator& world, const parallel::Dims3& dims, const PointCloud& cloud,
                const Family& family);

  const parallel::Communicator& comm() const { return exchange_.comm(); }
  const parallel::Dims3& dims() const { return dims_; }
  /// This rank's points (owned, then ghosts) and their families.
  const PointCloud& cloud() const { return cloud_; }
  const Family& family() const { return family_; }
  std::size_t owned() const { return owned_; }
  /// Index in the whole body of each local point, and in the whole family of each local bond.
  const std::vector<std::size_t>& point_origin() const { return point_origin_; }
  const std::vector<std::size_t>& bond_origin() const { return bond_origin_; }

  /// Owners' values to their ghosts: one double per local point, or positions and velocities.
  /// Collective.
  void forward(std::vector<double>& values) const;
  void forward(std::vector<Vec3>& y, std::vector<Vec3>& v) const;

 private:
  parallel::Dims3 dims_;
  parallel::ParticleExchange exchange_;
  std::vector<parallel::GhostSwap> swaps_;
  PointCloud cloud_;
  Family family_;
  std::size_t owned_ = 0;
  std::vector<std::size_t> point_origin_, bond_origin_;
};

}  // namespace shockfield::pd
