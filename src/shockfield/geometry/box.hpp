#pragma once
// Simulation box with per-dimension boundaries, LAMMPS style, orthogonal or LAMMPS's restricted
// triclinic cell: edge vectors a = (lx, 0, 0), b = (xy, ly, 0), c = (xz, yz, lz) from the
// corner lo, with lx = hi.x - lo.x etc. (lo and hi are LAMMPS's boxlo/boxhi, not the bounding
// box) and tilt = (xy, xz, yz). A point is x = lo + h s with h = [a b c] and fractional (LAMMPS
// "lamda") coordinates s in [0, 1)^3 inside the box. Boundaries:
//   p  periodic: atoms wrap, ghost images carry interactions across the faces;
//   f  fixed: the face does not move, an atom that leaves is lost (an error);
//   s  shrink-wrapped: the face follows the outermost atom at every neighbour rebuild.
#include <array>
#include <string>

#include "shockfield/core/types.hpp"

namespace shockfield::geometry {

enum class Boundary { periodic, fixed, shrink };

/// A cell flip (LAMMPS `flip yes` of fix deform and fix npt; Domain::image_flip's m, n, p): the
/// equivalent cell with edges b' = b + m a and c' = c + n a + p b (b the edge before the flip), the
/// same lattice of periodic images, whose tilts are back within half an edge.
struct CellFlip {
  int m = 0, n = 0, p = 0;
  bool any() const { return m != 0 || n != 0 || p != 0; }
};

/// Parses "p", "f" or "s"; throws InputError naming `what` otherwise.
Boundary parse_boundary(const std::string& code, const std::string& what);
char boundary_code(Boundary b);

struct Box {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<Boundary, 3> boundary{Boundary::periodic, Boundary::periodic, Boundary::periodic};

  /// Tilt factors (xy, xz, yz); zero for an orthogonal box.
  Vec3 tilt = Vec3::Zero();

  Vec3 length() const { return hi - lo; }
  /// lx ly lz, which is det h for a triclinic cell too.
  double volume() const { const Vec3 l = length(); return l.x() * l.y() * l.z(); }
  bool triclinic() const { return tilt.x() != 0 || tilt.y() != 0 || tilt.z() != 0; }
  /// Edge vector d of the cell (a, b or c).
  Vec3 edge(int d) const;
  /// The cell matrix h = [a b c] (edges as columns; upper triangular).
  Mat3 cell() const;
  /// n0 a + n1 b + n2 c: the displacement of periodic image n (image counts as in LAMMPS).
  Vec3 lattice_shift(const std::array<int, 3>& n) const;
  /// Fractional coordinates s = h^-1 (x - lo) of a position.
  Vec3 to_fractional(const Vec3& x) const;
  /// h^-1 r: the fractional components of a displacement.
  Vec3 fractional_vector(const Vec3& r) const;
  /// The position lo + h s of fractional coordinates s.
  Vec3 from_fractional(const Vec3& s) const;
  /// Distance between the two faces spanned by the other two edges, for each edge d: the
  /// thickness of the cell along the face normal (LAMMPS measures ghost cutoffs along it).
  /// Equals length() for an orthogonal box.
  Vec3 face_distances() const;
  /// Corners of the axis-aligned bounding box (the "xlo_bound xhi_bound" of LAMMPS dumps).
  Vec3 bound_lo() const;
  Vec3 bound_hi() const;
  bool periodic(int d) const { return boundary[d] == Boundary::periodic; }
  bool contains(const Vec3& x) const;
  /// Maps x into the box along periodic dimensions and updates its image counts, in constant
  /// time (by floor, whatever the distance). False, with x and image unchanged, when x is not
  /// finite or its image count would leave the range of int.
  [[nodiscard]] bool try_wrap(Vec3& x, std::array<int, 3>& image) const;
  /// try_wrap(), throwing RunError (the run blew up) when it fails.
  void wrap(Vec3& x, std::array<int, 3>& image) const;
  /// Shortest periodic image of a separation vector (for a triclinic cell as LAMMPS's
  /// Domain::minimum_image: the c, b, a image in turn that brings each fractional component
  /// within one half).
  Vec3 minimum_image(Vec3 d) const;
  /// "ppf"-style code, for messages and files.
  std::string boundary_codes() const;
  /// Checks a triclinic cell against LAMMPS's limits (each tilt at most half the edge it skews
  /// along, |xy|, |xz| <= lx / 2 and |yz| <= ly / 2; a skewed dimension periodic: xy needs y
  /// periodic, xz and yz need z periodic); throws InputError starting with `where`.
  void check_tilt(const std::string& where) const;
  /// The flip that brings back each tilt beyond `fraction` of its edge (LAMMPS FixNH::pre_exchange
  /// with fraction 0.6, FixDeform::end_of_step with 0.5): yz by one ly (which moves xz by the xy
  /// tilt), then xz and xy by one lx; only along periodic a (xy, xz) and b (yz).
  CellFlip flip_beyond(double fraction) const;
  /// Replaces the cell by the flipped one: the tilts change, lo, hi and the lattice do not.
  void apply_flip(const CellFlip& flip);

 private:
  bool try_wrap_triclinic(Vec3& x, std::array<int, 3>& image) const;
};

/// The image counts of the same unwrapped position in the flipped cell (LAMMPS
/// Domain::image_flip): with b = b' − m a and c = c' − n a − p b, n_b' = n_b − p n_c and
/// n_a' = n_a − m n_b' − n n_c.
std::array<int, 3> flipped_image(const std::array<int, 3>& image, const CellFlip& flip);

/// Throws InputError "<what> needs an orthogonal box; ..." for a triclinic box (the methods that
/// grid or bin along the axes and have not learnt tilted cells yet).
void require_orthogonal(const Box& box, const std::string& what);

/// The box whose bounding box and tilt a LAMMPS dump gives ("ITEM: BOX BOUNDS xy xz yz": lines
/// "xlo_bound xhi_bound xy", "ylo_bound yhi_bound xz", "zlo_bound zhi_bound yz").
Box box_from_bounds(const Vec3& bound_lo, const Vec3& bound_hi, const Vec3& tilt,
                    const std::array<Boundary, 3>& boundary);

}  // namespace shockfield::geometry
