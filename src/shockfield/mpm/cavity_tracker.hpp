#pragma once
// Size of one cavity over time (Xu et al. 2015, §4.2, Figs 53, 59, 62): area (2D) or volume (3D),
// horizontal and vertical sizes, collapsibility Φ = (A0 − A)/A0, and the largest upward velocity
// of the material above it and downward velocity below it.
//
// The cavity is measured on a raster of half the particle spacing in a box around its last
// centre: each particle covers the raster cells inside its deformed domain x_p + F·[−l_p, l_p]^d
// (l_p the initial half-spacing; a square of the current area, l_p·J^(1/d), is not enough: around
// a growing cavity the hoop stretch exceeds J^(1/d) and the squares leave radial slivers that join
// the cavity to the box edge), and the cavity is the set of uncovered cells connected to its
// last interior that does not reach the box boundary (so a cavity vented through the free surface
// counts as gone). The centre follows the material: it moves with the mean velocity of the ring
// of particles around the cavity, then snaps to the centroid of the cells found.
#include <array>
#include <cstdint>
#include <vector>

#include "shockfield/mpm/particles.hpp"
#include "shockfield/mpm/sample_builders.hpp"

namespace shockfield::mpm {

struct CavityMeasure {
  double size = 0.0;            ///< area [m²] (2D) or volume [m³] (3D)
  double horizontal = 0.0;      ///< extent along x [m]
  double vertical = 0.0;        ///< extent along the shock axis [m]
  double collapsibility = 0.0;  ///< Φ = (A0 − A)/A0, A0 the first measurement
  double v_up_above = 0.0;      ///< max velocity along the shock axis of the column above [m/s]
  double v_down_below = 0.0;    ///< min velocity along the shock axis of the column below [m/s]
};

class CavityTracker {
 public:
  CavityTracker(int dim, const Void& initial, double spacing);
  /// Measures the cavity at time t (the first call fixes A0).
  CavityMeasure measure(const Particles& p, double t);

  /// Tracking state for checkpoints.
  std::vector<double> state() const;
  void restore(const std::vector<double>& s);

 private:
  /// Marks the raster cells whose centre lies in the particle's deformed domain.
  void cover_domain(const Vec3& x, const Vec3& half, const Mat3& deformation, const Vec3& lo,
                    const std::array<int, 3>& dims, std::vector<std::uint8_t>& covered) const;

  int dim_;
  double r0_, cell_;
  Vec3 centre_;
  double radius_;        // equivalent radius of the last measurement
  double a0_ = -1.0;     // first measured size
  double last_time_ = 0.0;
};

}  // namespace shockfield::mpm
