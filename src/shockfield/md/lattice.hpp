#pragma once
// Crystal lattices with the semantics of the LAMMPS `lattice` and `create_atoms box` commands.
//
// Styles and basis atoms (fractions of the conventional cell, in LAMMPS order):
//   sc       (0,0,0)
//   bcc      (0,0,0) (½,½,½)
//   fcc      (0,0,0) (½,½,0) (½,0,½) (0,½,½)
//   hcp      orthogonal cell a1=(1,0,0), a2=(0,√3,0), a3=(0,0,c/a) in units of a0, c/a = √(8/3)
//            unless given; basis (0,0,0) (½,½,0) (½,⅚,½) (0,⅓,½)
//   diamond  fcc + the same shifted by (¼,¼,¼)
// Orientation (`lattice ... orient x i j k orient y ... orient z ...`): three integer vectors, the
// Cartesian directions of the unrotated cell that become the box x, y and z axes. As in LAMMPS
// they must be mutually orthogonal and right-handed ((x × y)·z > 0).
//
// The box: shockfield sizes a box by repeat counts along the oriented axes. The periodic repeat
// along an axis is the shortest crystal translation along that direction (for cubic lattices
// a0·|v|/m where v/m is the shortest translation: e.g. fcc [1-10] → a0·√2/2, [11-2] → a0·√6/2,
// [111] → a0·√3), so a periodic box of whole repeats is seamless.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

enum class LatticeStyle { sc, bcc, fcc, hcp, diamond };

/// Parses "sc", "bcc", "fcc", "hcp", "diamond"; throws InputError naming `what` otherwise.
LatticeStyle parse_lattice_style(const std::string& name, const std::string& what);
const std::vector<std::string>& lattice_style_names();

struct LatticeSpec {
  LatticeStyle style = LatticeStyle::fcc;
  double a0 = 1.0;  ///< lattice constant, Å (the LAMMPS `lattice` scale in metal units)
  std::array<std::array<int, 3>, 3> orient{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::optional<double> c_over_a;  ///< hcp only; √(8/3) when absent
  std::vector<int> basis_types;    ///< 0-based type per basis atom; empty: all type 0
};

class Lattice {
 public:
  /// Validates the spec (a0 > 0, orient orthogonal and right-handed, basis_types size, c/a only
  /// for hcp, a periodic repeat along every axis); throws InputError saying what is wrong.
  explicit Lattice(const LatticeSpec& spec);

  int basis_size() const { return static_cast<int>(basis_.size()); }
  /// Periodic repeat length along the box x, y, z axes, Å.
  const Vec3& repeat() const { return repeat_; }
  /// The box [0, n·repeat) with the given boundaries.
  geometry::Box box(const std::array<int, 3>& n, const std::array<geometry::Boundary, 3>& boundary) const;
  /// Appends every lattice site inside `box` to `atoms` (ids after atoms.max_id()), as LAMMPS
  /// `create_atoms <type> box` does (CreateAtoms::add_lattice): with ε = 10⁻⁶·L, a site is inside
  /// when lo − ε ≤ x < hi − 2ε on periodic dimensions, then mapped into the box. On fixed
  /// dimensions (where LAMMPS takes lo ≤ x < hi, so that it keeps a hi-face site whose computed
  /// position falls a round-off below hi) lo − ε ≤ x < hi − ε: a face site is kept or dropped
  /// regardless of round-off, and one within ε below lo is put on lo. On shrink-wrapped dimensions LAMMPS has grown the box by
  /// Domain::small = 10⁻⁴·L on both sides first (Domain::set_initial_box), so the sites on the hi
  /// face are created too: lo − 10⁻⁴L ≤ x < hi + 10⁻⁴L (4×4×10 fcc `p p s`: 672 atoms, `p p f`:
  /// 640, as LAMMPS 29 Sep 2021). Face sites a round-off outside a non-periodic face are put on it.
  /// Returns the number of atoms added.
  std::size_t create_atoms(const geometry::Box& box, Atoms& atoms) const;
  /// Calls visit(x, type) for every site create_atoms would add to `box`, in the same order and
  /// at the same (mapped) positions, without storing them (`shockfield run --check` counts a
  /// crystal of any allowed size this way).
  void for_each_site(const geometry::Box& box, const std::function<void(const Vec3& x, int type)>& visit) const;

 private:
  Vec3 site(const std::array<long long, 3>& cell, std::size_t b) const;

  LatticeSpec spec_;
  Mat3 cell_;    ///< columns: conventional cell vectors a1, a2, a3 in Å (unrotated)
  Mat3 rotate_;  ///< rows: unit orient vectors (lattice frame → box frame)
  std::vector<Vec3> basis_;
  Vec3 repeat_;
};

}  // namespace shockfield::md
