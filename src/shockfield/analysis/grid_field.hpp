#pragma once
// A scalar field Θ(x) on a regular grid (Xu et al. 2015, §3.1: "fields and structures based on ordered
// points"). Values are stored x fastest: index = x + nx * (y + ny * z); a 2D field has nz = 1
// (a 3D grid of a single voxel layer sets single_layer_3d).
// Cells may be marked void (no material, e.g. an empty bin of a particle field): a void cell has
// no value, counts as black (Θ < Θ_th) for every threshold and is skipped by statistics.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace shockfield::analysis {

/// The shape of a regular grid: cell counts, spacing and origin (shared by the field that owns its
/// values and the view that reads somebody else's).
struct GridGeometry {
  std::array<std::size_t, 3> n{0, 0, 1};         ///< cells along x, y, z (nz = 1 in 2D)
  std::array<double, 3> spacing{1.0, 1.0, 1.0};  ///< grid step along x, y, z
  std::array<double, 3> origin{0.0, 0.0, 0.0};   ///< position of cell (0, 0, 0)
  bool single_layer_3d = false;  ///< nz = 1 but a 3D grid (one layer of voxels): dimension() 3
  /// The unit of spacing and origin as the file names it ("m", "A", "1"); empty: not named.
  std::string length_units{};

  std::size_t size() const { return n[0] * n[1] * n[2]; }
  int dimension() const { return n[2] > 1 || single_layer_3d ? 3 : 2; }
  std::size_t index(std::size_t x, std::size_t y, std::size_t z = 0) const {
    return x + n[0] * (y + n[1] * z);
  }
};

/// A field whose values live elsewhere (a numpy array, a solver's array): what every analysis that
/// only reads a field takes, so that a caller's array is analysed in place, without a copy. The
/// viewed memory must outlive the view and not change while an analysis reads it.
struct GridFieldView : GridGeometry {
  std::span<const double> values;          ///< n[0] * n[1] * n[2] values
  std::span<const std::uint8_t> is_void;   ///< empty (no void cells) or one flag per cell

  bool void_at(std::size_t i) const { return !is_void.empty() && is_void[i] != 0; }
  std::size_t void_count() const;
};

/// A field that owns its values. It converts to a GridFieldView, so every analysis accepts it.
struct GridField : GridGeometry {
  std::vector<double> values;         ///< n[0] * n[1] * n[2] values
  std::string units{};                ///< the values' unit as the file names it ("Pa", "1"); empty: not named
  std::vector<std::uint8_t> is_void;  ///< empty (no void cells) or one flag per cell

  /// A field of nx × ny × nz cells, all equal to `value`.
  static GridField filled(std::size_t nx, std::size_t ny, std::size_t nz, double value);

  bool void_at(std::size_t i) const { return !is_void.empty() && is_void[i] != 0; }
  std::size_t void_count() const { return view().void_count(); }
  GridFieldView view() const { return {GridGeometry(*this), values, is_void}; }
  operator GridFieldView() const { return view(); }  // NOLINT: a field is usable wherever a view is
};

/// Checks that the field can be analysed: at least one cell, values.size() matching the
/// dimensions, a void mask that is empty or of the same size, positive spacings, and no NaN or
/// infinite value in a non-void cell. Throws InputError naming `what` (a file name or a role such
/// as "reference field") and the first offending cell.
void validate(const GridFieldView& field, const std::string& what);

/// Throws InputError unless `a` and `b` have the same cell counts and spacings.
void require_same_grid(const GridGeometry& a, const GridGeometry& b, const std::string& what_a,
                       const std::string& what_b);

}  // namespace shockfield::analysis
