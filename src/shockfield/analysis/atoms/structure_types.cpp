#include "shockfield/analysis/atoms/structure_types.hpp"

#include "shockfield/analysis/atoms/diamond_structure.hpp"

namespace shockfield::analysis::atoms {

std::string_view structure_name(Structure s) {
  switch (s) {
    case Structure::fcc: return "fcc";
    case Structure::hcp: return "hcp";
    case Structure::bcc: return "bcc";
    case Structure::ico: return "ico";
    case Structure::other: return "other";
  }
  return "other";
}

std::string_view diamond_structure_name(DiamondStructure s) {
  switch (s) {
    case DiamondStructure::cubic: return "cubic";
    case DiamondStructure::cubic_first: return "cubic_first";
    case DiamondStructure::cubic_second: return "cubic_second";
    case DiamondStructure::hexagonal: return "hexagonal";
    case DiamondStructure::hexagonal_first: return "hexagonal_first";
    case DiamondStructure::hexagonal_second: return "hexagonal_second";
    case DiamondStructure::other: return "other";
  }
  return "other";
}

StructureCounts count_structures(const std::vector<Structure>& structures) {
  StructureCounts c;
  for (Structure s : structures) ++c.count[static_cast<std::size_t>(structure_code(s) - 1)];
  c.total = structures.size();
  return c;
}

}  // namespace shockfield::analysis::atoms
