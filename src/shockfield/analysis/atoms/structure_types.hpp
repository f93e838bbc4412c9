#pragma once
// Structure types shared by the per-atom identifications, with the codes of LAMMPS
// `compute cna/atom`: 1 fcc, 2 hcp, 3 bcc, 4 icosahedral, 5 other. (OVITO numbers the same types
// 0 other, 1 fcc, 2 hcp, 3 bcc, 4 ico.)
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace shockfield::analysis::atoms {

enum class Structure : std::uint8_t { fcc = 1, hcp = 2, bcc = 3, ico = 4, other = 5 };

constexpr std::array<Structure, 5> kStructures{Structure::fcc, Structure::hcp, Structure::bcc, Structure::ico,
                                               Structure::other};

std::string_view structure_name(Structure s);
constexpr int structure_code(Structure s) { return static_cast<int>(s); }

/// Atoms of each structure (index: code − 1) and their total.
struct StructureCounts {
  std::array<std::size_t, 5> count{};
  std::size_t total = 0;

  std::size_t of(Structure s) const { return count[static_cast<std::size_t>(structure_code(s) - 1)]; }
  /// Fraction of the atoms with structure s (0 for no atoms).
  double fraction(Structure s) const { return total == 0 ? 0.0 : static_cast<double>(of(s)) / static_cast<double>(total); }
};

StructureCounts count_structures(const std::vector<Structure>& structures);

}  // namespace shockfield::analysis::atoms
