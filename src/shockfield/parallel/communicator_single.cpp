// One rank without MPI (communicator_backend.hpp): every collective is a copy, and a Cartesian
// grid is 1 × 1 × 1 whose periodic axes are their own neighbours.
#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "shockfield/parallel/communicator_backend.hpp"

namespace shockfield::parallel {
namespace {

class SingleRank final : public Communicator::Backend {
 public:
  explicit SingleRank(const std::array<bool, 3>& periodic = {false, false, false}) : periodic_(periodic) {}
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void broadcast(void*, std::size_t, int) const override {}
  int min(int value) const override { return value; }
  void send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv, int source) const override {
    if (dest == 0 && source == 0) recv = send;  // a periodic axis of one rank: its own neighbour
  }
  std::vector<double> gather(const std::vector<double>& local, int) const override { return local; }
  std::vector<double> all_gather(const std::vector<double>& local) const override { return local; }
  std::vector<double> scatter(const std::vector<std::vector<double>>& pieces, std::size_t, int) const override {
    return pieces.at(0);
  }
  void abort(int code) const override { std::exit(code); }
  std::shared_ptr<const Backend> cartesian(const std::array<int, 3>& dims,
                                           const std::array<bool, 3>& periodic) const override {
    if (dims != std::array<int, 3>{1, 1, 1}) throw std::logic_error("one rank: its rank grid is 1 x 1 x 1");
    return std::make_shared<SingleRank>(periodic);
  }
  std::array<int, 3> coordinates() const override { return {0, 0, 0}; }
  std::array<int, 2> neighbours(int axis) const override {
    const int n = periodic_[axis] ? 0 : no_rank;
    return {n, n};
  }

 private:
  std::array<bool, 3> periodic_;
};

}  // namespace

int launcher_world_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  return std::getenv("PMIX_RANK") || std::getenv("PMI_RANK") ? 1 : 0;
}

std::shared_ptr<const Communicator::Backend> single_rank_backend() { return std::make_shared<SingleRank>(); }

}  // namespace shockfield::parallel
