#pragma once
// The BGK DBM on a rank grid (docs/parallel.md): each rank steps its block of the lattice with
// its own two ghost layers, those on a cut face filled by the halo exchange (parallel/), those on
// the domain's edge by the case's boundaries exactly as in a one-rank run, so that every cell's
// update sees the same numbers and the run gives the same bits on any rank grid. Rank 0 keeps the
// whole lattice for what the serial code does with it — the initial state, checkpoints, every
// output and the health check's message — and drives the other ranks by commands: it broadcasts
// one (scatter, step, gather, quit) and then takes part in it, while the others wait in serve().
#include <memory>

#include "shockfield/dbm/case_file.hpp"
#include "shockfield/parallel/halo_exchange.hpp"
#include "shockfield/parallel/rank_grid.hpp"

namespace shockfield::dbm {

class Decomposition {
 public:
  /// Collective over the world: the rank grid `rank_grid` ("PxQ", or empty: the one with the
  /// least halo) over c's lattice. InputError on every rank (the same one) when the ranks do not
  /// fit the lattice or the case uses what is not decomposed yet (spectral convection,
  /// [reaction], the GLS model). The block's arrays are allocated by the first scatter.
  Decomposition(const DbmCase& c, const std::string& rank_grid);
  /// Rank 0: tells the other ranks to leave serve() (unless quit() already did).
  ~Decomposition();
  Decomposition(const Decomposition&) = delete;
  Decomposition& operator=(const Decomposition&) = delete;

  const parallel::RankGrid& grid() const { return grid_; }
  /// This rank's block (its Simulation, clock included).
  const Simulation& block() const { return *block_; }

  // Rank 0's commands; `whole`: rank 0's Simulation of the whole lattice.
  /// Deals whole's f and clock out to the blocks.
  void scatter(const Simulation& whole);
  /// One step of every block; false when a block's state broke down (check_state) on some rank.
  bool step();
  /// Collects the blocks' f into whole (interior cells; whole's ghosts are left as they are).
  void gather(Simulation& whole);
  void quit();

  /// The other ranks: carries out rank 0's commands until quit.
  void serve();

 private:
  enum class Command : int { scatter, step, gather, quit };
  void send(Command command);
  // The collective part of a command on every rank (`whole` on rank 0 only).
  bool perform(Command command, const Simulation* source, Simulation* target);

  parallel::RankGrid grid_;
  parallel::GridLayout whole_layout_, block_layout_;
  std::unique_ptr<Simulation> block_;
  std::unique_ptr<parallel::HaloExchange> halo_;
  bool quit_sent_ = false;
};

}  // namespace shockfield::dbm
