// MPI's Communicator backend (communicator_backend.hpp), built with SHOCKFIELD_MPI and used when
// mpirun started the program. Counts travel as int (MPI's count type): a rank's piece of a
// gather is at most 2³¹ − 1 doubles (16 GiB).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "shockfield/parallel/communicator_backend.hpp"

namespace shockfield::parallel {
namespace {

bool launched_by_mpirun() { return launcher_world_size() > 0; }

bool mpi_running() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

int count_of(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("an MPI message of more than 2^31 - 1 doubles");
  return static_cast<int>(n);
}
int rank_or_null(int r) { return r == no_rank ? MPI_PROC_NULL : r; }
int null_or_rank(int r) { return r == MPI_PROC_NULL ? no_rank : r; }

// Displacements of a variable-length collective from each rank's count.
std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> d(counts.size(), 0);
  std::exclusive_scan(counts.begin(), counts.end(), d.begin(), 0);
  return d;
}

class MpiRanks final : public Communicator::Backend {
 public:
  MpiRanks(MPI_Comm comm, bool owned) : comm_(comm), owned_(owned) {}
  ~MpiRanks() override {
    if (owned_ && mpi_running()) MPI_Comm_free(&comm_);
  }

  int rank() const override {
    int r = 0;
    MPI_Comm_rank(comm_, &r);
    return r;
  }
  int size() const override {
    int s = 1;
    MPI_Comm_size(comm_, &s);
    return s;
  }
  void broadcast(void* data, std::size_t bytes, int root) const override {
    MPI_Bcast(data, count_of(bytes), MPI_BYTE, root, comm_);
  }
  int min(int value) const override {
    int result = value;
    MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MIN, comm_);
    return result;
  }
  void send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv, int source) const override {
    MPI_Sendrecv(send.data(), count_of(send.size()), MPI_DOUBLE, rank_or_null(dest), 0, recv.data(),
                 count_of(recv.size()), MPI_DOUBLE, rank_or_null(source), 0, comm_, MPI_STATUS_IGNORE);
  }
  std::vector<double> gather(const std::vector<double>& local, int root) const override {
    const int n = count_of(local.size());
    std::vector<int> counts(static_cast<std::size_t>(size()));
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_);
    const std::vector<int> offsets = displacements(counts);
    std::vector<double> all(rank() == root ? static_cast<std::size_t>(offsets.back()) + counts.back() : 0);
    MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, root, comm_);
    return all;
  }
  std::vector<double> all_gather(const std::vector<double>& local) const override {
    const int n = count_of(local.size());
    std::vector<int> counts(static_cast<std::size_t>(size()));
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
    const std::vector<int> offsets = displacements(counts);
    std::vector<double> all(static_cast<std::size_t>(offsets.back()) + counts.back());
    MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, comm_);
    return all;
  }
  std::vector<double> scatter(const std::vector<std::vector<double>>& pieces, std::size_t count,
                              int root) const override {
    std::vector<int> counts;
    std::vector<double> packed;
    if (rank() == root) {
      for (const auto& p : pieces) {
        counts.push_back(count_of(p.size()));
        packed.insert(packed.end(), p.begin(), p.end());
      }
    }
    const std::vector<int> offsets = rank() == root ? displacements(counts) : std::vector<int>{};
    std::vector<double> mine(count);
    MPI_Scatterv(packed.data(), counts.data(), offsets.data(), MPI_DOUBLE, mine.data(), count_of(count), MPI_DOUBLE,
                 root, comm_);
    return mine;
  }
  void abort(int code) const override { MPI_Abort(comm_, code); }
  std::shared_ptr<const Backend> cartesian(const std::array<int, 3>& dims,
                                           const std::array<bool, 3>& periodic) const override {
    const std::array<int, 3> periods{periodic[0], periodic[1], periodic[2]};
    MPI_Comm grid = MPI_COMM_NULL;
    MPI_Cart_create(comm_, 3, dims.data(), periods.data(), /*reorder=*/0, &grid);
    return std::make_shared<MpiRanks>(grid, true);
  }
  std::array<int, 3> coordinates() const override {
    std::array<int, 3> c{0, 0, 0};
    MPI_Cart_coords(comm_, rank(), 3, c.data());
    return c;
  }
  std::array<int, 2> neighbours(int axis) const override {
    int low = MPI_PROC_NULL, high = MPI_PROC_NULL;
    MPI_Cart_shift(comm_, axis, 1, &low, &high);
    return {null_or_rank(low), null_or_rank(high)};
  }

 private:
  mutable MPI_Comm comm_;
  bool owned_;  // a communicator this program created, freed with its backend
};

}  // namespace

std::string mpi_build_text() {
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(version, &length);  // callable before MPI_Init
  std::string text(version, static_cast<std::size_t>(length));
  return "built (" + text.substr(0, text.find_first_of(",\n")) + ")";
}

Environment::Environment(int& argc, char**& argv) {
  if (!launched_by_mpirun()) return;
  int provided = 0, rank = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0 && (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)))
    MPI_Abort(MPI_COMM_WORLD, 1);
}
Environment::~Environment() {
  if (mpi_running()) MPI_Finalize();
}

std::shared_ptr<const Communicator::Backend> world_backend() {
  if (!launched_by_mpirun()) return single_rank_backend();
  if (!mpi_running()) {  // a library user under mpirun that made no Environment: finalized at exit
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    std::atexit([] {
      if (mpi_running()) MPI_Finalize();
    });
  }
  static const auto world = std::make_shared<MpiRanks>(MPI_COMM_WORLD, false);
  return world;
}

}  // namespace shockfield::parallel
