#pragma once
// Particles on a Cartesian rank grid (docs/parallel.md), written once for every particle method
// and generic over its particle record: owned particles migrate to the rank whose piece of the box
// holds them, and ghost copies of the particles within a cutoff of a neighbouring piece are sent to
// it (LAMMPS's Comm::exchange and Comm::borders). Axis by axis (x, then y, then z), ghosts of
// earlier axes included, so the ghosts of the up-to-26 neighbours (edges and corners) arrive in
// three rounds of two swaps. A periodic axis wraps through the rank grid and the images are
// shifted by the period; an axis of one rank is its own neighbour, and with it this is exactly the
// periodic-image ghosting of a serial run (md/ghosts is that case: one rank, every axis uncut).
//
// The particles are the caller's (structure of arrays, any fields): the exchange sees them
// through a small adaptor (the nanoflann way) that gives a coordinate, packs a record into doubles
// and appends received ones (the concepts below). The coordinate is any one that is affine along
// the axis: the position for an orthogonal box, the fractional coordinate for a triclinic cell (one
// rank only). The swaps of a ghost build are kept so that values of the owners can later be sent
// to their ghosts (forward) and ghost contributions summed back onto their owners (reverse).
#include <omp.h>

#include <array>
#include <concepts>
#include <cstddef>
#include <vector>

#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

/// One axis of the whole box in the exchange's coordinate: [lo, hi), periodic or bounded.
struct AxisSpan {
  double lo = 0, hi = 1;
  bool periodic = true;
};

/// One swap of ghosts along `axis`: this rank's entries `send` go to rank `dest`, imaged by
/// `periods` periods of the axis (0 unless the swap wraps), and `count` entries from rank
/// `source` are appended at [first, first + count). dest and source are this rank for a periodic
/// image on an axis of one rank; either may be no_rank at a bounded edge.
struct GhostSwap {
  int axis = 0, periods = 0;
  int dest = no_rank, source = no_rank;
  std::vector<std::size_t> send;
  std::size_t first = 0, count = 0;
};

/// What a ghost build needs of the particles: entries [0, size()) (owned, then ghosts), the
/// coordinate of entry i along an axis, a ghost record of `ghost_width` doubles (entry i imaged by
/// `periods` periods along `axis`), and appending received records (`from_self`: this rank sent
/// them, as a periodic image of its own entries).
template <class P>
concept GhostParticles = requires(P& p, const P& cp, std::size_t i, int axis, double* out, const double* in) {
  { cp.size() } -> std::convertible_to<std::size_t>;
  { cp.coordinate(i, axis) } -> std::convertible_to<double>;
  { P::ghost_width } -> std::convertible_to<int>;
  cp.pack_ghost(i, axis, /*periods=*/0, out);
  p.append_ghosts(in, /*count=*/i, /*from_self=*/true);
};

/// What a migration needs: the owned entries [0, owned()) (no ghosts), their coordinates, records
/// of `owned_width` doubles, removing the leaving ones (flags per owned entry, order kept) and
/// appending arrivals. Coordinates must already be wrapped into the periodic box.
template <class P>
concept MigratingParticles = requires(P& p, const P& cp, std::size_t i, int axis, double* out, const double* in,
                                      const std::vector<char>& leaving) {
  { cp.owned() } -> std::convertible_to<std::size_t>;
  { cp.coordinate(i, axis) } -> std::convertible_to<double>;
  { P::owned_width } -> std::convertible_to<int>;
  cp.pack_owned(i, out);
  p.remove_owned(leaving);
  p.append_owned(in, /*count=*/i);
};

class ParticleExchange {
 public:
  /// `grid`: a Cartesian communicator (its dims cut the spans evenly); `spans`: the whole box.
  /// InputError when a cut axis's pieces are shorter than `cutoff[axis]` (a ghost would need a
  /// rank beyond the neighbour). Collective.
  ParticleExchange(const Communicator& grid, const std::array<AxisSpan, 3>& spans,
                   const std::array<double, 3>& cutoff);

