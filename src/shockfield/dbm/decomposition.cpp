#include "shockfield/dbm/decomposition.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/parallel/block_transfer.hpp"

namespace shockfield::dbm {
namespace {

const parallel::Communicator& world() {
  static const parallel::Communicator w = parallel::Communicator::world();
  return w;
}

parallel::Cells3 cells_of(const Lattice& l) { return {l.nx, l.ny, 1}; }

// What the decomposition does not carry yet (docs/parallel.md, "Not done").
void check_decomposable(const DbmCase& c) {
  const char* what = c.bgk.spectral_convection ? "spectral (FFT) convection"
                     : c.reaction                ? "[reaction] (the reactive DBM)"
                     : c.gls                     ? "[model] kind = \"gls\" (the liquid-vapour model)"
                                                 : nullptr;
  if (what)
    throw InputError(fmt::format("{} runs on one rank only so far: run it without mpirun (or with -np 1 "
                                 "and no --rank-grid); docs/parallel.md lists what is decomposed",
                                 what));
}

parallel::Dims3 dims_for(const DbmCase& c, const std::string& rank_grid) {
  check_decomposable(c);
  if (rank_grid.empty()) return parallel::choose_rank_grid(cells_of(c.lattice), world().size(), Lattice::ghosts);
  return parallel::parse_rank_grid(rank_grid);  // checked against the rank count by RankGrid
}

parallel::GridLayout layout_of(const Lattice& l, int components) {
  return {{l.nx, l.ny, 1}, {Lattice::ghosts, Lattice::ghosts, 0}, components, l.cells()};
}

Lattice block_lattice(const Lattice& whole, const parallel::Block& b) {
  Lattice l = whole;
  l.nx = static_cast<int>(b.count[0]);
  l.ny = static_cast<int>(b.count[1]);
  return l;
}

}  // namespace

Decomposition::Decomposition(const DbmCase& c, const std::string& rank_grid)
    : grid_(world(), dims_for(c, rank_grid),
            {c.boundaries.side[0].kind == BoundaryKind::periodic, c.boundaries.side[2].kind == BoundaryKind::periodic,
             false},
            cells_of(c.lattice), Lattice::ghosts),
      whole_layout_(layout_of(c.lattice, c.model.size())) {
  const Lattice local = block_lattice(c.lattice, grid_.block());
  block_layout_ = layout_of(local, c.model.size());
  block_ = std::make_unique<Simulation>(c.model, local, c.boundaries, c.bgk, false);
  // Only cut axes go through the halo: an uncut periodic axis wraps in the boundaries' code, as
  // in a one-rank run (which also serves a lattice one cell high).
  const parallel::Dims3& dims = grid_.dims();
  halo_ = std::make_unique<parallel::HaloExchange>(grid_.comm(), block_layout_,
                                                   std::array<bool, 3>{dims[0] > 1, dims[1] > 1, false});
  block_->set_halo(halo_.get());
}

Decomposition::~Decomposition() {
  if (grid_.comm().is_root() && !quit_sent_) quit();
}

void Decomposition::send(Command command) {
  int code = static_cast<int>(command);
  grid_.comm().broadcast(&code, sizeof code);
}

bool Decomposition::perform(Command command, const Simulation* source, Simulation* target) {
  const parallel::Communicator& comm = grid_.comm();
  switch (command) {
    case Command::scatter: {
      block_->allocate();
      parallel::scatter_blocks(grid_, whole_layout_, source ? source->f().data() : nullptr, block_layout_,
                               block_->f().data());
      double time = source ? source->time() : 0.0;
      long long steps = source ? source->steps() : 0;
      comm.broadcast(&time, sizeof time);
      comm.broadcast(&steps, sizeof steps);
      block_->restore_clock(time, steps);
      return true;
    }
    case Command::step: {
      block_->step();
      int healthy = 1;
      try {
        block_->check_state();
      } catch (const RunError&) {
        healthy = 0;  // rank 0 names the cell from the whole lattice (the one-rank message)
      }
      return comm.min(healthy) == 1;
    }
    case Command::gather:
      parallel::gather_blocks(grid_, block_layout_, block_->f().data(), whole_layout_,
                              target ? target->f().data() : nullptr);
      return true;
    case Command::quit:
      return false;
  }
  return false;
}

void Decomposition::scatter(const Simulation& whole) {
  send(Command::scatter);
  perform(Command::scatter, &whole, nullptr);
}

bool Decomposition::step() {
  send(Command::step);
  return perform(Command::step, nullptr, nullptr);
}

void Decomposition::gather(Simulation& whole) {
  send(Command::gather);
  perform(Command::gather, nullptr, &whole);
}

void Decomposition::quit() {
  send(Command::quit);
  quit_sent_ = true;
}

void Decomposition::serve() {
  for (;;) {
    int code = 0;
    grid_.comm().broadcast(&code, sizeof code);
    const auto command = static_cast<Command>(code);
    if (command == Command::quit) return;
    perform(command, nullptr, nullptr);
  }
}

}  // namespace shockfield::dbm
