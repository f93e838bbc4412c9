#pragma once
// Atom storage, structure of arrays. Entries [0, nlocal) are the atoms the simulation owns;
// entries [nlocal, size()) are ghost images of owned atoms across periodic faces (LAMMPS style),
// rebuilt with the neighbour list. Types are 0-based inside the code and 1-based in every file
// and message, as in LAMMPS. Positions in Å, velocities in Å/ps, forces in eV/Å, masses in amu.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/box.hpp"

namespace shockfield::md {

struct Atoms;

/// The other ranks of a decomposed run (md/decomposition.hpp), for the atoms a rank owns: ghost
/// values travel through the particle exchange's swaps (a ghost's owner may be on another rank),
/// and sums over atoms add the ranks' partial sums in rank order.
class AtomRanks {
 public:
  virtual ~AtomRanks() = default;
  /// Adds each ghost's `width` doubles into the entry it was made from, swaps in reverse order.
  virtual void reverse_sum(double* values, int width) const = 0;
  /// Copies each owner's `width` doubles to its ghosts.
  virtual void forward_copy(double* values, int width) const = 0;
  /// Moves the ghosts to their owners' positions, imaged.
  virtual void update_ghost_positions(Atoms& atoms, const geometry::Box& box) const = 0;
  /// Σ over ranks of each partial, in rank order (the same bits on every rank).
  virtual std::vector<double> sum(const std::vector<double>& partials) const = 0;
};

struct Atoms {
  // Owned and ghost entries.
  std::vector<Vec3> x;     ///< positions
  std::vector<int> type;   ///< 0-based type
  // Owned entries only (size nlocal) unless noted.
  std::vector<Vec3> v;                    ///< velocities
  std::vector<Vec3> f;                    ///< forces (owned + ghost while forces are summed)
  std::vector<std::int64_t> id;           ///< 1-based tags, unique
  std::vector<std::array<int, 3>> image;  ///< periodic image counts (unwrapped = x + image·h, h the cell edges)
  std::vector<std::uint32_t> mask;        ///< group membership bits; bit 0 = "all"

  // Ghost bookkeeping (size nghost): owner index and which periodic image of the owner the ghost
  // is (ghost position = owner position + image·h, h the cell edges, so it follows box deformation).
  std::vector<int> ghost_owner;
  std::vector<std::array<int, 3>> ghost_image;

  std::vector<double> mass;               ///< per type, amu
  std::vector<std::string> type_names;    ///< per type, element symbol or "" (e.g. "Cu")

  std::size_t nlocal = 0;
  /// Set while a decomposed run owns the atoms (null: one rank, every ghost's owner is here).
  std::shared_ptr<const AtomRanks> ranks;

  std::size_t size() const { return x.size(); }
  std::size_t nghost() const { return x.size() - nlocal; }
  int ntypes() const { return static_cast<int>(mass.size()); }
  double mass_of(std::size_t i) const { return mass[static_cast<std::size_t>(type[i])]; }

  /// Appends one owned atom (only valid when there are no ghosts).
  void add(const Vec3& pos, int type0, std::int64_t tag, const Vec3& vel = Vec3::Zero());
  /// Removes every ghost entry.
  void clear_ghosts();
  /// Keeps the owned atoms whose flag is true, in order (ghosts must be cleared first).
  void keep(const std::vector<bool>& flag);
  /// Moves the ghosts to their owners' current positions plus image·h (Box::lattice_shift).
  void update_ghost_positions(const geometry::Box& box);
  /// Adds each ghost's value into its owner's value (size() entries in `values`).
  template <class T>
  void reverse_sum(std::vector<T>& values) const {
    static_assert(sizeof(T) % sizeof(double) == 0, "values of whole doubles (double, Vec3, Voigt6)");
    if (ranks) return ranks->reverse_sum(reinterpret_cast<double*>(values.data()), sizeof(T) / sizeof(double));
    for (std::size_t g = 0; g < nghost(); ++g) values[ghost_owner[g]] += values[nlocal + g];
  }
  /// Copies each owner's value to its ghosts (size() entries in `values`).
  template <class T>
  void forward_copy(std::vector<T>& values) const {
    static_assert(sizeof(T) % sizeof(double) == 0, "values of whole doubles (double, Vec3, Voigt6)");
    if (ranks) return ranks->forward_copy(reinterpret_cast<double*>(values.data()), sizeof(T) / sizeof(double));
    for (std::size_t g = 0; g < nghost(); ++g) values[nlocal + g] = values[ghost_owner[g]];
  }
  /// Largest tag in use (0 when empty).
  std::int64_t max_id() const;
};

}  // namespace shockfield::md
