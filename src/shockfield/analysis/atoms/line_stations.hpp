#pragma once
// Stations along the line that a cluster of dislocation-core atoms traces, straight or curved, for
// automatic Burgers circuits (Xu et al. 2015 §3.2.3, "Calculation of the Burgers vector of
// dislocation loop": a circuit around the line; a loop's line is curved, so one circuit about the
// cluster's principal axis does not enclose it). The stations are a farthest-point sample of the
// cluster's atoms at a given spacing; at each, the atoms within one spacing (minimum image, so a
// cluster across periodic faces or around the whole box is handled locally) give a local centre
// and the central second-moment tensor M (defect_clusters.hpp). Where M's largest semi-axis
// √(5λ₁) exceeds `elongation` × the second √(5λ₂), the local line direction is M's first
// eigenvector; elsewhere (a sheet, a blob, a junction) the station is dropped. A loop's line sense
// is set by its normal n (right-handed circulation about n, the usual convention for dislocation
// loops): orient_circulation() gives every station that sense, so the circuits around one loop
// give one Burgers vector, not ±b.
#include <span>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/core/types.hpp"

namespace shockfield::analysis::atoms {

struct LineStation {
  Vec3 centre = Vec3::Zero();   ///< Å: mean position of the local atoms (may lie outside the box)
  Vec3 tangent = Vec3::UnitZ(); ///< unit local line direction (sense arbitrary until oriented)
  double half_width = 0;        ///< Å: √(5λ₂), the core's half-width across the line
  std::size_t atoms = 0;        ///< local atoms the moments were taken over
};

/// Stations along the line traced by the atoms `members` of `frame` (indices), about `spacing` Å
/// apart, where the local atoms are elongated by at least `elongation`; in the sampling order
/// (the first is the member farthest from the others' mean).
std::vector<LineStation> line_stations(const AtomFrame& frame, std::span<const std::size_t> members, double spacing,
                                       double elongation = 1.5);

/// Turns each station's direction so that it circulates right-handed about `normal` through
/// `centre`: (r × ξ)·n ≥ 0, r the station's minimum-image offset from the centre.
void orient_circulation(std::vector<LineStation>& stations, const geometry::Box& box, const Vec3& centre,
                        const Vec3& normal);

/// True when the stations all lie along one straight line: every tangent within `degrees` of
/// `axis`, and every station centre within `offset` Å of the line through `centre` along `axis`.
bool stations_are_straight(const std::vector<LineStation>& stations, const geometry::Box& box, const Vec3& centre,
                           const Vec3& axis, double offset, double degrees = 20.0);

}  // namespace shockfield::analysis::atoms