  const Communicator& comm() const { return comm_; }
  /// This rank's piece [lo, hi) of `axis`, and the rank coordinate owning coordinate x along it.
  double piece_lo(int axis) const { return boundary(axis, coords_[axis]); }
  double piece_hi(int axis) const { return boundary(axis, coords_[axis] + 1); }
  int owner_along(int axis, double x) const;
  /// Ranks along `axis` (1: uncut).
  int ranks_along(int axis) const { return dims_[axis]; }

  /// Sends every owned particle outside this rank's piece to the neighbour holding it, axis by
  /// axis. RunError when a particle is more than one piece away (it moved too far between two
  /// migrations). Collective.
  template <MigratingParticles P>
  void migrate(P& particles) const;

  /// Appends the ghosts of this rank (`layers[axis]` image layers on an uncut periodic axis, one
  /// on a cut axis) and returns the swaps that made them, in order. Collective.
  template <GhostParticles P>
  std::vector<GhostSwap> build_ghosts(P& particles, const std::array<int, 3>& layers) const;

  /// Owners' values to their ghosts, swap by swap: pack(entry, swap, out) writes `width` doubles
  /// of a sent entry, unpack(entry, in) stores a received one. Collective.
  template <class Pack, class Unpack>
  void forward(const std::vector<GhostSwap>& swaps, int width, Pack pack, Unpack unpack) const;
  /// Ghosts' values back onto the entries they were made from, swaps in reverse order:
  /// pack(ghost entry, out), add(sent entry, in). Collective.
  template <class Pack, class Add>
  void reverse(const std::vector<GhostSwap>& swaps, int width, Pack pack, Add add) const;

  /// The sum over ranks of a count (exact below 2^53). Collective.
  long long total(std::size_t count) const;

 private:
  double boundary(int axis, int part) const;
  [[noreturn]] void throw_moved_too_far(int axis, double x) const;
  bool wraps(int axis, int side) const;  // side 0: to the low neighbour
  // Sends `send` (whole records) to dest and returns what source sent.
  std::vector<double> transfer(const std::vector<double>& send, int dest, int source) const;
  // The entries of [0, n) whose coordinate imaged by `periods` lies in the receiver's piece ± cutoff.
  template <GhostParticles P>
  std::vector<std::size_t> select(const P& particles, std::size_t n, int axis, int periods, int receiver) const;

  Communicator comm_;
  std::array<AxisSpan, 3> spans_;
  std::array<double, 3> cutoff_;
  std::array<int, 3> dims_, coords_;
  std::array<std::array<int, 2>, 3> neighbours_;
};

template <GhostParticles P>
std::vector<std::size_t> ParticleExchange::select(const P& particles, std::size_t n, int axis, int periods,
                                                  int receiver) const {
  const double period = spans_[axis].hi - spans_[axis].lo;
  const double lo = boundary(axis, receiver) - cutoff_[axis], hi = boundary(axis, receiver + 1) + cutoff_[axis];
  // Each thread selects a contiguous range; concatenated in thread order they are a serial scan.
  std::vector<std::vector<std::size_t>> chosen(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel num_threads(static_cast<int>(chosen.size()))
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num()), team = static_cast<std::size_t>(omp_get_num_threads());
    auto& mine = chosen[t];
    for (std::size_t i = n * t / team; i < n * (t + 1) / team; ++i) {
      const double y = particles.coordinate(i, axis) + periods * period;
      if (!(y < lo || y >= hi)) mine.push_back(i);
    }
  }
  std::vector<std::size_t> all;
  for (const auto& part : chosen) all.insert(all.end(), part.begin(), part.end());
  return all;
}

