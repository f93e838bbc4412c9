#include "shockfield/md/decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "shockfield/core/error.hpp"
#include "shockfield/md/ghosts.hpp"
#include "shockfield/parallel/ordered_sum.hpp"

namespace shockfield::md {
namespace {

// An owned atom as 12 doubles: x y z, vx vy vz, image counts, id, type, mask (ids and masks are
// exact in a double below 2^53).
void pack_atom(const Atoms& atoms, std::size_t i, double* out) {
  const Vec3& x = atoms.x[i];
  const Vec3& v = atoms.v[i];
  const auto& n = atoms.image[i];
  const double record[12] = {x[0], x[1], x[2], v[0], v[1], v[2], double(n[0]), double(n[1]), double(n[2]),
                             static_cast<double>(atoms.id[i]), double(atoms.type[i]), double(atoms.mask[i])};
  std::copy(record, record + 12, out);
}

// Atoms as the particle exchange sees them for migration (records of pack_atom).
struct MigratingAtoms {
  Atoms& atoms;
  static constexpr int owned_width = 12;
  std::size_t owned() const { return atoms.nlocal; }
  double coordinate(std::size_t i, int d) const { return atoms.x[i][d]; }
  void pack_owned(std::size_t i, double* out) const { pack_atom(atoms, i, out); }
  void remove_owned(const std::vector<char>& leaving) {
    std::vector<bool> keep(leaving.size());
    for (std::size_t i = 0; i < leaving.size(); ++i) keep[i] = !leaving[i];
    atoms.keep(keep);
  }
  void append_owned(const double* in, std::size_t count) {
    for (std::size_t j = 0; j < count; ++j) {
      const double* r = in + j * owned_width;
      atoms.add(Vec3(r[0], r[1], r[2]), static_cast<int>(r[10]), static_cast<std::int64_t>(r[9]), Vec3(r[3], r[4], r[5]));
      atoms.image.back() = {static_cast<int>(r[6]), static_cast<int>(r[7]), static_cast<int>(r[8])};
      atoms.mask.back() = static_cast<std::uint32_t>(r[11]);
    }
  }
};

// Adds the wall time of its scope to `seconds`.
class HaloTimer {
 public:
  explicit HaloTimer(double& seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  ~HaloTimer() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point start_;
};

std::string box_text(const geometry::Box& box) {
  const Vec3 l = box.length();
  return fmt::format("{:.4g} x {:.4g} x {:.4g} Å", l[0], l[1], l[2]);
}

}  // namespace

parallel::Dims3 md_rank_grid(const geometry::Box& box, double ghost_cutoff, int ranks, const parallel::Dims3& given) {
  if (box.triclinic())
    throw InputError(fmt::format("a triclinic box runs on one rank only so far ({} ranks started)", ranks));
  // The pieces an axis can be cut into; a shrink-wrapped axis is not cut (its faces move).
  parallel::Cells3 pieces{1, 1, 1};
  for (int d = 0; d < 3; ++d)
    if (box.boundary[d] != geometry::Boundary::shrink)
      pieces[d] = std::max(1LL, static_cast<long long>(std::floor(box.length()[d] / ghost_cutoff)));
  const bool chosen = given == parallel::Dims3{0, 0, 0};
  try {
    if (chosen) return parallel::choose_rank_grid(pieces, ranks, 1);
    parallel::check_rank_grid(given, pieces, ranks, 1);
    return given;
  } catch (const InputError& e) {
    if (!chosen && static_cast<long long>(given[0]) * given[1] * given[2] != ranks) throw;
    throw InputError(fmt::format(
        "{} ranks cannot cut the box ({}) into pieces at least {:.4g} Å long (the interaction range: cutoff + "
        "skin) along every cut axis{}; at most {} x {} x {} = {} ranks fit",
        ranks, box_text(box), ghost_cutoff, chosen ? "" : fmt::format(" as --rank-grid {}x{}x{}", given[0], given[1], given[2]),
        pieces[0], pieces[1], pieces[2], pieces[0] * pieces[1] * pieces[2]));
  }
}

Decomposition::Decomposition(const parallel::Communicator& world, const parallel::Dims3& dims,
                             const geometry::Box& box, double ghost_cutoff)
    : dims_(dims),
      exchange_(world.cartesian(dims, {box.periodic(0), box.periodic(1), box.periodic(2)}), ghost_spans(box),
                ghost_cutoffs(box, ghost_cutoff)) {}

Atoms gather_atoms(const Decomposition& domain, const Atoms& atoms) {
  constexpr int width = MigratingAtoms::owned_width;
  std::vector<double> mine(atoms.nlocal * width);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) pack_atom(atoms, i, mine.data() + i * width);
  const std::vector<double> all = domain.comm().gather(mine);
  Atoms whole;
  whole.mass = atoms.mass;
  whole.type_names = atoms.type_names;
  // Records in id order (ids are 1..N in a system built or read by the serial code, but need not be).
  std::vector<std::size_t> order(all.size() / width);
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all[a * width + 9] < all[b * width + 9]; });
  std::vector<double> sorted(all.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    std::copy(all.begin() + static_cast<std::ptrdiff_t>(order[k] * width),
              all.begin() + static_cast<std::ptrdiff_t>((order[k] + 1) * width), sorted.begin() + static_cast<std::ptrdiff_t>(k * width));
  MigratingAtoms{whole}.append_owned(sorted.data(), order.size());
  return whole;
}

