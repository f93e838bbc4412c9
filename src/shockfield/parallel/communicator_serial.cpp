// A build without MPI (communicator.hpp): one rank, always.
#include <cstdio>
#include <cstdlib>

#include "shockfield/parallel/communicator_backend.hpp"

namespace shockfield::parallel {

std::string mpi_build_text() { return "not built"; }
Environment::Environment(int&, char**&) {
  // Under mpirun -np N every copy of this build would run the whole case into the same folder.
  if (launcher_world_size() > 1) {
    std::fprintf(stderr, "error: this shockfield was built without MPI (SHOCKFIELD_MPI=OFF, docs/parallel.md): "
                         "under mpirun -np %d every rank would run the whole case; run it without mpirun\n",
                 launcher_world_size());
    std::exit(2);
  }
}
Environment::~Environment() = default;
std::shared_ptr<const Communicator::Backend> world_backend() { return single_rank_backend(); }

}  // namespace shockfield::parallel
