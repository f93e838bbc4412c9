#include "shockfield/parallel/halo_exchange.hpp"

#include <stdexcept>

namespace shockfield::parallel {

HaloExchange::HaloExchange(const Communicator& grid, const GridLayout& layout, const std::array<bool, 3>& exchanged)
    : comm_(grid), layout_(layout) {
  for (int a = 0; a < 3; ++a) {
    const bool used = exchanged[a] && layout.ghosts[a] > 0;
    if (used && layout.ghosts[a] > layout.interior[a])
      throw std::logic_error("halo exchange: a block thinner than its ghost layers");
    neighbours_[a] = used ? grid.neighbours(a) : std::array<int, 2>{no_rank, no_rank};
  }
}

std::size_t HaloExchange::slab_size(int axis) const {
  std::size_t n = static_cast<std::size_t>(layout_.ghosts[axis]) * layout_.components;
  for (int b = 0; b < 3; ++b)
    if (b != axis) n *= static_cast<std::size_t>(b < axis ? layout_.extent(b) : layout_.interior[b]);
  return n;
}

void HaloExchange::copy_slab(double* data, int axis, int first, std::vector<double>& buffer, bool to_buffer) const {
  // Along axes before `axis`: every cell, ghosts included; after it: the interior.
  std::array<int, 3> lo{}, hi{};
  for (int b = 0; b < 3; ++b) {
    lo[b] = b < axis ? -layout_.ghosts[b] : 0;
    hi[b] = b < axis ? layout_.interior[b] + layout_.ghosts[b] : layout_.interior[b];
  }
  lo[axis] = first;
  hi[axis] = first + layout_.ghosts[axis];
  std::size_t n = 0;
  for (int c = 0; c < layout_.components; ++c) {
    double* component = data + static_cast<std::size_t>(c) * layout_.component_stride;
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i, ++n) {
          double& cell = component[layout_.at(i, j, k)];
          if (to_buffer) buffer[n] = cell;
          else cell = buffer[n];
        }
  }
}

void HaloExchange::exchange(double* data, int axis) const {
  const int w = layout_.ghosts[axis], n = layout_.interior[axis];
  const auto [low, high] = neighbours_[axis];
  if (low == no_rank && high == no_rank) return;
  std::vector<double> send(slab_size(axis)), recv(slab_size(axis));
  // Low face to the low neighbour, the high neighbour's low face into the high ghosts; then back.
  copy_slab(data, axis, 0, send, true);
  comm_.send_receive(send, low, recv, high);
  if (high != no_rank) copy_slab(data, axis, n, recv, false);
  copy_slab(data, axis, n - w, send, true);
  comm_.send_receive(send, high, recv, low);
  if (low != no_rank) copy_slab(data, axis, -w, recv, false);
}

std::size_t HaloExchange::doubles_per_exchange() const {
  std::size_t n = 0;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side)
      if (neighbours_[a][side] != no_rank) n += slab_size(a);
  return n;
}

}  // namespace shockfield::parallel
