#include "shockfield/md/fix.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/core/error.hpp"

namespace shockfield::md {

const std::vector<double>& fix_state_values(const FixState& state, const std::string& fix, const std::string& name,
                                            std::size_t count) {
  const auto it = std::find_if(state.begin(), state.end(), [&](const FixStateItem& s) { return s.name == name; });
  static const std::vector<double> none;
  if (it == state.end() && count == 0) return none;  // an empty variable (a chain of length 0) is not stored
  if (it == state.end())
    throw InputError(fmt::format("fix {}: the checkpoint holds no '{}' (a checkpoint of another fix?)", fix, name));
  if (it->values.size() != count)
    throw InputError(fmt::format("fix {}: the checkpoint's '{}' has {} values, expected {}", fix, name,
                                 it->values.size(), count));
  return it->values;
}

}  // namespace shockfield::md
