#pragma once
// Sizes of a PD lattice body counted before it is built: its bonds (the pairs of lattice points
// within the horizon, exactly as build_family finds them) and an estimate of the memory of its
// points and bonds. The case reader refuses a horizon whose bond list would exceed kMaxBonds
// (core/size_limits.hpp), and `shockfield run --check` reports the sizes without building the
// body (docs/robustness.md).
#include <array>

namespace shockfield::pd {

/// Bonds (ordered pairs i ≠ j, as Family::bonds() counts them) of a dim-D lattice of counts
/// points with horizon δ = horizon_factor·ΔX: Σ over lattice offsets o ≠ 0 with |o| ≤ m (with
/// build_family's 1e-12 tolerance) of Π_d (n_d − |o_d|). Sums the longest axis in closed form,
/// so the cost is at most the product of the two shorter axes' offset ranges (≤ 10^6 loops for
/// any body of at most 10^8 points).
double lattice_bonds(int dim, const std::array<int, 3>& counts, double horizon_factor);

/// Estimated bytes of a running PD body: ~1 kB per point (positions, velocities, forces, the
/// correspondence model's stress, shape tensor, deformation gradient and material state) and
/// ~40 B per bond (neighbour index, length, volume scale, influence weight, damage flag, and the
/// build's temporary lists).
double pd_bytes(double points, double bonds);

}  // namespace shockfield::pd
