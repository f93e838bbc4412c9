#include "shockfield/macroparticle/outputs.hpp"

#include <fmt/format.h>

#include "shockfield/geometry/shrink_wrap.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/io/vtk_pieces.hpp"

namespace shockfield::macroparticle {

namespace fs = std::filesystem;

namespace {

bool due(long long every, std::int64_t step) { return every > 0 && step % every == 0; }

// Drops the frames of a folder written after `step` (their names end in _<step>.* or .<step>.*,
// a frame's folder of VTK pieces in _<step>).
void drop_frames_after(const fs::path& dir, std::int64_t step) {
  if (!fs::exists(dir)) return;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string stem = entry.path().stem().string();
    const auto cut = stem.find_last_of("._");
    if (cut != std::string::npos && std::stoll(stem.substr(cut + 1)) > step) fs::remove_all(entry.path());
  }
}

}  // namespace

RodOutputs::RodOutputs(const fs::path& folder, const OutputSpec& spec, std::optional<std::int64_t> resume_step)
    : folder_(folder), spec_(spec) {
  if (spec.dump_every > 0) fs::create_directories(folder / "dumps");
  if (spec.vtk_every > 0) {
    fs::create_directories(folder / "particles");
    const double keep = resume_step ? static_cast<double>(*resume_step) : 0.0;
    pvd_ = io::PvdSeries(folder / "particles.pvd", resume_step ? &keep : nullptr, "s");
  }
  if (resume_step) {
    drop_frames_after(folder / "dumps", *resume_step);
    drop_frames_after(folder / "particles", *resume_step);
    last_step_ = *resume_step;
  }
}

bool RodOutputs::needs_per_atom(std::int64_t step) const {
  return due(spec_.dump_every, step) || due(spec_.vtk_every, step);
}

void RodOutputs::write_due(const Rod& rod) {
  const std::int64_t step = rod.sim().step;
  if (step == last_step_) return;
  last_step_ = step;
  if (due(spec_.dump_every, step)) write_dump(rod);
  if (due(spec_.vtk_every, step)) write_vtk(rod);
}

void RodOutputs::write_dump(const Rod& rod) const {
  const md::Simulation& sim = rod.sim();
  // The box reset to where the particles are now, as LAMMPS write_data resets a shrink-wrapped box
  // (geometry/shrink_wrap), not where the last neighbour rebuild left it: LAMMPS read_dump and
  // rerun then find every particle inside.
  geometry::Box box = sim.box;
  geometry::shrink_wrap(box, std::span<const Vec3>(sim.atoms.x.data(), sim.atoms.nlocal), sim.shrink_margin);
  io::DumpFrame frame = io::make_dump_frame(sim.step, box, sim.atoms, {"id", "type", "x", "y", "z", "vx", "vy", "vz"});
  // Engine units to SI (reduced_units.hpp).
  const double length = rod.units().length, speed = rod.units().velocity();
  for (const char* c : {"x", "y", "z"}) {
    std::vector<double> v = frame.column(c);
    for (double& x : v) x *= length;
    frame.set_column(c, std::move(v));
  }
  for (const char* c : {"vx", "vy", "vz"}) {
    std::vector<double> v = frame.column(c);
    for (double& x : v) x *= speed;
    frame.set_column(c, std::move(v));
  }
  for (int d = 0; d < 3; ++d) {
    frame.box.lo[d] *= length;
    frame.box.hi[d] *= length;
  }
  frame.time = sim.time * rod.units().time();
  frame.units = "si";  // what the columns are in, as the PD and granular dumps say (io/particle_frame)
  frame.set_column("szz", rod.particle_stress());
  io::CheckedOutput out(folder_ / "dumps" / fmt::format("dump.{:0{}}.lammpstrj", sim.step, spec_.dump_pad));
  io::write_dump_frame(out.stream(), frame);
  out.close();
}

void RodOutputs::write_vtk(const Rod& rod) {
  const md::Atoms& a = rod.sim().atoms;
  std::vector<double> xyz, velocity;
  xyz.reserve(3 * a.nlocal);
  velocity.reserve(3 * a.nlocal);
  for (std::size_t i = 0; i < a.nlocal; ++i)
    for (int d = 0; d < 3; ++d) {
      xyz.push_back(a.x[i][d] * rod.units().length);
      velocity.push_back(a.v[i][d] * rod.units().velocity());
    }
  io::VtkFormat format{io::VtkEncoding::Zlib, io::VtkPrecision::Float32};
  format.pieces = spec_.vtk_pieces;
  const std::string file = io::write_points_frame(
      folder_, fmt::format("particles/particles_{}", rod.sim().step), xyz,
      {{"velocity", 3, std::move(velocity), "m/s"}, {"stress_zz", 1, rod.particle_stress(), "Pa"}}, format);
  pvd_.add(rod.sim().time * rod.units().time(), file);
}

}  // namespace shockfield::macroparticle
