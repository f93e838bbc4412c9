#pragma once
// The state a force model carries from step to step (broken bonds, critical stretches,
// deformation gradients, plastic variables), as named arrays with units: what a checkpoint stores
// one dataset per quantity (docs/checkpoints.md) and a resume hands back.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace shockfield::pd {

/// One quantity: `rows` entries (points or bonds) of `shape` values each (empty: a scalar per row),
/// real (`reals`) or integer (`counts`, for flags and counters), row-major.
struct ModelStateArray {
  std::string name;
  std::string units;                 ///< "1" for a pure number
  std::size_t rows = 0;
  std::vector<std::size_t> shape;    ///< values per row, e.g. {9} for a tensor, {grains, 9}
  bool integer = false;              ///< values in `counts`, else in `reals`
  std::vector<double> reals;
  std::vector<std::int64_t> counts;
  std::size_t row_size() const;
  bool operator==(const ModelStateArray&) const = default;
};

using ModelState = std::vector<ModelStateArray>;

/// The array `name` of `state` holding exactly rows × row_size values, integers if `integer`;
/// InputError naming `model`, the array and what was expected otherwise (a checkpoint of another
/// case or model).
const ModelStateArray& saved_array(const ModelState& state, const std::string& model, const std::string& name,
                                   std::size_t rows, std::size_t row_size, bool integer);

}  // namespace shockfield::pd
