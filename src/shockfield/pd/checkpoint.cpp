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

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const std::vector<double>& model_state,
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
  // The force model's own state, in its layout (docs/checkpoints.md): bond flags then s0 (pmb,
  // lps), or F then the material state per point (correspondence); mixed units.
  h5.write("model_state", "mixed", model_state);
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, std::vector<double>& model_state) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string f = file.string();
  checkpoint.require("pd", kCheckpointFormat);
  const std::size_t n = sim.cloud().size();
  sim.restore(unflatten(h5.read_doubles("position"), n, "position", f),
              unflatten(h5.read_doubles("velocity"), n, "velocity", f),
              unflatten(h5.read_doubles("force_density"), n, "force_density", f),
              checkpoint.count("step"), h5.attribute("time"));
  model_state = h5.read_doubles("model_state");
  return {checkpoint.count("series"), checkpoint.count("profiles")};
}

}  // namespace shockfield::pd
