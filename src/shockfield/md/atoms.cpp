#include "shockfield/md/atoms.hpp"

#include <algorithm>

namespace shockfield::md {

void Atoms::add(const Vec3& pos, int type0, std::int64_t tag, const Vec3& vel) {
  x.push_back(pos);
  type.push_back(type0);
  v.push_back(vel);
  f.push_back(Vec3::Zero());
  id.push_back(tag);
  image.push_back({0, 0, 0});
  mask.push_back(1u);
  ++nlocal;
}

void Atoms::clear_ghosts() {
  x.resize(nlocal);
  type.resize(nlocal);
  f.resize(nlocal);
  ghost_owner.clear();
  ghost_image.clear();
}

void Atoms::keep(const std::vector<bool>& flag) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < nlocal; ++i) {
    if (!flag[i]) continue;
    x[k] = x[i]; type[k] = type[i]; v[k] = v[i]; f[k] = f[i];
    id[k] = id[i]; image[k] = image[i]; mask[k] = mask[i];
    ++k;
  }
  nlocal = k;
  x.resize(k); type.resize(k); v.resize(k); f.resize(k);
  id.resize(k); image.resize(k); mask.resize(k);
}

void Atoms::update_ghost_positions(const geometry::Box& box) {
  if (ranks) return ranks->update_ghost_positions(*this, box);
  for (std::size_t g = 0; g < nghost(); ++g) x[nlocal + g] = x[ghost_owner[g]] + box.lattice_shift(ghost_image[g]);
}

std::int64_t Atoms::max_id() const {
  return id.empty() ? 0 : *std::max_element(id.begin(), id.end());
}

}  // namespace shockfield::md
