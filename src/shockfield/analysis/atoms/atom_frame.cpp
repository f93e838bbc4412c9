#include "shockfield/analysis/atoms/atom_frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis::atoms {

void validate_frame(const AtomFrame& frame, const std::string& source) {
  const std::size_t n = frame.size();
  if (!frame.types.empty() && frame.types.size() != n)
    throw InputError(fmt::format("{}: {} types for {} atoms", source, frame.types.size(), n));
  if (!frame.ids.empty() && frame.ids.size() != n)
    throw InputError(fmt::format("{}: {} ids for {} atoms", source, frame.ids.size(), n));
  const Vec3 length = frame.box.length();
  for (int d = 0; d < 3; ++d)
    if (!(length[d] > 0) || !std::isfinite(length[d]))
      throw InputError(fmt::format("{}: box {} bounds [{}, {}] do not give a positive length", source,
                                   "xyz"[d], frame.box.lo[d], frame.box.hi[d]));
  auto id_of = [&](std::size_t i) { return frame.ids.empty() ? static_cast<std::int64_t>(i + 1) : frame.ids[i]; };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = frame.positions[i];
    if (!x.allFinite())
      throw InputError(fmt::format("{}: atom id {} has a non-finite position", source, id_of(i)));
    // a triclinic cell is bounded by its faces: fractional coordinates against [0, 1]
    const Vec3 s = frame.box.triclinic() ? frame.box.to_fractional(x) : x;
    const Vec3 lo = frame.box.triclinic() ? Vec3::Zero() : frame.box.lo;
    const Vec3 hi = frame.box.triclinic() ? Vec3::Ones() : frame.box.hi;
    for (int d = 0; d < 3; ++d)
      if (frame.box.boundary[d] == geometry::Boundary::fixed && (s[d] < lo[d] || s[d] > hi[d]))
        throw InputError(fmt::format("{}: atom id {} at {} = {} is outside the fixed box bounds [{}, {}]{}", source,
                                     id_of(i), "xyz"[d], x[d], frame.box.lo[d], frame.box.hi[d],
                                     frame.box.triclinic() ? " of the tilted cell" : ""));
  }
  if (frame.ids.empty()) return;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return frame.ids[a] < frame.ids[b]; });
  for (std::size_t k = 1; k < n; ++k)
    if (frame.ids[order[k]] == frame.ids[order[k - 1]])
      throw InputError(fmt::format("{}: atom id {} appears twice (rows {} and {} of the frame)", source,
                                   frame.ids[order[k]], std::min(order[k], order[k - 1]) + 1,
                                   std::max(order[k], order[k - 1]) + 1));
}

AtomFrame frame_from_dump(const io::DumpFrame& dump, const std::string& source) {
  AtomFrame frame;
  frame.timestep = dump.timestep;
  frame.box = dump.box;
  const std::string where = fmt::format("{} (timestep {})", source, dump.timestep);
  if (dump.natoms() > 0) {
    frame.positions = dump.positions();  // its error names the dump file and the timestep
    if (dump.has("type")) frame.types = dump.types();
    if (dump.has("id")) frame.ids = dump.ids();
  }
  validate_frame(frame, where);
  return frame;
}

AtomFrame frame_from_atoms(long long timestep, const geometry::Box& box, const md::Atoms& atoms,
                           const std::string& source) {
  AtomFrame frame;
  frame.timestep = timestep;
  frame.box = box;
  const auto n = static_cast<std::ptrdiff_t>(atoms.nlocal);
  frame.positions.assign(atoms.x.begin(), atoms.x.begin() + n);
  frame.types.resize(atoms.nlocal);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) frame.types[i] = atoms.type[i] + 1;
  frame.ids.assign(atoms.id.begin(), atoms.id.begin() + n);
  validate_frame(frame, source);
  return frame;
}

}  // namespace shockfield::analysis::atoms
