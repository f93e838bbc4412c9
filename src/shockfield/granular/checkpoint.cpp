#include "shockfield/granular/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::granular {
namespace {

constexpr double kFormatVersion = 3;  // 2: checksummed (io/checkpoint_file); 3: the profiles counter

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters) {
  io::CheckpointWriter h5(file);
  h5.set_attribute("format_version", kFormatVersion);
  h5.set_attribute("method", "granular");
  h5.set_attribute("step", static_cast<double>(sim.step_count()));
  h5.set_attribute("time", sim.time());
  h5.set_attribute("external_work", sim.thermo().external_work);
  h5.set_attribute("series", static_cast<double>(counters.series));
  h5.set_attribute("probes", static_cast<double>(counters.probes));
  h5.set_attribute("spacetime", static_cast<double>(counters.spacetime));
  h5.set_attribute("signal", static_cast<double>(counters.signal));
  h5.set_attribute("profiles", static_cast<double>(counters.profiles));
  h5.write("displacement", sim.displacement());
  h5.write("velocity", sim.velocity());
  h5.write("force", sim.force());
  h5.write("contact_force", sim.contact_force());
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string f = file.string();
  if (h5.attribute("format_version") != kFormatVersion || h5.string_attribute("method") != "granular")
    throw InputError(fmt::format("{}: not a granular checkpoint of format {}", f, kFormatVersion));
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
