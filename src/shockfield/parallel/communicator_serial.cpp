// A build without MPI (communicator.hpp): one rank, always.
#include "shockfield/parallel/communicator_backend.hpp"

namespace shockfield::parallel {

std::string mpi_build_text() { return "not built"; }
Environment::Environment(int&, char**&) {}
Environment::~Environment() = default;
std::shared_ptr<const Communicator::Backend> world_backend() { return single_rank_backend(); }

}  // namespace shockfield::parallel
