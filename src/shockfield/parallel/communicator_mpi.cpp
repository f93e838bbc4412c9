// The MPI Communicator (communicator.hpp), built with SHOCKFIELD_MPI. Counts travel as int (MPI's
// count type): a rank's piece of a gather is at most 2³¹ − 1 doubles (16 GiB).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

struct Communicator::Handle {
  MPI_Comm comm = MPI_COMM_WORLD;
  bool owned = false;  // a communicator this program created (freed with the last copy)
  ~Handle() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (owned && !finalized) MPI_Comm_free(&comm);
  }
};

namespace {

int count_of(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("an MPI message of more than 2^31 - 1 doubles");
  return static_cast<int>(n);
}
int rank_or_null(int r) { return r == no_rank ? MPI_PROC_NULL : r; }
int null_or_rank(int r) { return r == MPI_PROC_NULL ? no_rank : r; }

// Counts and displacements of a variable-length collective from each rank's length.
std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> d(counts.size(), 0);
  std::exclusive_scan(counts.begin(), counts.end(), d.begin(), 0);
  return d;
}

}  // namespace

std::string mpi_build_text() {
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(version, &length);
  std::string text(version, static_cast<std::size_t>(length));
  text = text.substr(0, text.find_first_of(",\n"));
  return "built (" + text + ")";
}

// MPI started by a library user that made no Environment (a test, the Python module): finalized at exit.
void initialize_for_library() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  std::atexit([] {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  });
}

Environment::Environment(int& argc, char**& argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr))
      MPI_Abort(MPI_COMM_WORLD, 1);
  }
}
Environment::~Environment() { MPI_Finalize(); }

Communicator Communicator::world() {
  initialize_for_library();
  static const auto world = std::make_shared<const Handle>();
  return Communicator(world);
}

int Communicator::rank() const {
  int r = 0;
  MPI_Comm_rank(handle_->comm, &r);
  return r;
}
int Communicator::size() const {
  int s = 1;
  MPI_Comm_size(handle_->comm, &s);
  return s;
}

void Communicator::broadcast(void* data, std::size_t bytes, int root) const {
  MPI_Bcast(data, count_of(bytes), MPI_BYTE, root, handle_->comm);
}

int Communicator::min(int value) const {
  int result = value;
  MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MIN, handle_->comm);
  return result;
}

void Communicator::send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv,
                                int source) const {
  MPI_Sendrecv(send.data(), count_of(send.size()), MPI_DOUBLE, rank_or_null(dest), 0, recv.data(),
               count_of(recv.size()), MPI_DOUBLE, rank_or_null(source), 0, handle_->comm, MPI_STATUS_IGNORE);
}

std::vector<double> Communicator::gather(const std::vector<double>& local, int root) const {
  const int n = count_of(local.size());
  std::vector<int> counts(static_cast<std::size_t>(size()));
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, handle_->comm);
  const std::vector<int> offsets = displacements(counts);
  std::vector<double> all(rank() == root ? static_cast<std::size_t>(offsets.back()) + counts.back() : 0);
  MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, root,
              handle_->comm);
  return all;
}

std::vector<double> Communicator::all_gather(const std::vector<double>& local) const {
  const int n = count_of(local.size());
  std::vector<int> counts(static_cast<std::size_t>(size()));
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, handle_->comm);
  const std::vector<int> offsets = displacements(counts);
  std::vector<double> all(static_cast<std::size_t>(offsets.back()) + counts.back());
  MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 handle_->comm);
  return all;
}

std::vector<double> Communicator::scatter(const std::vector<std::vector<double>>& pieces, std::size_t count,
                                          int root) const {
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
               root, handle_->comm);
  return mine;
}

Communicator Communicator::cartesian(const std::array<int, 3>& dims, const std::array<bool, 3>& periodic) const {
  const std::array<int, 3> periods{periodic[0], periodic[1], periodic[2]};
  auto handle = std::make_shared<Handle>();
  MPI_Cart_create(handle_->comm, 3, dims.data(), periods.data(), /*reorder=*/0, &handle->comm);
  handle->owned = true;
  return Communicator(std::move(handle));
}

std::array<int, 3> Communicator::coordinates() const {
  std::array<int, 3> c{0, 0, 0};
  MPI_Cart_coords(handle_->comm, rank(), 3, c.data());
  return c;
}

std::array<int, 2> Communicator::neighbours(int axis) const {
  int low = MPI_PROC_NULL, high = MPI_PROC_NULL;
  MPI_Cart_shift(handle_->comm, axis, 1, &low, &high);
  return {null_or_rank(low), null_or_rank(high)};
}

}  // namespace shockfield::parallel
