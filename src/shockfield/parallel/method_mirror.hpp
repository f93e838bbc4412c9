#pragma once
// A method decomposed over MPI ranks that runs the run driver on rank 0 only (docs/parallel.md):
// rank 0's method announces each of its collective calls (a step, a thermo row, a checkpoint's
// gather, ...) before making it, and the other ranks, serving, make the same call on their own
// copy of the method — so every rank goes through the same collectives in the same order without
// a second copy of the driver. Used by MD; the DBM predates it and has its own commands.
#include <string>

#include "shockfield/core/method.hpp"
#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

/// The collective calls of a Method that rank 0 announces (and `quit`: the run is over).
enum class MethodCall : int {
  start,
  resume,
  advance,
  check_health,
  write_outputs,
  write_checkpoint,
  write_final_outputs,
  thermo_values,
  results,
  quit
};

class MethodMirror {
 public:
  explicit MethodMirror(Communicator comm) : comm_(std::move(comm)) {}
  /// Rank 0 announces its next collective call (no-op elsewhere; `quit` once).
  void announce(MethodCall call) const;
  /// Rank 0: the run's checkpoint file, which the serving ranks read on `resume`.
  void announce_resume(const std::string& checkpoint) const;
  /// Ranks other than 0: make the calls rank 0 announces on `method` until it announces quit. A
  /// RunError of a call is rank 0's too (it diagnoses it); anything else of this rank alone
  /// (out of memory) ends every rank (MPI_Abort, exit 3) rather than leaving rank 0 waiting.
  void serve(Method& method) const;
  bool leads() const { return comm_.is_root(); }

 private:
  Communicator comm_;
  mutable bool quit_sent_ = false;
};

}  // namespace shockfield::parallel
