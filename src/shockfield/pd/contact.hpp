#pragma once
// Short-range contact forces as LAMMPS's PERI package (Parks et al. 2008) applies them
// (pair_peri_pmb.cpp and pair_peri_lps.cpp, after Silling's EMU theory manual, 12 May 2005,
// p. 18; docs/references.md): any two points i, j,
// bonded or not, closer than
//     d_ij = min(0.9·|x_j − x_i|, 1.35·ΔX)            (x: reference positions, ΔX: lattice spacing)
// repel. The force density on i is
//     f_i = 15·c·V_j·(d_ij − r)/δ · (y_i − y_j)/r,     r = |y_i − y_j| < d_ij,
// with c the bond-based micromodulus (PMB: its own; LPS: LpsModel::contact_micromodulus, from its
// bulk modulus) and δ the horizon. With equal volumes this is LAMMPS's force term for term; with unequal
// volumes LAMMPS's half neighbour list gives both points the V_j of the listed partner, here each
// point takes its partner's volume, so the pair force V_i·f_i = −V_j·f_j conserves momentum. The
// pair potential is U_ij = 15·c·V_i·V_j·(d_ij − r)²/(2δ).
//
// The candidates come from a full Verlet list of the current positions (cut-off 1.35·ΔX + skin,
// rebuilt when a point has moved more than half the skin since the last build), each point's
// partners sorted by index and only pairs inside d_ij summed: the force does not depend on when
// the list was built nor on the thread count, so it has no state a checkpoint would need.
#include <cmath>
#include <vector>

#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/pd/point_cloud.hpp"

namespace shockfield::pd {

class ShortRangeContact {
 public:
  /// `micromodulus` c (the force constant is 15c); `horizon` δ. The cloud must outlive this.
  ShortRangeContact(const PointCloud& cloud, double micromodulus, double horizon);

  /// Refreshes the candidate list for positions y when needed (call before force_density).
  void update(const std::vector<Vec3>& y);
  /// Contact force density on point i at positions y (those of the last update).
  Vec3 force_density(std::size_t i, const std::vector<Vec3>& y) const {
    Vec3 f = Vec3::Zero();
    for (auto k = list_.offset[i]; k < list_.offset[i + 1]; ++k) {
      const auto j = static_cast<std::size_t>(list_.neighbors[static_cast<std::size_t>(k)]);
      const Vec3 d = y[i] - y[j];
      const double r2 = d.squaredNorm(), reach = reach_[static_cast<std::size_t>(k)];
      if (r2 >= reach * reach) continue;
      const double r = std::sqrt(r2);
      if (r > 0.0) f += (constant_ * cloud_.volume[j] * (reach - r) / r) * d;
    }
    return f;
  }
  /// Σ over pairs in contact of 15·c·V_i·V_j·(d_ij − r)²/(2δ) [J, per unit of the missing dimensions]
  /// (updates the list for y first).
  double energy(const std::vector<Vec3>& y);
  /// Pairs (i < j) in contact at y (updates the list for y first).
  std::size_t active_pairs(const std::vector<Vec3>& y);
  /// Builds of the candidate list so far.
  long long builds() const { return builds_; }

 private:
  void build(const std::vector<Vec3>& y);

  const PointCloud& cloud_;
  double constant_;  // 15c/δ
  double max_reach_, skin_;
  geometry::NeighborList list_;
  std::vector<double> reach_;  // d_ij per list entry
  std::vector<Vec3> y_built_;
  long long builds_ = 0;
};

}  // namespace shockfield::pd
