#pragma once
// Cubic and hexagonal diamond by the adaptive CNA of second neighbours (Maras, Trushin, Stukowski,
// Ala-Nissila & Jónsson, Comput. Phys. Commun. 205, 13 (2016)), as OVITO's "Identify diamond
// structure" modifier does it. In diamond an atom's 4 nearest neighbours are its covalent bonds and
// their own 4 nearest neighbours, less the atom itself, are its 12 second neighbours: these form
// an fcc shell in cubic diamond and an hcp shell in hexagonal diamond (lonsdaleite). So: the 12
// vectors v_i + v_ij (i the 4 nearest, j each one's 4 nearest but the centre; exactly 3 each), then
// adaptive CNA on them — local cutoff r_c = (1+√2)/2 · their mean length, bonds among them closer
// than r_c, signatures (common, bonds, chain): all 12 (4, 2, 1) → cubic diamond; 6 (4, 2, 1) and
// 6 (4, 2, 2) → hexagonal diamond. Then, as OVITO: an unidentified atom among the 4 nearest of a
// cubic (hexagonal) diamond atom is "cubic (hexagonal) diamond, first neighbour" (the surface
// layer of a diamond region), and an unidentified atom among the 4 nearest of a first-neighbour
// atom is "second neighbour"; atom order decides when an atom borders both kinds (serial: the same
// for any thread count). Codes are OVITO's: 0 other, 1 cubic, 2 cubic first neighbour, 3 cubic
// second neighbour, 4 hexagonal, 5 hexagonal first neighbour, 6 hexagonal second neighbour.
// Scale-free like adaptive CNA: any lattice constant, moderate homogeneous strain (tested ±10%).
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/analysis/atoms/neighbor_table.hpp"

namespace shockfield::analysis::atoms {

enum class DiamondStructure : std::uint8_t {
  other = 0,
  cubic = 1,
  cubic_first = 2,
  cubic_second = 3,
  hexagonal = 4,
  hexagonal_first = 5,
  hexagonal_second = 6
};

constexpr std::array<DiamondStructure, 7> kDiamondStructures{
    DiamondStructure::cubic,     DiamondStructure::cubic_first,     DiamondStructure::cubic_second,
    DiamondStructure::hexagonal, DiamondStructure::hexagonal_first, DiamondStructure::hexagonal_second,
    DiamondStructure::other};

/// "cubic", "cubic_first", "cubic_second", "hexagonal", "hexagonal_first", "hexagonal_second", "other".
std::string_view diamond_structure_name(DiamondStructure s);

struct DiamondResult {
  std::vector<DiamondStructure> structure;  ///< per atom, frame order
  std::array<std::size_t, 7> count{};       ///< atoms per code (index: the code)
  std::size_t of(DiamondStructure s) const { return count[static_cast<std::size_t>(s)]; }
  double fraction(DiamondStructure s) const {
    return structure.empty() ? 0.0 : static_cast<double>(of(s)) / static_cast<double>(structure.size());
  }
};

struct DiamondCna {
  NeighborRequest request() const { return {0, 4}; }
  DiamondResult compute(const AtomFrame& frame, const NeighborTable& table) const;
};

}  // namespace shockfield::analysis::atoms