template <GhostParticles P>
std::vector<GhostSwap> ParticleExchange::build_ghosts(P& particles, const std::array<int, 3>& layers) const {
  constexpr int width = P::ghost_width;
  std::vector<GhostSwap> swaps;
  for (int axis = 0; axis < 3; ++axis) {
    const int passes = 2 * (dims_[axis] > 1 ? 1 : layers[axis]);
    const std::size_t n = particles.size();  // owned + ghosts of earlier axes
    // Pass p: layer k = p/2 + 1; p even sends to the high neighbour (the images land on its low
    // side, shifted by -k periods when the pass wraps), p odd to the low one.
    for (int p = 0; p < passes; ++p) {
      const int side = p % 2 == 0 ? 1 : 0, k = p / 2 + 1;
      GhostSwap s;
      s.axis = axis;
      s.dest = neighbours_[axis][side];
      s.source = neighbours_[axis][1 - side];
      s.periods = wraps(axis, side) ? (side == 1 ? -k : k) : 0;
      const int receiver = (coords_[axis] + (side == 1 ? 1 : -1) + dims_[axis]) % dims_[axis];
      if (s.dest != no_rank) s.send = select(particles, n, axis, s.periods, receiver);
      std::vector<double> out(s.send.size() * width);
      const auto m = static_cast<std::ptrdiff_t>(s.send.size());
#pragma omp parallel for schedule(static)
      for (std::ptrdiff_t j = 0; j < m; ++j)
        particles.pack_ghost(s.send[static_cast<std::size_t>(j)], axis, s.periods, out.data() + j * width);
      const std::vector<double> in = transfer(out, s.dest, s.source);
      s.first = particles.size();
      s.count = in.size() / width;
      particles.append_ghosts(in.data(), s.count, s.source == comm_.rank());
      swaps.push_back(std::move(s));
    }
  }
  return swaps;
}

template <MigratingParticles P>
void ParticleExchange::migrate(P& particles) const {
  constexpr int width = P::owned_width;
  for (int axis = 0; axis < 3; ++axis) {
    if (dims_[axis] == 1) continue;
    const int c = coords_[axis], d = dims_[axis];
    // side 0: to the low neighbour, 1: to the high one (with two ranks they are the same rank).
    std::array<std::vector<double>, 2> out;
    std::vector<char> leaving(particles.owned(), 0);
    for (std::size_t i = 0; i < particles.owned(); ++i) {
      const int owner = owner_along(axis, particles.coordinate(i, axis));
      if (owner == c) continue;
      const int side = owner == (c + d - 1) % d ? 0 : owner == (c + 1) % d ? 1 : -1;
      if (side < 0 || neighbours_[axis][side] == no_rank) throw_moved_too_far(axis, particles.coordinate(i, axis));
      leaving[i] = 1;
      out[side].resize(out[side].size() + width);
      particles.pack_owned(i, out[side].data() + out[side].size() - width);
    }
    particles.remove_owned(leaving);
    for (int side = 0; side < 2; ++side) {
      const std::vector<double> in = transfer(out[side], neighbours_[axis][side], neighbours_[axis][1 - side]);
      particles.append_owned(in.data(), in.size() / width);
    }
  }
}

template <class Pack, class Unpack>
void ParticleExchange::forward(const std::vector<GhostSwap>& swaps, int width, Pack pack, Unpack unpack) const {
  for (const GhostSwap& s : swaps) {
    std::vector<double> out(s.send.size() * width);
    for (std::size_t j = 0; j < s.send.size(); ++j) pack(s.send[j], s, out.data() + j * width);
    const std::vector<double> in = transfer(out, s.dest, s.source);
    for (std::size_t j = 0; j < s.count; ++j) unpack(s.first + j, in.data() + j * width);
  }
}

template <class Pack, class Add>
void ParticleExchange::reverse(const std::vector<GhostSwap>& swaps, int width, Pack pack, Add add) const {
  for (auto s = swaps.rbegin(); s != swaps.rend(); ++s) {
    std::vector<double> out(s->count * width);
    for (std::size_t j = 0; j < s->count; ++j) pack(s->first + j, out.data() + j * width);
    const std::vector<double> in = transfer(out, s->source, s->dest);
    for (std::size_t j = 0; j < s->send.size(); ++j) add(s->send[j], in.data() + j * width);
  }
}

}  // namespace shockfield::parallel
