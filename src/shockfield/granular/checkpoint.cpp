#include "shockfield/granular/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/hdf5_file.hpp"

namespace shockfield::granular {
namespace {

constexpr double kFormatVersion = 1;

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    io::Hdf5File h5(tmp, io::Hdf5File::Mode::create);
    h5.set_attribute("format_version", kFormatVersion);
    h5.set_attribute("method", "granular");
    h5.set_attribute("step", static_cast<double>(sim.step_count()));
    h5.set_attribute("time", sim.time());
    h5.set_attribute("external_work", sim.thermo().external_work);
    h5.set_attribute("series", static_cast<double>(counters.series));
    h5.set_attribute("probes", static_cast<double>(counters.probes));
    h5.set_attribute("spacetime", static_cast<double>(counters.spacetime));
    h5.set_attribute("signal", static_cast<double>(counters.signal));
    h5.write("displacement", sim.displacement());
    h5.write("velocity", sim.velocity());
    h5.write("force", sim.force());
    h5.write("contact_force", sim.contact_force());
  }
  std::filesystem::rename(tmp, file);
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim) {
  io::Hdf5File h5(file, io::Hdf5File::Mode::read);
  const std::string f = file.string();
  if (h5.attribute("format_version") != kFormatVersion || h5.string_attribute("method") != "granular")
    throw InputError(fmt::format("{}: not a granular checkpoint of format {}", f, kFormatVersion));
  try {
    sim.restore(h5.read_doubles("displacement"), h5.read_doubles("velocity"), h5.read_doubles("force"),
                h5.read_doubles("contact_force"), static_cast<long long>(h5.attribute("step")),
                h5.attribute("time"), h5.attribute("external_work"));
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", f, e.what()));
  }
  return {static_cast<std::int64_t>(h5.attribute("series")), static_cast<std::int64_t>(h5.attribute("probes")),
          static_cast<std::int64_t>(h5.attribute("spacetime")), static_cast<std::int64_t>(h5.attribute("signal"))};
}

}  // namespace shockfield::granular
