#include "shockfield/parallel/particle_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/parallel/ordered_sum.hpp"

namespace shockfield::parallel {

ParticleExchange::ParticleExchange(const Communicator& grid, const std::array<AxisSpan, 3>& spans,
                                   const std::array<double, 3>& cutoff)
    : comm_(grid), spans_(spans), cutoff_(cutoff), coords_(grid.coordinates()) {
  for (int a = 0; a < 3; ++a) {
    neighbours_[a] = grid.neighbours(a);
    dims_[a] = 1;
  }
  // The rank grid's extent along each axis: one more than the largest coordinate along it.
  const std::vector<double> all = grid.all_gather({double(coords_[0]), double(coords_[1]), double(coords_[2])});
  for (std::size_t r = 0; r < all.size(); r += 3)
    for (int a = 0; a < 3; ++a) dims_[a] = std::max(dims_[a], static_cast<int>(all[r + a]) + 1);
  for (int a = 0; a < 3; ++a) {
    if (dims_[a] == 1) continue;
    const double piece = (spans[a].hi - spans[a].lo) / dims_[a];
    if (!(piece >= cutoff[a]))
      throw InputError(fmt::format(
          "{} ranks along {} cut the box ({} long) into pieces of {:.4g}, shorter than the ghost cutoff {:.4g} "
          "(interaction range + skin): a ghost would come from beyond the next rank; use at most {} ranks along {}",
          dims_[a], "xyz"[a], spans[a].hi - spans[a].lo, piece, cutoff[a],
          std::max(1, static_cast<int>(std::floor((spans[a].hi - spans[a].lo) / cutoff[a]))), "xyz"[a]));
  }
}

double ParticleExchange::boundary(int axis, int part) const {
  const AxisSpan& s = spans_[axis];
  if (part <= 0) return s.lo;  // exactly the box's faces at both ends
  if (part >= dims_[axis]) return s.hi;
  return s.lo + (s.hi - s.lo) * part / dims_[axis];
}

int ParticleExchange::owner_along(int axis, double x) const {
  const AxisSpan& s = spans_[axis];
  const int d = dims_[axis];
  int part = static_cast<int>(std::floor((x - s.lo) / (s.hi - s.lo) * d));
  part = std::clamp(part, 0, d - 1);
  // The estimate may be off by one at a boundary: the pieces [boundary(p), boundary(p + 1)) decide.
  while (part > 0 && x < boundary(axis, part)) --part;
  while (part < d - 1 && x >= boundary(axis, part + 1)) ++part;
  return part;
}

bool ParticleExchange::wraps(int axis, int side) const {
  return spans_[axis].periodic && (side == 0 ? coords_[axis] == 0 : coords_[axis] == dims_[axis] - 1);
}

void ParticleExchange::throw_moved_too_far(int axis, double x) const {
  throw RunError(fmt::format("a particle at {} = {} left this rank's piece [{}, {}) by more than one neighbouring "
                             "piece between two migrations (it moved too far, or left a bounded box)",
                             "xyz"[axis], x, piece_lo(axis), piece_hi(axis)));
}

std::vector<double> ParticleExchange::transfer(const std::vector<double>& send, int dest, int source) const {
  std::vector<double> count_in(source == no_rank ? 0 : 1);
  comm_.send_receive(std::vector<double>(dest == no_rank ? 0 : 1, static_cast<double>(send.size())), dest, count_in,
                     source);
  std::vector<double> in(count_in.empty() ? 0 : static_cast<std::size_t>(count_in[0]));
  static const std::vector<double> nothing;
  comm_.send_receive(dest == no_rank ? nothing : send, dest, in, source);
  return in;
}

long long ParticleExchange::total(std::size_t count) const {
  return static_cast<long long>(ordered_sum(comm_, {static_cast<double>(count)}, {comm_.rank()}, 1)[0]);
}

}  // namespace shockfield::parallel
