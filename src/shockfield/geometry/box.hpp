#pragma once
// Orthogonal simulation box with per-dimension boundaries, LAMMPS style:
//   p  periodic: atoms wrap, ghost images carry interactions across the faces;
//   f  fixed: the face does not move, an atom that leaves is lost (an error);
//   s  shrink-wrapped: the face follows the outermost atom at every neighbour rebuild.
#include <array>
#include <string>

#include "shockfield/core/types.hpp"

namespace shockfield::geometry {

enum class Boundary { periodic, fixed, shrink };

/// Parses "p", "f" or "s"; throws InputError naming `what` otherwise.
Boundary parse_boundary(const std::string& code, const std::string& what);
char boundary_code(Boundary b);

struct Box {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<Boundary, 3> boundary{Boundary::periodic, Boundary::periodic, Boundary::periodic};

  Vec3 length() const { return hi - lo; }
  double volume() const { const Vec3 l = length(); return l.x() * l.y() * l.z(); }
  bool periodic(int d) const { return boundary[d] == Boundary::periodic; }
  bool contains(const Vec3& x) const;
  /// Maps x into the box along periodic dimensions and updates its image counts, in constant
  /// time (by floor, whatever the distance). False, with x and image unchanged, when x is not
  /// finite or its image count would leave the range of int.
  [[nodiscard]] bool try_wrap(Vec3& x, std::array<int, 3>& image) const;
  /// try_wrap(), throwing RunError (the run blew up) when it fails.
  void wrap(Vec3& x, std::array<int, 3>& image) const;
  /// Shortest periodic image of a separation vector.
  Vec3 minimum_image(Vec3 d) const;
  /// "ppf"-style code, for messages and files.
  std::string boundary_codes() const;
};

}  // namespace shockfield::geometry
