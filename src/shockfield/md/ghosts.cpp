#include "shockfield/md/ghosts.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::md {
namespace {
constexpr double kMaxGhostLayers = 8;
}  // namespace

void rebuild_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff) {
  atoms.clear_ghosts();
  for (std::size_t i = 0; i < atoms.nlocal; ++i) box.wrap(atoms.x[i], atoms.image[i]);
  for (int d = 0; d < 3; ++d) {
    if (!box.periodic(d)) continue;
    const double length = box.hi[d] - box.lo[d];
    const double needed = std::ceil(cutoff / length);
    // Each layer copies every atom again: beyond a few layers the box is degenerate, not small.
    if (!(needed <= kMaxGhostLayers))
      throw RunError(fmt::format("the periodic box is {} Å long along {}, less than 1/{} of the "
                                 "interaction range {} Å (cutoff + skin): ghost images cannot be built",
                                 length, "xyz"[d], kMaxGhostLayers, cutoff));
    const int layers = static_cast<int>(needed);
    const std::size_t n = atoms.size();  // owned + ghosts of earlier dimensions
    for (int layer = 1; layer <= layers; ++layer) {
      for (int side = -1; side <= 1; side += 2) {
        Vec3 shift = Vec3::Zero();
        shift[d] = side * layer * length;
        std::array<int, 3> step{0, 0, 0};
        step[d] = side * layer;
        for (std::size_t i = 0; i < n; ++i) {
          const double y = atoms.x[i][d] + shift[d];
          if (y < box.lo[d] - cutoff || y >= box.hi[d] + cutoff) continue;
          const bool is_ghost = i >= atoms.nlocal;
          const int owner = is_ghost ? atoms.ghost_owner[i - atoms.nlocal] : static_cast<int>(i);
          std::array<int, 3> image = step;
          if (is_ghost)
            for (int k = 0; k < 3; ++k) image[k] += atoms.ghost_image[i - atoms.nlocal][k];
          atoms.x.push_back(atoms.x[i] + shift);
          atoms.type.push_back(atoms.type[i]);
          atoms.ghost_owner.push_back(owner);
          atoms.ghost_image.push_back(image);
        }
      }
    }
  }
  atoms.f.resize(atoms.size());
}

}  // namespace shockfield::md
