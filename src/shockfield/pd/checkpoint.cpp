#include "shockfield/pd/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::pd {
namespace {


std::vector<double> flatten(const std::vector<Vec3>& a) {
  std::vector<double> out;
  out.reserve(3 * a.size());
  for (const Vec3& x : a) out.insert(out.end(), {x[0], x[1], x[2]});
  return out;
}

std::vector<Vec3> unflatten(const std::vector<double>& d, std::size_t n, const std::string& name,
                            const std::string& file) {
  if (d.size() != 3 * n)
    throw InputError(fmt::format("{}: dataset '{}' has {} values, the case has {} points", file, name, d.size(), n));
  std::vector<Vec3> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = Vec3(&d[3 * i]);
  return out;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const ModelState& model_state,
                      const OutputCounters& counters) {
  io::CheckpointWriter h5(file, "pd", kCheckpointFormat);
  const hsize_t n = sim.cloud().size();
  h5.set_count("step", sim.step_count());
  h5.set_attribute("time", sim.time());
  h5.set_count("dim", sim.cloud().dim);
  h5.set_count("series", counters.series);
  h5.set_count("profiles", counters.profiles);
  h5.write("position", "m", flatten(sim.positions()), {n, 3});
  h5.write("velocity", "m/s", flatten(sim.velocities()), {n, 3});
  h5.write("force_density", "N/m3", flatten(sim.force_density()), {n, 3});
  // The force model's own state, one dataset per quantity (docs/checkpoints.md).
  for (const ModelStateArray& a : model_state) {
    std::vector<hsize_t> shape{a.rows};
    shape.insert(shape.end(), a.shape.begin(), a.shape.end());
    if (a.integer)
      h5.write(a.name, a.units, a.counts, shape);
    else
      h5.write(a.name, a.units, a.reals, shape);
  }
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, ModelState& model_state) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string f = file.string();
  checkpoint.require("pd", kCheckpointFormat);
  const std::size_t n = sim.cloud().size();
  sim.restore(unflatten(h5.read_doubles("position"), n, "position", f),
              unflatten(h5.read_doubles("velocity"), n, "velocity", f),
              unflatten(h5.read_doubles("force_density"), n, "force_density", f),
              checkpoint.count("step"), h5.attribute("time"));
  model_state.clear();
  for (const std::string& name : h5.dataset_names()) {
    if (name == "position" || name == "velocity" || name == "force_density") continue;
    const std::vector<hsize_t> dims = h5.shape(name);
    ModelStateArray a{name, h5.units(name), dims.empty() ? 0 : static_cast<std::size_t>(dims[0]), {},
                      h5.is_integer(name), {}, {}};
    for (std::size_t d = 1; d < dims.size(); ++d) a.shape.push_back(static_cast<std::size_t>(dims[d]));
    if (a.integer)
      a.counts = h5.read_ints(name);
    else
      a.reals = h5.read_doubles(name);
    model_state.push_back(std::move(a));
  }
  return {checkpoint.count("series"), checkpoint.count("profiles")};
}

}  // namespace shockfield::pd
