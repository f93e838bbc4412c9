#pragma once
// Initial hcp domains: a field file, a list of spheres, ellipsoids and slabs (two parallel planes),
// and random spherical nuclei, each with the flat-front tanh profile of the model across its surface
// (model.hpp). Overlapping domains take the larger ξ. Distances are minimum-image along periodic axes.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
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

/// A starting field from a file (`[initial] file`, `array`): a grid field shockfield analyze reads
/// (a .vti frame of a phase-field run, a CSV grid, legacy VTK) with exactly the grid's nodes per
/// axis and spacing (relative 1e-9), every value finite.
struct FieldFile {
  std::filesystem::path path;  ///< empty: none
  std::string array;           ///< the data array (VTK files); empty: the first scalar array
};

/// Reads the field file's values in node order; InputError naming the file and what differs
/// (node counts, spacing, a non-finite value and its node).
std::vector<double> read_field_file(const FieldFile& file, const Grid& grid);

/// A gradient coefficient that depends on the local pressure (Xu et al. 2015 §4.4.3: "the
/// parameter D is a function of pressure"), to first order about a reference:
/// D(x) = D [1 + slope (p(x) − reference)], p read from a field file as above.
struct PressureDependence {
  FieldFile file;  ///< empty path: D does not depend on pressure
  double reference = 0.0;
  double slope = 0.0;  ///< per unit of the file's pressure
};

/// The scale 1 + slope (p − reference) on every node; InputError naming the file and the node
/// where it is not positive.
std::vector<double> pressure_scale(const PressureDependence& pressure, const Grid& grid);

/// ξ on every node: the field file's values (0, bcc, without one), and where a domain lies the
/// larger of that and the domain's profile.
std::vector<double> initial_field(const Grid& grid, const Model& model, const std::vector<Domain>& domains,
                                  const FieldFile& file = {});

}  // namespace shockfield::phasefield
