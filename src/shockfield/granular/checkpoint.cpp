#include "shockfield/granular/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::granular {

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters) {
  io::CheckpointWriter h5(file, "granular", kCheckpointFormat);
  h5.set_count("step", sim.step_count());
  h5.set_attribute("time", sim.time());
  h5.set_attribute("external_work", sim.thermo().external_work);
  h5.set_count("series", counters.series);
  h5.set_count("probes", counters.probes);
  h5.set_count("spacetime", counters.spacetime);
  h5.set_count("signal", counters.signal);
  h5.set_count("profiles", counters.profiles);
  h5.write("displacement", "m", sim.displacement());
  h5.write("velocity", "m/s", sim.velocity());
  h5.write("force", "N", sim.force());
  h5.write("contact_force", "N", sim.contact_force());
  // The chain itself (fixed by the case), so that the file alone gives the grains' positions
  // (depth + displacement, downwards) for `shockfield convert`.
  h5.write("depth", "m", sim.chain().depth);
  h5.write("radius", "m", sim.chain().radius);
  h5.write("mass", "kg", sim.chain().mass);
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string f = file.string();
  checkpoint.require("granular", kCheckpointFormat);
  try {
    sim.restore(h5.read_doubles("displacement"), h5.read_doubles("velocity"), h5.read_doubles("force"),
                h5.read_doubles("contact_force"), checkpoint.count("step"),
                h5.attribute("time"), h5.attribute("external_work"));
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", f, e.what()));
  }
  return {checkpoint.count("series"), checkpoint.count("probes"), checkpoint.count("spacetime"),
          checkpoint.count("signal"), checkpoint.count("profiles")};
}

}  // namespace shockfield::granular
