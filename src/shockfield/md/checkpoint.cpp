#include "shockfield/md/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"
#include "shockfield/md/force_evaluation.hpp"

namespace shockfield::md {
namespace {

std::vector<double> flatten(const std::vector<Vec3>& v, std::size_t n) {
  std::vector<double> out(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) out[3 * i + d] = v[i][d];
  return out;
}

std::vector<Vec3> unflatten(const std::vector<double>& flat) {
  std::vector<Vec3> out(flat.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  return out;
}

// lo, hi, then the tilt factors xy xz yz for a triclinic box only (orthogonal files unchanged).
std::vector<double> box_data(const geometry::Box& b) {
  std::vector<double> d{b.lo.x(), b.lo.y(), b.lo.z(), b.hi.x(), b.hi.y(), b.hi.z()};
  if (b.triclinic()) d.insert(d.end(), {b.tilt.x(), b.tilt.y(), b.tilt.z()});
  return d;
}

void set_box(geometry::Box& b, const std::vector<double>& d) {
  b.lo = Vec3(d.at(0), d.at(1), d.at(2));
  b.hi = Vec3(d.at(3), d.at(4), d.at(5));
  b.tilt = d.size() >= 9 ? Vec3(d[6], d[7], d[8]) : Vec3::Zero();
}

// The datasets of fix k's state are named fix<k>_<fix>.<variable>.
std::string fix_dataset_prefix(std::size_t k, const Fix& fix) { return fmt::format("fix{}_{}.", k, fix.name()); }

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const CheckpointPosition& where,
                      const CheckpointUnits& units) {
  io::CheckpointWriter h5(file, units.method, kCheckpointFormat);
  const Atoms& a = sim.atoms;
  const std::size_t n = a.nlocal;
  const auto n3 = std::vector<hsize_t>{n, 3};
  h5.set_count("step", sim.step);
  h5.set_attribute("time", sim.time);
  h5.set_attribute("units", units.system);
  h5.set_count("neighbor_rebuilds", sim.rebuilds);
  h5.set_count("steps_since_rebuild", sim.steps_since_rebuild);
  h5.set_count("stage", where.stage);
  h5.set_count("stage_step", where.stage_step);
  h5.set_attribute("boundary", sim.box.boundary_codes());
  h5.write("position", units.length, flatten(a.x, n), n3);
  h5.write("velocity", units.velocity, flatten(a.v, n), n3);
  h5.write("force", units.force, flatten(a.f, n), n3);
  h5.write("position_at_rebuild", units.length, flatten(sim.positions_at_rebuild(), n), n3);
  std::vector<std::int64_t> image(3 * n), type(n), mask(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) image[3 * i + d] = a.image[i][d];
    type[i] = a.type[i];
    mask[i] = a.mask[i];
  }
  h5.write("image", "1", image, n3);
  h5.write("id", "1", a.id);
  h5.write("type", "1", type);
  h5.write("mask", "1", mask);
  h5.write("type_mass", units.mass, a.mass);
  std::string names;
  for (const std::string& name : a.type_names) names += (names.empty() ? "" : " ") + (name.empty() ? "-" : name);
  h5.set_attribute("type_names", names);
  h5.write("box", units.length, box_data(sim.box));
  h5.write("box_at_rebuild", units.length, box_data(sim.box_at_rebuild()));
  for (std::size_t k = 0; k < sim.fixes.size(); ++k)
    for (const FixStateItem& item : sim.fixes[k]->state())
      if (!item.values.empty())
        h5.write(fix_dataset_prefix(k, *sim.fixes[k]) + item.name, units.metal_fix_units ? item.units : "1",
                 item.values);
  h5.commit();
}

CheckpointPosition read_checkpoint_header(const std::filesystem::path& file, const std::string& method) {
  const io::CheckpointReader checkpoint(file);
  checkpoint.require(method, kCheckpointFormat);
  return {checkpoint.count("stage"), checkpoint.count("stage_step")};
}

void read_checkpoint(const std::filesystem::path& file, Simulation& sim, const std::string& method) {
  const io::CheckpointReader checkpoint(file);
  checkpoint.require(method, kCheckpointFormat);
  const io::Hdf5File& h5 = checkpoint.h5();
  Atoms& a = sim.atoms;
  const auto id = h5.read_ints("id");
  const std::size_t n = id.size();
  if (h5.string_attribute("boundary") != sim.box.boundary_codes())
    throw InputError(fmt::format("{}: checkpoint boundaries '{}' differ from the case's '{}'", file.string(),
                                 h5.string_attribute("boundary"), sim.box.boundary_codes()));
  const auto type = h5.read_ints("type");
  const auto mask = h5.read_ints("mask");
  const auto image = h5.read_ints("image");
  a.clear_ghosts();
  a.x = unflatten(h5.read_doubles("position"));
  a.v = unflatten(h5.read_doubles("velocity"));
  a.f.assign(n, Vec3::Zero());
  a.id = id;
  a.type.resize(n);
  a.mask.resize(n);
  a.image.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (type[i] < 0 || type[i] >= a.ntypes())
      throw InputError(fmt::format("{}: atom type {} does not exist in the case", file.string(), type[i] + 1));
    a.type[i] = static_cast<int>(type[i]);
    a.mask[i] = static_cast<std::uint32_t>(mask[i]);
    for (int d = 0; d < 3; ++d) a.image[i][d] = static_cast<int>(image[3 * i + d]);
  }
  a.nlocal = n;
  sim.step = checkpoint.count("step");
  sim.time = h5.attribute("time");
  set_box(sim.box, h5.read_doubles("box"));
  geometry::Box rebuild_box = sim.box;
  set_box(rebuild_box, h5.read_doubles("box_at_rebuild"));
  const std::vector<std::string> datasets = h5.dataset_names();
  for (std::size_t k = 0; k < sim.fixes.size(); ++k) {
    const std::string prefix = fix_dataset_prefix(k, *sim.fixes[k]);
    FixState state;
    for (const std::string& name : datasets)
      if (name.starts_with(prefix))
        state.push_back({name.substr(prefix.size()), h5.units(name), h5.read_doubles(name)});
    sim.fixes[k]->restore(state);
  }
  sim.restore_rebuild_state(unflatten(h5.read_doubles("position_at_rebuild")), rebuild_box);
  sim.rebuilds = checkpoint.count("neighbor_rebuilds");
  sim.steps_since_rebuild = checkpoint.count("steps_since_rebuild");
  // Energies and virial of the restored step, then the saved forces: they include what fixes
  // added after the force evaluation (Langevin bath forces), which a recomputation would lose.
  evaluate_forces(a, *sim.potential, sim.list, sim.forces, false);
  a.f = unflatten(h5.read_doubles("force"));
}

}  // namespace shockfield::md
