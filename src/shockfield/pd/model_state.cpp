#include "shockfield/pd/model_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <numeric>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {

std::size_t ModelStateArray::row_size() const {
  return std::accumulate(shape.begin(), shape.end(), std::size_t{1}, std::multiplies<>());
}

const ModelStateArray& saved_array(const ModelState& state, const std::string& model, const std::string& name,
                                   std::size_t rows, std::size_t row_size, bool integer) {
  const auto it = std::find_if(state.begin(), state.end(), [&](const ModelStateArray& a) { return a.name == name; });
  if (it == state.end())
    throw InputError(fmt::format("pd {}: the saved state has no '{}' (a checkpoint of another force model?)", model,
                                 name));
  if (it->integer != integer)
    throw InputError(fmt::format("pd {}: saved state '{}' is stored as {}, expected {}", model, name,
                                 it->integer ? "integers" : "reals", integer ? "integers" : "reals"));
  const std::size_t held = it->integer ? it->counts.size() : it->reals.size();
  if (held != rows * row_size)
    throw InputError(fmt::format("pd {}: saved state '{}' has {} values, expected {} ({} rows of {})", model, name,
                                 held, rows * row_size, rows, row_size));
  return *it;
}

}  // namespace shockfield::pd
