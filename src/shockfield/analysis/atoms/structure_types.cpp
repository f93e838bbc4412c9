#include "shockfield/analysis/atoms/structure_types.hpp"

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

StructureCounts count_structures(const std::vector<Structure>& structures) {
  StructureCounts c;
  for (Structure s : structures) ++c.count[static_cast<std::size_t>(structure_code(s) - 1)];
  c.total = structures.size();
  return c;
}

}  // namespace shockfield::analysis::atoms
