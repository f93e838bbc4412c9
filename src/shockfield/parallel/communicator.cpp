#include "shockfield/parallel/communicator.hpp"

#include "shockfield/parallel/communicator_backend.hpp"

namespace shockfield::parallel {

Communicator Communicator::world() { return Communicator(world_backend()); }
Communicator Communicator::single() { return Communicator(single_rank_backend()); }
int Communicator::rank() const { return backend_->rank(); }
int Communicator::size() const { return backend_->size(); }
void Communicator::broadcast(void* data, std::size_t bytes, int root) const { backend_->broadcast(data, bytes, root); }
int Communicator::min(int value) const { return backend_->min(value); }
void Communicator::send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv,
                                int source) const {
  backend_->send_receive(send, dest, recv, source);
}
std::vector<double> Communicator::gather(const std::vector<double>& local, int root) const {
  return backend_->gather(local, root);
}
std::vector<double> Communicator::all_gather(const std::vector<double>& local) const {
  return backend_->all_gather(local);
}
std::vector<double> Communicator::scatter(const std::vector<std::vector<double>>& pieces, std::size_t count,
                                          int root) const {
  return backend_->scatter(pieces, count, root);
}
void Communicator::abort(int code) const { backend_->abort(code); }
Communicator Communicator::cartesian(const std::array<int, 3>& dims, const std::array<bool, 3>& periodic) const {
  return Communicator(backend_->cartesian(dims, periodic));
}
std::array<int, 3> Communicator::coordinates() const { return backend_->coordinates(); }
std::array<int, 2> Communicator::neighbours(int axis) const { return backend_->neighbours(axis); }

}  // namespace shockfield::parallel
