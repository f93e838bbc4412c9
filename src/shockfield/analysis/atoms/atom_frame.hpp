#pragma once
// The input of every atomistic structure analysis: one snapshot of atoms (positions, box, types,
// ids), whatever file it came from. Analyses never modify it.
#include <cstdint>
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::analysis::atoms {

struct AtomFrame {
  std::vector<Vec3> positions;    ///< Å, inside the box along non-periodic dimensions
  geometry::Box box;              ///< orthogonal; periodic dimensions give periodic images
  std::vector<int> types;         ///< 1-based, as in LAMMPS files (empty: all type 1)
  std::vector<std::int64_t> ids;  ///< unique tags (empty: 1..N in order)
  long long timestep = 0;

  std::size_t size() const { return positions.size(); }
};

/// Checks a frame before analysis and throws InputError naming `source` and the atom when it is
/// unusable: types/ids of the wrong length, duplicate ids, non-finite positions, a box of zero or
/// negative length, or an atom outside the box along a fixed (`f`) dimension. Atoms outside a
/// periodic dimension are fine (their images are taken), and shrink-wrapped (`s`, `m`)
/// dimensions follow the atoms. An empty frame is accepted (every analysis returns nothing).
void validate_frame(const AtomFrame& frame, const std::string& source);

/// The frame of a LAMMPS dump snapshot: positions from x y z (or xu yu zu, xs ys zs), types
/// from `type` (all 1 when absent), ids from `id` (1..N when absent); validated as above.
AtomFrame frame_from_dump(const io::DumpFrame& dump, const std::string& source);

/// The frame of the owned atoms of an md::Atoms set (an MD simulation's, a data file's): types
/// 1-based, ids; validated as above.
AtomFrame frame_from_atoms(long long timestep, const geometry::Box& box, const md::Atoms& atoms,
                           const std::string& source);

}  // namespace shockfield::analysis::atoms
