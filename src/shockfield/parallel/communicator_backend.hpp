#pragma once
// What a Communicator forwards to (communicator.hpp): one implementation per kind of group.
#include "shockfield/parallel/communicator.hpp"

namespace shockfield::parallel {

class Communicator::Backend {
 public:
  virtual ~Backend() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual void broadcast(void* data, std::size_t bytes, int root) const = 0;
  virtual int min(int value) const = 0;
  virtual void send_receive(const std::vector<double>& send, int dest, std::vector<double>& recv,
                            int source) const = 0;
  virtual std::vector<double> gather(const std::vector<double>& local, int root) const = 0;
  virtual std::vector<double> all_gather(const std::vector<double>& local) const = 0;
  virtual std::vector<double> scatter(const std::vector<std::vector<double>>& pieces, std::size_t count,
                                      int root) const = 0;
  virtual void abort(int code) const = 0;
  virtual std::shared_ptr<const Backend> cartesian(const std::array<int, 3>& dims,
                                                   const std::array<bool, 3>& periodic) const = 0;
  virtual std::array<int, 3> coordinates() const = 0;
  virtual std::array<int, 2> neighbours(int axis) const = 0;
};

/// The rank count mpirun (Open MPI, or a PMI launcher: MPICH's Hydra, Slurm) left in this
/// process's environment, or 0 when it was not started by one (communicator_single.cpp).
int launcher_world_size();

/// One rank, no MPI (communicator_single.cpp).
std::shared_ptr<const Communicator::Backend> single_rank_backend();
/// The world of this run: MPI's under mpirun in an MPI build, else single_rank_backend()
/// (communicator_mpi.cpp, communicator_serial.cpp).
std::shared_ptr<const Communicator::Backend> world_backend();

}  // namespace shockfield::parallel
