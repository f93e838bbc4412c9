#pragma once
// The one place shockfield talks to MPI (docs/parallel.md). A Communicator is a group of ranks
// (the world, or a Cartesian rank grid made from it) with the few operations the decomposition
// needs, carried out by a backend (communicator_backend.hpp): MPI's (communicator_mpi.cpp, in a
// build with SHOCKFIELD_MPI, for a program started by mpirun) or one rank's (communicator_single.cpp:
// a build without MPI, or a program started without mpirun, which then never starts MPI — its
// start-up costs about a second). The code above this header has no #ifdef and sees no MPI type.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace shockfield::parallel {

/// The rank of no neighbour (MPI_PROC_NULL): the domain edge of a non-periodic axis.
inline constexpr int no_rank = -1;

/// "built (Open MPI v4.1.4, ...)" or "not built": for `shockfield --version`.
std::string mpi_build_text();

/// MPI for the life of the program when started by mpirun (MPI_Init_thread with
/// MPI_THREAD_FUNNELED: OpenMP threads compute, the main thread communicates); nothing otherwise.
/// Ranks other than 0 print nothing: their stdout and stderr go to /dev/null, so each message
/// appears once.
class Environment {
 public:
  Environment(int& argc, char**& argv);
  ~Environment();
  Environment(const Environment&) = delete;
  Environment& operator=(const Environment&) = delete;
};

class Communicator {
 public:
  /// Every rank of the run (MPI_COMM_WORLD); one rank in the serial build.
  static Communicator world();
  /// One rank without MPI, in any build and under mpirun too: a method's serial path.
  static Communicator single();

  int rank() const;
  int size() const;
  bool is_root() const { return rank() == 0; }

  /// Copies `bytes` bytes at `data` from `root` to every rank.
  void broadcast(void* data, std::size_t bytes, int root = 0) const;
  /// The smallest `value` over all ranks.
  int min(int value) const;
  /// Sends `send` to `dest` and receives `recv` from `source` (either may be no_rank: nothing
  /// sent or received); the buffers' sizes must match their partner's.
  void send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv, int source) const;
  /// Every rank's `local` (any lengths) concatenated in rank order, on `root` (empty elsewhere).
  std::vector<double> gather(const std::vector<double>& local, int root = 0) const;
  /// Every rank's `local` (any lengths) concatenated in rank order, on every rank.
  std::vector<double> all_gather(const std::vector<double>& local) const;
  /// Rank r receives pieces[r] of `root` (pieces ignored elsewhere; `count` is this rank's length).
  std::vector<double> scatter(const std::vector<std::vector<double>>& pieces, std::size_t count, int root = 0) const;

  /// Ends every rank of the run with exit code `code` (MPI_Abort): for a failure on one rank that
  /// the others, waiting in a collective, would never learn of.
  void abort(int code) const;

  /// A Cartesian grid of dims[0] × dims[1] × dims[2] ranks (MPI_Cart_create, no reordering, so
  /// the grid's rank r is the world's rank r); `periodic` per axis. Collective.
  Communicator cartesian(const std::array<int, 3>& dims, const std::array<bool, 3>& periodic) const;
  /// Of a Cartesian communicator: this rank's coordinates, and the ranks next to it along `axis`
  /// on the low and high side (no_rank at a non-periodic edge).
  std::array<int, 3> coordinates() const;
  std::array<int, 2> neighbours(int axis) const;

  class Backend;  // communicator_backend.hpp
  explicit Communicator(std::shared_ptr<const Backend> backend) : backend_(std::move(backend)) {}

 private:
  std::shared_ptr<const Backend> backend_;
};

}  // namespace shockfield::parallel
