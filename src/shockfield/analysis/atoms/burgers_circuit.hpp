#pragma once
// Burgers vectors of dislocations in fcc crystals by the Frank scheme of Xu et al. (2015) §3.2.3
// ("Calculation of the Burgers vector of dislocation loop", Figs 16–17):
//  1. a Burgers circuit — a closed sequence of nearest-neighbour steps between atoms — is taken
//     around one or more dislocation lines in the deformed crystal;
//  2. each step x_{k+1} − x_k is mapped to the nearest vector of the step set S: the edges of the
//     Thompson tetrahedron and of its inverse, which are the twelve perfect nearest-neighbour
//     vectors a/2⟨110⟩, and their mirrors in the four {111} planes (the nearest-neighbour
//     vectors across a stacking fault or twin boundary, a/2⟨110⟩ ± a/6⟨112⟩), instead of a
//     local reference lattice;
//  3. the Burgers vector is the closure failure of the mapped steps. Convention FS/RH (Hirth &
//     Lothe 1982, §1-4): the circuit is right-handed about the line sense ξ, closed in the real
//     crystal, and b = start − finish of the mapped path in the perfect crystal, b = −Σ_k s_k.
//     With this convention the Volterra field u = b θ/2π (θ right-handed about ξ) has Burgers
//     vector +b.
// Every vector of S is an integer vector in units of a/6 along the crystal's cube axes, so the sum
// is exact: b is reported as [h k l]/6 (Fig 16 writes b = [1, 2, −1]/6). A circuit that encloses
// no dislocation gives 0 exactly, also where it crosses a stacking fault (the mirror steps).
// Only fcc is handled: the step set of bcc (a/2⟨111⟩ and a⟨100⟩ neighbours of different length)
// is not the Thompson tetrahedron; burgers_vector refuses a frame whose steps do not fit S.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"

namespace shockfield::analysis::atoms {

using Vec3i = Eigen::Vector3i;

/// The crystal's orientation and lattice constant: the box axes x, y, z are the crystal
/// directions `orient` (LAMMPS `lattice ... orient`, orthogonal and right-handed), a in Å.
struct CrystalFrame {
  Mat3 crystal_from_lab = Mat3::Identity();  ///< columns: unit orient vectors (crystal components of the box axes)
  double lattice_constant = 0;

  /// Validates the directions (non-zero, orthogonal, right-handed) and a > 0; InputError naming `what`.
  static CrystalFrame from_orient(const std::array<Vec3i, 3>& orient, double lattice_constant, const std::string& what);
  /// Nearest-neighbour distance a/√2.
  double neighbor_distance() const;
  /// Bond cutoff between the first and second shells, (1/√2 + 1)/2 · a (LAMMPS cna/atom's fcc value).
  double bond_cutoff() const;
};

/// The step set S in units of a/6: 12 perfect a/2⟨110⟩ then 24 mirrored steps.
const std::vector<Vec3i>& frank_step_set();

/// A circuit placed around a line: the atoms within `band` of the cylinder of radius `radius`
/// about the axis through `centre` along `axis`, and within `slab` of the plane through `centre`
/// normal to it; the circuit is the shortest closed path of bonds (closer than `bond_cutoff`)
/// among them that winds once, right-handed, about the axis.
struct AxisCircuit {
  Vec3 centre = Vec3::Zero();  ///< Å
  Vec3 axis = Vec3::UnitZ();   ///< line sense ξ (any length > 0)
  double radius = 0;           ///< Å
  double band = 0;             ///< Å, half-width of the annulus
  double slab = 0;             ///< Å, half-thickness along the axis
  double bond_cutoff = 0;      ///< Å
};

/// The atoms (frame indices, in order, the first not repeated at the end) of the circuit, or an
/// InputError saying why none exists (too few atoms in the band, no path that winds around).
std::vector<std::size_t> circuit_around(const AtomFrame& frame, const NeighborTable& table, const AxisCircuit& spec);

/// The atoms with these ids, in this order (a closed circuit: the last steps back to the first).
std::vector<std::size_t> circuit_of_ids(const AtomFrame& frame, const std::vector<std::int64_t>& ids);

struct BurgersResult {
  std::vector<std::size_t> circuit;  ///< frame indices
  Vec3i sixths = Vec3i::Zero();      ///< b in crystal axes, units a/6
  Vec3 lab = Vec3::Zero();           ///< b in the box axes, Å
  /// Largest |step − its mapped vector| over the circuit, in nearest-neighbour distances. The
  /// vectors of S are 0.577 of it apart, so above ~0.25 a step was mapped by a guess (the circuit
  /// runs through a core or a strongly distorted region): `reliable` is false.
  double max_step_error = 0;
  bool reliable = true;

  /// "none", "perfect a/2<110>", "Shockley a/6<112>", "Frank a/3<111>", "stair-rod a/6<110>",
  /// "Hirth a/3<100>" or "other".
  std::string kind() const;
  /// "[h k l]/6" (reduced: "[1 -1 0]/2" for [3 −3 0]/6, "0" for none).
  std::string text() const;
};

/// The Frank-scheme Burgers vector of a closed circuit (FS/RH). InputError when a step is longer
/// than 1.5 nearest-neighbour distances (not a bond: the atoms are not neighbours).
BurgersResult burgers_vector(const AtomFrame& frame, const std::vector<std::size_t>& circuit, const CrystalFrame& crystal);

}  // namespace shockfield::analysis::atoms
