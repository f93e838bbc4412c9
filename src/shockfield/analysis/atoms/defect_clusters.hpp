#pragma once
// Clusters of selected atoms (defect atoms, atoms of one structure type): atoms connected through
// chains of selected neighbours closer than a cutoff, periodic images included. Per cluster, the
// central-moment method of Xu et al. (2015) §4.4.2 for hcp domains: the centre (mean of the
// cluster's positions, unwrapped through its bonds so that a cluster across a periodic face is
// whole) and the central second-moment tensor
//   M = (1/N) Σ_i (x_i − c)(x_i − c)ᵀ,
// whose eigenvectors are the principal axes. For a uniform solid ellipsoid of semi-axes a ≥ b ≥ c,
// M's eigenvalues are a²/5, b²/5, c²/5, so the semi-axes are L_k = √(5 λ_k); from them the
// ellipsoid's volume 4/3 π a b c and its surface (Thomsen's approximation, within 1.1%).
// The atomic volume estimate N · V_box/N_atoms is also given.
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"

namespace shockfield::analysis::atoms {

struct Cluster {
  std::size_t size = 0;
  Vec3 centre = Vec3::Zero();        ///< Å; wrapped into the box along periodic dimensions
  Mat3 moment = Mat3::Zero();        ///< central second-moment tensor, Å²
  Vec3 semi_axes = Vec3::Zero();     ///< √(5 λ_k), largest first, Å
  Mat3 axes = Mat3::Identity();      ///< columns: unit principal directions, in semi_axes order
  double ellipsoid_volume = 0;       ///< 4/3 π a b c, Å³
  double ellipsoid_surface = 0;      ///< Thomsen's approximation, Å²
  double atomic_volume = 0;          ///< size · box volume / atoms, Å³
};

/// The centre (wrapped into the box), moments, principal axes and size measures of the points
/// `unwrapped` (one cluster, positions made continuous across periodic faces).
Cluster describe_cluster(const std::vector<Vec3>& unwrapped, const geometry::Box& box, double volume_per_atom);

struct ClusterResult {
  std::vector<int> cluster_of;   ///< per atom: 0-based cluster, −1 when not selected or in a dropped cluster
  std::vector<Cluster> clusters;  ///< largest first (ties: smallest first atom index)
};

struct DefectClusters {
  double cutoff = 0;         ///< Å: selected atoms closer than this are connected
  std::size_t min_size = 1;  ///< smaller clusters are dropped

  NeighborRequest request() const { return {cutoff, 0}; }
  /// Clusters of the atoms with selected[i] true (one flag per atom).
  ClusterResult compute(const AtomFrame& frame, const NeighborTable& table, const std::vector<bool>& selected) const;
};

}  // namespace shockfield::analysis::atoms
