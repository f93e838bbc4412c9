// The one-rank Communicator of a build without MPI (communicator.hpp): every collective is a copy,
// and a Cartesian grid is 1 × 1 × 1 whose periodic axes are their own neighbours.
#include <stdexcept>

#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

struct Communicator::Handle {
  std::array<bool, 3> periodic{false, false, false};
};

std::string mpi_build_text() { return "not built"; }

Environment::Environment(int&, char**&) {}
Environment::~Environment() = default;

Communicator Communicator::world() { return Communicator(std::make_shared<const Handle>()); }
int Communicator::rank() const { return 0; }
int Communicator::size() const { return 1; }
void Communicator::broadcast(void*, std::size_t, int) const {}
int Communicator::min(int value) const { return value; }

void Communicator::send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv,
                                int source) const {
  if (dest == 0 && source == 0) recv = send;  // a periodic axis of one rank: its own neighbour
}

std::vector<double> Communicator::gather(const std::vector<double>& local, int) const { return local; }
std::vector<double> Communicator::all_gather(const std::vector<double>& local) const { return local; }
std::vector<double> Communicator::scatter(const std::vector<std::vector<double>>& pieces, std::size_t, int) const {
  return pieces.at(0);
}

Communicator Communicator::cartesian(const std::array<int, 3>& dims, const std::array<bool, 3>& periodic) const {
  if (dims != std::array<int, 3>{1, 1, 1})
    throw std::logic_error("a build without MPI has one rank: its rank grid is 1 x 1 x 1");
  return Communicator(std::make_shared<const Handle>(Handle{periodic}));
}

std::array<int, 3> Communicator::coordinates() const { return {0, 0, 0}; }
std::array<int, 2> Communicator::neighbours(int axis) const {
  const int n = handle_->periodic[axis] ? 0 : no_rank;
  return {n, n};
}

}  // namespace shockfield::parallel
