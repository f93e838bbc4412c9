#include "shockfield/analysis/atoms/neighbor_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "shockfield/core/error.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/ghosts.hpp"

namespace shockfield::analysis::atoms {
namespace {

// The frame as the owned atoms of md::append_ghosts, which reads positions, types and images only
// (velocities, ids and masks are not needed). Room for the ghosts is reserved and the arrays are
// filled by all threads: copied or appended on one thread, they were a serial part of every
// analysis (bench/RESULTS.md).
md::Atoms owned_atoms(const AtomFrame& frame, double cutoff) {
  md::Atoms atoms;
  const std::size_t n = frame.size(), capacity = md::ghost_capacity(n, frame.box, cutoff);
  atoms.x.reserve(capacity);
  atoms.type.reserve(capacity);
  atoms.x.resize(n);  // Vec3's constructor leaves the entries unset: the loop below touches them first
  atoms.type.resize(n);
  atoms.image.resize(n);
  const auto sn = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < sn; ++i) {
    const auto u = static_cast<std::size_t>(i);
    atoms.x[u] = frame.positions[u];
    atoms.image[u] = {0, 0, 0};
  }
  atoms.nlocal = n;
  md::append_ghosts(atoms, frame.box, cutoff);
  return atoms;
}

}  // namespace

NeighborRequest NeighborRequest::combined(const NeighborRequest& other) const {
  return {std::max(cutoff, other.cutoff), std::max(min_neighbors, other.min_neighbors)};
}

double density_cutoff(const AtomFrame& frame, int count) {
  if (frame.size() == 0 || count <= 0) return 0;
  // Radius of a sphere holding `count` atoms at number density n: (3 count / (4π n))^(1/3).
  const double density = static_cast<double>(frame.size()) / frame.box.volume();
  return 1.1 * std::cbrt(3.0 * count / (4.0 * std::numbers::pi * density));
}

NeighborTable::NeighborTable(const AtomFrame& frame, const NeighborRequest& request)
    : request_(request), nlocal_(frame.size()) {
  if (request.cutoff < 0 || request.min_neighbors < 0 || (request.cutoff == 0 && request.min_neighbors == 0))
    throw InputError(fmt::format("neighbour request needs a positive cutoff or neighbour count (got cutoff {}, "
                                 "count {})", request.cutoff, request.min_neighbors));
  offset_.assign(1, 0);
  if (nlocal_ == 0) return;  // nothing to search
  const double cutoff = std::max(request.cutoff, density_cutoff(frame, request.min_neighbors));
  md::Atoms atoms = owned_atoms(frame, cutoff);
  points_ = std::move(atoms.x);
  ghost_owner_ = std::move(atoms.ghost_owner);
  geometry::NeighborList list;
  geometry::build_neighbor_list(points_, nlocal_, cutoff, /*half=*/false, list);
  offset_ = std::move(list.offset);
  neighbors_ = std::move(list.neighbors);
  reach_.assign(nlocal_, cutoff);

  // Each atom's neighbours nearest first (sort_nearest).
  const auto n = static_cast<std::ptrdiff_t>(nlocal_);
#pragma omp parallel
  {
    std::vector<std::pair<double, int>> scratch;
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const auto u = static_cast<std::size_t>(i);
      scratch.clear();
      for (std::int64_t k = offset_[u]; k < offset_[u + 1]; ++k)
        scratch.emplace_back(delta(u, neighbors_[static_cast<std::size_t>(k)]).squaredNorm(),
                             neighbors_[static_cast<std::size_t>(k)]);
      sort_nearest(scratch);
      for (std::size_t k = 0; k < scratch.size(); ++k)
        neighbors_[static_cast<std::size_t>(offset_[u]) + k] = scratch[k].second;
    }
  }

  std::vector<std::vector<int>> lists;  // replacement lists of widened atoms, empty for the others
  const double diagonal = frame.box.length().norm();
  double radius = cutoff;
  for (int round = 0; round < kMaxWidenings && radius < diagonal; ++round) {
    const auto short_atoms = atoms_short_of_request(lists);
    if (short_atoms.empty()) break;
    if (lists.empty()) lists.resize(nlocal_);
    radius *= 2;
    widen(frame, short_atoms, lists, radius);
  }
  if (lists.empty()) return;  // no atom was short of its request
  // Splice the widened lists into the CSR table.
  UninitializedVector<std::int64_t> offset(nlocal_ + 1, 0);
  UninitializedVector<int> merged;
  for (std::size_t i = 0; i < nlocal_; ++i) {
    if (lists[i].empty()) {
      const auto own = of(i);
      merged.insert(merged.end(), own.begin(), own.end());
    } else {
      merged.insert(merged.end(), lists[i].begin(), lists[i].end());
    }
    offset[i + 1] = static_cast<std::int64_t>(merged.size());
  }
  offset_.swap(offset);
  neighbors_.swap(merged);
}