std::vector<Vec3> gather_by_id(const Decomposition& domain, const Atoms& atoms, const std::vector<Vec3>& values) {
  std::vector<double> mine;
  mine.reserve(4 * atoms.nlocal);
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    mine.insert(mine.end(), {static_cast<double>(atoms.id[i]), values[i][0], values[i][1], values[i][2]});
  const std::vector<double> all = domain.comm().gather(mine);
  std::vector<std::size_t> order(all.size() / 4);
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all[4 * a] < all[4 * b]; });
  std::vector<Vec3> sorted;
  sorted.reserve(order.size());
  for (std::size_t k : order) sorted.emplace_back(all[4 * k + 1], all[4 * k + 2], all[4 * k + 3]);
  return sorted;
}

void keep_own_atoms(const Decomposition& domain, Atoms& atoms) {
  std::vector<bool> keep(atoms.nlocal);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) keep[i] = domain.owns(atoms.x[i]);
  atoms.clear_ghosts();
  atoms.keep(keep);
}

bool Decomposition::owns(const Vec3& x) const {
  const std::array<int, 3> here = comm().coordinates();
  for (int d = 0; d < 3; ++d)
    if (exchange_.owner_along(d, x[d]) != here[d]) return false;
  return true;
}

void Decomposition::rebuild(Atoms& atoms, const geometry::Box& box, double ghost_cutoff) {
  const HaloTimer timer(halo_seconds);
  atoms.clear_ghosts();
  for (std::size_t i = 0; i < atoms.nlocal; ++i) box.wrap(atoms.x[i], atoms.image[i]);
  MigratingAtoms owned{atoms};
  exchange_.migrate(owned);
  GhostAtoms view{atoms, box, false};
  swaps_ = exchange_.build_ghosts(view, ghost_layers(box, ghost_cutoff));
  atoms.f.resize(atoms.size());
  atoms.ranks = shared_from_this();
}

void Decomposition::check_total(const Atoms& atoms) {
  const long long total = total_atoms(atoms);
  if (first_total_ < 0) first_total_ = total;
  if (total != first_total_)
    throw std::logic_error(fmt::format("atoms lost or owned twice across ranks: {} now, {} at the start", total,
                                       first_total_));
}

bool Decomposition::any(bool flag) const { return comm().min(flag ? 0 : 1) == 0; }

double Decomposition::max(double value) const {
  const std::vector<double> all = comm().all_gather({value});
  return *std::max_element(all.begin(), all.end());
}

void Decomposition::reverse_sum(double* values, int width) const {
  const HaloTimer timer(halo_seconds);
  exchange_.reverse(
      swaps_, width, [&](std::size_t k, double* out) { std::copy(values + k * width, values + (k + 1) * width, out); },
      [&](std::size_t i, const double* in) {
        for (int c = 0; c < width; ++c) values[i * width + c] += in[c];
      });
}

void Decomposition::forward_copy(double* values, int width) const {
  const HaloTimer timer(halo_seconds);
  exchange_.forward(
      swaps_, width,
      [&](std::size_t i, const parallel::GhostSwap&, double* out) {
        std::copy(values + i * width, values + (i + 1) * width, out);
      },
      [&](std::size_t k, const double* in) { std::copy(in, in + width, values + k * width); });
}

void Decomposition::update_ghost_positions(Atoms& atoms, const geometry::Box& box) const {
  const HaloTimer timer(halo_seconds);
  exchange_.forward(
      swaps_, 3,
      [&](std::size_t i, const parallel::GhostSwap& s, double* out) {
        Vec3 x = atoms.x[i];
        x[s.axis] += s.periods * (box.hi[s.axis] - box.lo[s.axis]);  // as GhostAtoms::pack_ghost
        std::copy(x.data(), x.data() + 3, out);
      },
      [&](std::size_t k, const double* in) { atoms.x[k] = Vec3(in[0], in[1], in[2]); });
}

std::vector<double> Decomposition::sum(const std::vector<double>& partials) const {
  return parallel::ordered_sum(comm(), partials, {comm().rank()}, static_cast<int>(partials.size()));
}

}  // namespace shockfield::md
