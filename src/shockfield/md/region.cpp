#include "shockfield/md/region.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::md {

std::size_t delete_atoms(const Region& region, Atoms& atoms) {
  std::vector<bool> keep(atoms.nlocal);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) keep[i] = !region.match(atoms.x[i]);
  const std::size_t before = atoms.nlocal;
  atoms.keep(keep);
  return before - atoms.nlocal;
}

std::uint32_t GroupTable::bit(const std::string& name) {
  if (has(name)) return find(name);
  if (names_.size() == 32)
    throw InputError(fmt::format("group '{}': too many groups (at most 32, 'all' included)", name));
  names_.push_back(name);
  return 1u << (names_.size() - 1);
}

bool GroupTable::has(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::uint32_t GroupTable::find(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end())
    throw InputError(fmt::format("unknown group '{}' (groups: {})", name, fmt::join(names_, ", ")));
  return 1u << (it - names_.begin());
}

namespace {
template <class Pred>
std::size_t add_if(std::uint32_t bit, Atoms& atoms, Pred pred) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) {
    if (pred(i)) atoms.mask[i] |= bit;
    n += (atoms.mask[i] & bit) != 0;
  }
  return n;
}
}  // namespace

std::size_t add_to_group(std::uint32_t bit, const Region& region, Atoms& atoms) {
  return add_if(bit, atoms, [&](std::size_t i) { return region.match(atoms.x[i]); });
}

std::size_t add_to_group(std::uint32_t bit, const std::vector<int>& types, Atoms& atoms) {
  return add_if(bit, atoms, [&](std::size_t i) {
    return std::find(types.begin(), types.end(), atoms.type[i]) != types.end();
  });
}

}  // namespace shockfield::md
