#pragma once
// Families (Liu et al. 2025, eq. 5): every point x' with |x' − x| ≤ δ, found with the shared cell list and
// stored in CSR form (offsets / neighbours), each bond listed from both ends as LAMMPS's
// fix PERI_NEIGH does. Per bond: reference length r0 = |ξ| and the partial-volume factor β that
// weights the neighbour's volume V_j at the horizon edge.
//
// Partial volume ("linear", the LAMMPS rule of fix_peri_neigh.cpp / pair_peri_*.cpp): a neighbour
// within ΔX/2 of the horizon counts with β = (δ + ΔX/2 − r0)/ΔX (1 at δ − ΔX/2, ½ at δ);
// "none" keeps β = 1.
#include <string>
#include <vector>

#include "shockfield/pd/point_cloud.hpp"

namespace shockfield::pd {

enum class VolumeCorrection { none, linear };
VolumeCorrection volume_correction_from_name(const std::string& name);

struct Family {
  double horizon = 0.0;              ///< δ [m]
  std::vector<int> offset;           ///< bonds of point i: [offset[i], offset[i+1])
  std::vector<int> neighbor;         ///< j of each bond
  std::vector<double> length;        ///< r0 = |x_j − x_i| [m]
  std::vector<double> volume_scale;  ///< β

  std::size_t bonds() const { return neighbor.size(); }
  int begin(std::size_t i) const { return offset[i]; }
  int end(std::size_t i) const { return offset[i + 1]; }
};

/// Families of every point for horizon δ. InputError when δ < ΔX (a point would have no
/// neighbour on the lattice) or δ is not finite. Neighbours are in increasing index order.
Family build_family(const PointCloud& cloud, double horizon, VolumeCorrection correction);

}  // namespace shockfield::pd
