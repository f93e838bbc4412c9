#pragma once
// Atoms to a grid field: the fraction of selected atoms (e.g. the hcp atoms of the adaptive CNA)
// on the nodes of a regular grid — the order parameter ξ of the phase-field model made from an MD
// frame (Xu et al. (2015) §4.4.3: what MD learns about the hcp domains passed to the mesoscale;
// docs/analysis-atoms.md "Voxel fields", docs/bridges.md). Each atom is deposited on the 8 nodes
// around it with cloud-in-cell (trilinear) weights w; optionally both sums are smoothed by a
// Gaussian of standard deviation σ (a normalised convolution, so empty space does not dilute the
// fraction); fraction = Σ w s / Σ w with s = 1 for a selected atom.
//
// Grid: every axis has the same node spacing h (the phase-field grid's `spacing`). A periodic axis
// of length L gets n = round(L/h) nodes at lo + i L/n (node n is node 0 again); a non-periodic one
// n = round(L/h) + 1 nodes from lo to hi (walls on the first and last node). The atoms are mapped
// onto that grid by the per-axis stretch n h / L (or (n − 1) h / L), reported: at most h/(2L).
#include <array>
#include <cstddef>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"

namespace shockfield::analysis::atoms {

struct VoxelOptions {
  double spacing = 1.0;    ///< node spacing h, Å
  double smoothing = 0.0;  ///< Gaussian σ, Å (0: cloud-in-cell only)
};

struct VoxelField {
  std::array<std::size_t, 3> n{1, 1, 1};
  double spacing = 1.0;                  ///< h, the same along every axis
  std::array<double, 3> origin{0, 0, 0}; ///< the box's lo corner
  std::array<bool, 3> periodic{true, true, true};
  std::array<double, 3> stretch{1, 1, 1};  ///< grid length / box length per axis
  std::vector<double> fraction;  ///< Σ w s / Σ w per node (x fastest); 0 where no atom reaches
  std::vector<double> density;   ///< Σ w / h³ (atoms per Å³, of the stretched grid)
  std::size_t empty_nodes = 0;   ///< nodes no atom reaches (fraction set to 0)
  std::size_t selected = 0;      ///< selected atoms
};

/// The field of `frame` with `selected` (one flag per atom). InputError for a spacing that is
/// not positive or larger than an axis, a negative σ, or more than 10^9 nodes.
VoxelField voxel_fraction(const AtomFrame& frame, const std::vector<bool>& selected, const VoxelOptions& options);

}  // namespace shockfield::analysis::atoms