void NeighborTable::sort_nearest(std::vector<std::pair<double, int>>& found) const {
  std::sort(found.begin(), found.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    if (owner(a.second) != owner(b.second)) return owner(a.second) < owner(b.second);
    return a.second < b.second;
  });
}

std::vector<std::size_t> NeighborTable::atoms_short_of_request(const std::vector<std::vector<int>>& lists) const {
  std::vector<std::size_t> short_atoms;
  for (std::size_t i = 0; i < nlocal_; ++i) {
    const std::size_t have = lists.empty() || lists[i].empty() ? of(i).size() : lists[i].size();
    if (static_cast<int>(have) < request_.min_neighbors) short_atoms.push_back(i);
  }
  return short_atoms;
}

void NeighborTable::widen(const AtomFrame& frame, const std::vector<std::size_t>& short_atoms,
                          std::vector<std::vector<int>>& lists, double cutoff) {
  md::Atoms atoms = owned_atoms(frame, cutoff);
  // The wider search's ghosts join the table's entries.
  const int base = static_cast<int>(points_.size());
  points_.insert(points_.end(), atoms.x.begin() + static_cast<std::ptrdiff_t>(nlocal_), atoms.x.end());
  ghost_owner_.insert(ghost_owner_.end(), atoms.ghost_owner.begin(), atoms.ghost_owner.end());
  // Search points: the short atoms first (the ones listed), then every other atom and ghost.
  std::vector<bool> is_short(nlocal_, false);
  for (std::size_t i : short_atoms) is_short[i] = true;
  std::vector<Vec3> search;
  std::vector<int> entry;  // search point → table entry
  for (std::size_t i : short_atoms) {
    search.push_back(atoms.x[i]);
    entry.push_back(static_cast<int>(i));
  }
  for (std::size_t k = 0; k < atoms.size(); ++k) {
    if (k < nlocal_ && is_short[k]) continue;
    search.push_back(atoms.x[k]);
    entry.push_back(k < nlocal_ ? static_cast<int>(k) : base + static_cast<int>(k - nlocal_));
  }
  geometry::NeighborList list;
  geometry::build_neighbor_list(search, short_atoms.size(), cutoff, /*half=*/false, list);
  for (std::size_t s = 0; s < short_atoms.size(); ++s) {
    const std::size_t i = short_atoms[s];
    std::vector<std::pair<double, int>> found;
    for (std::int64_t k = list.offset[s]; k < list.offset[s + 1]; ++k) {
      const int j = entry[static_cast<std::size_t>(list.neighbors[static_cast<std::size_t>(k)])];
      found.emplace_back(delta(i, j).squaredNorm(), j);
    }
    sort_nearest(found);
    lists[i].clear();
    for (const auto& f : found) lists[i].push_back(f.second);
    reach_[i] = cutoff;
  }
}

void NeighborTable::require(const NeighborRequest& r, std::string_view analysis) const {
  if (request_.cutoff < r.cutoff || request_.min_neighbors < r.min_neighbors)
    throw std::invalid_argument(fmt::format("{} needs a neighbour table with cutoff >= {} and >= {} neighbours; this "
                                            "one has cutoff {} and {}", analysis, r.cutoff, r.min_neighbors,
                                            request_.cutoff, request_.min_neighbors));
}

std::size_t NeighborTable::memory_bytes() const {
  return points_.capacity() * sizeof(Vec3) + ghost_owner_.capacity() * sizeof(int) +
         offset_.capacity() * sizeof(std::int64_t) + neighbors_.capacity() * sizeof(int) +
         reach_.capacity() * sizeof(double);
}

}  // namespace shockfield::analysis::atoms
