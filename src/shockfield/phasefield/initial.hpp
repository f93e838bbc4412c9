#pragma once
// Initial hcp domains: a list of spheres, ellipsoids and slabs (two parallel planes), and random
// spherical nuclei, each with the flat-front tanh profile of the model across its surface
// (model.hpp). Overlapping domains take the larger ξ. Distances are minimum-image along periodic axes.
#include <array>
#include <cstdint>
#include <vector>

#include "shockfield/phasefield/grid.hpp"
#include "shockfield/phasefield/model.hpp"

namespace shockfield::phasefield {

struct Domain {
  enum class Kind { sphere, ellipsoid, slab };
  Kind kind = Kind::sphere;
  std::array<double, 3> center{0, 0, 0};
  /// sphere: {R, R, R}; ellipsoid: the semi-axes along x, y, z; slab: {half width, -, -}.
  std::array<double, 3> size{1, 1, 1};
  std::array<double, 3> normal{1, 0, 0};  ///< slab normal
};

struct RandomNuclei {
  std::int64_t count = 0;
  double radius = 1.0;
  std::uint64_t seed = 1;
};

/// The nuclei as spheres with centres uniform in the box (core/rng.hpp: seed, nucleus, axis).
std::vector<Domain> random_domains(const Grid& grid, const RandomNuclei& nuclei);

/// Signed distance (approximate for an ellipsoid: exact on its axes) from the domain's surface,
/// negative inside, at the point x.
double signed_distance(const Grid& grid, const Domain& domain, const std::array<double, 3>& x);

/// ξ on every node: 0 (bcc) without domains.
std::vector<double> initial_field(const Grid& grid, const Model& model, const std::vector<Domain>& domains);

}  // namespace shockfield::phasefield
