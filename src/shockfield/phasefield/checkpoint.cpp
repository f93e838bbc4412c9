#include "shockfield/phasefield/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::phasefield {

void write_checkpoint(const std::filesystem::path& file, const Solver& solver, const OutputCounters& counters) {
  io::CheckpointWriter h5(file, "phasefield", kCheckpointFormat);
  h5.set_count("step", solver.steps());
  h5.set_attribute("time", solver.time());
  h5.set_count("series", counters.series);
  h5.set_count("frames", counters.frames);
  const auto& n = solver.grid().n;
  h5.set_count("dim", solver.grid().dim);
  h5.set_attribute("dx", solver.grid().dx);
  h5.write("xi", "1", solver.field(), {static_cast<hsize_t>(n[2]), static_cast<hsize_t>(n[1]), static_cast<hsize_t>(n[0])});
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Solver& solver) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string name = file.string();
  checkpoint.require("phasefield", kCheckpointFormat);
  std::vector<double> xi = h5.read_doubles("xi");
  if (xi.size() != solver.field().size())
    throw InputError(fmt::format("{}: dataset 'xi' has {} values, the case's grid has {} nodes", name, xi.size(),
                                 solver.field().size()));
  solver.field() = std::move(xi);
  solver.restore_clock(h5.attribute("time"), checkpoint.count("step"));
  return {checkpoint.count("series"), checkpoint.count("frames")};
}

}  // namespace shockfield::phasefield
