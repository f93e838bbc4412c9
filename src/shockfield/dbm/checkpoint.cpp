#include "shockfield/dbm/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::dbm {
namespace {

constexpr double kFormatVersion = 1;

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters,
                      const std::vector<double>* reactant) {
  io::CheckpointWriter h5(file);
  h5.set_attribute("format_version", kFormatVersion);
  h5.set_attribute("step", static_cast<double>(sim.steps()));
  h5.set_attribute("time", sim.time());
  h5.set_attribute("series", static_cast<double>(counters.series));
  h5.set_attribute("profiles", static_cast<double>(counters.profiles));
  h5.set_attribute("fields", static_cast<double>(counters.fields));
  const std::vector<double>& f = sim.f();
  h5.write("f", f, {static_cast<hsize_t>(sim.model().size()), f.size() / static_cast<std::size_t>(sim.model().size())});
  if (reactant) h5.write("reactant", *reactant, {static_cast<hsize_t>(reactant->size())});
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, std::vector<double>* reactant) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string name = file.string();
  checkpoint.require_format(kFormatVersion);
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
