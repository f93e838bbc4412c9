#pragma once
// MD on a Cartesian rank grid (docs/parallel.md, "MD on the rank grid"): each rank owns the atoms
// in its piece of an orthogonal box and holds ghost copies of the atoms within the interaction
// range (cutoff + skin) of it, made and kept up to date by the particle exchange
// (parallel/particle_exchange.hpp) — the same swaps that make the periodic images of a one-rank
// run (md/ghosts.hpp), here crossing ranks. A Simulation with a Decomposition migrates and
// re-ghosts its atoms at each neighbour-list rebuild, decides rebuilds over all ranks, and adds
// thermo sums in rank order; its atoms reach the other ranks through Atoms::ranks.
#include <memory>
#include <vector>

#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/parallel/particle_exchange.hpp"
#include "shockfield/parallel/rank_grid.hpp"

namespace shockfield::md {

/// The rank grid for `ranks` ranks over an orthogonal `box` whose pieces must be at least
/// `ghost_cutoff` long along every cut axis (`given`: the user's --rank-grid, or all zero to
/// choose the one with the least halo). InputError naming the box, the cutoff and the most ranks
/// that fit, or the axis the given grid cuts too finely; also for a triclinic box or a
/// shrink-wrapped axis (not decomposed yet).
parallel::Dims3 md_rank_grid(const geometry::Box& box, double ghost_cutoff, int ranks, const parallel::Dims3& given);

class Decomposition;

/// Every rank's owned atoms on rank 0, in id order, with the types' masses and names (empty on
/// the other ranks): what the serial output and checkpoint code read. Collective.
Atoms gather_atoms(const Decomposition& domain, const Atoms& atoms);
/// `values` (one per owned atom, e.g. atoms.f) of every rank on rank 0, in the id order of
/// gather_atoms (empty on the other ranks). Collective.
std::vector<Vec3> gather_by_id(const Decomposition& domain, const Atoms& atoms, const std::vector<Vec3>& values);
/// Keeps the owned atoms of a whole system (read or built the same on every rank) that lie in
/// this rank's piece: how a checkpoint of any rank count is dealt out. Not collective.
void keep_own_atoms(const Decomposition& domain, Atoms& atoms);

class Decomposition final : public AtomRanks, public std::enable_shared_from_this<Decomposition> {
 public:
  /// Collective over `world`: the Cartesian communicator of `dims` (md_rank_grid).
  Decomposition(const parallel::Communicator& world, const parallel::Dims3& dims, const geometry::Box& box,
                double ghost_cutoff);

  const parallel::Communicator& comm() const { return exchange_.comm(); }
  /// Ranks along x, y and z.
  const parallel::Dims3& dims() const { return dims_; }
  const parallel::ParticleExchange& exchange() const { return exchange_; }
  /// Whether `x` lies in this rank's piece (for dealing out the atoms of a whole system).
  bool owns(const Vec3& x) const;

  /// Wraps the owned atoms into the box, migrates them to their ranks and rebuilds the ghosts
  /// (atoms.ranks is set to this). Collective.
  void rebuild(Atoms& atoms, const geometry::Box& box, double ghost_cutoff);
  /// True on every rank when `flag` is true on any. Collective.
  bool any(bool flag) const;
  /// The largest value over ranks. Collective.
  double max(double value) const;
  /// The atoms of every rank (exact). Collective.
  long long total_atoms(const Atoms& atoms) const { return exchange_.total(atoms.nlocal); }
  /// std::logic_error unless every rank's atoms add up to the count of the first call (no atom
  /// lost or owned twice; Simulation::advance checks every step in a debug build). Collective.
  void check_total(const Atoms& atoms);

  void reverse_sum(double* values, int width) const override;
  void forward_copy(double* values, int width) const override;
  void update_ghost_positions(Atoms& atoms, const geometry::Box& box) const override;
  std::vector<double> sum(const std::vector<double>& partials) const override;

  /// Wall seconds spent in the exchange on this rank (ghost values, positions, migration and
  /// ghost rebuilds), for the performance summary.
  mutable double halo_seconds = 0;

 private:
  parallel::Dims3 dims_;
  parallel::ParticleExchange exchange_;
  std::vector<parallel::GhostSwap> swaps_;
  long long first_total_ = -1;
};

}  // namespace shockfield::md
