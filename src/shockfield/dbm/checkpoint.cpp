#include "shockfield/dbm/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::dbm {

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters,
                      const std::vector<double>* reactant) {
  io::CheckpointWriter h5(file, "dbm", kCheckpointFormat);
  h5.set_count("step", sim.steps());
  h5.set_attribute("time", sim.time());
  h5.set_count("series", counters.series);
  h5.set_count("profiles", counters.profiles);
  h5.set_count("fields", counters.fields);
  // The lattice (lattice.hpp): f_k on (ny + 2g) × (nx + 2g) cells, g ghost layers on every side,
  // cell (i, j) of the interior at [k][j + g][i + g]; model units throughout.
  const Lattice& lattice = sim.lattice();
  h5.set_count("nx", lattice.nx);
  h5.set_count("ny", lattice.ny);
  h5.set_count("ghosts", Lattice::ghosts);
  h5.set_attribute("dx", lattice.dx);
  h5.set_attribute("dy", lattice.dy);
  h5.set_attribute("b", sim.b());
  const VelocityModel& model = sim.model();
  h5.set_attribute("velocity_model", model.name);
  h5.write("velocity_x", "1", model.vx);
  h5.write("velocity_y", "1", model.vy);
  h5.write("eta", "1", model.eta);
  const auto rows = static_cast<hsize_t>(lattice.ny + 2 * Lattice::ghosts);
  const auto columns = static_cast<hsize_t>(lattice.stride());
  h5.write("f", "1", sim.f(), {static_cast<hsize_t>(model.size()), rows, columns});
  if (reactant) h5.write("reactant", "1", *reactant, {rows, columns});
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, std::vector<double>* reactant) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string name = file.string();
  checkpoint.require("dbm", kCheckpointFormat);
  std::vector<double> f = h5.read_doubles("f");
  if (f.size() != sim.f().size())
    throw InputError(fmt::format("{}: dataset 'f' has {} values, the case needs {} (a different grid or velocity model)",
                                 name, f.size(), sim.f().size()));
  sim.f() = std::move(f);
  if (reactant) {
    if (!h5.has("reactant"))
      throw InputError(fmt::format("{}: no dataset 'reactant': the checkpoint was written by a case without [reaction]", name));
    std::vector<double> phi = h5.read_doubles("reactant");
    if (phi.size() != reactant->size())
      throw InputError(fmt::format("{}: dataset 'reactant' has {} values, the [reaction] case needs {}", name,
                                   phi.size(), reactant->size()));
    *reactant = std::move(phi);
  }
  sim.restore_clock(h5.attribute("time"), checkpoint.count("step"));
  return {checkpoint.count("series"), checkpoint.count("profiles"),
          checkpoint.count("fields")};
}

}  // namespace shockfield::dbm
