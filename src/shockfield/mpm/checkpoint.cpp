#include "shockfield/mpm/checkpoint.hpp"

#include <fmt/format.h>

#include <array>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::mpm {
namespace {

// The scalars of materials::PointState, one dataset each, in the layout of docs/checkpoints.md.
struct ScalarField {
  const char* name;
  const char* units;
  double materials::PointState::*member;
};
constexpr std::array<ScalarField, 8> kScalars{{
    {"pressure", "Pa", &materials::PointState::pressure},
    {"viscous_pressure", "Pa", &materials::PointState::viscous_pressure},
    {"specific_energy", "J/kg", &materials::PointState::energy},
    {"temperature", "K", &materials::PointState::temperature},
    {"shock_specific_volume", "m3/kg", &materials::PointState::shock_volume},
    {"specific_plastic_work", "J/kg", &materials::PointState::plastic_work},
    {"sound_speed", "m/s", &materials::PointState::sound_speed},
    {"damage", "1", &materials::PointState::damage},
}};

template <int N, class Get>
std::vector<double> pack(std::size_t n, Get get) {
  std::vector<double> out(N * n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto v = get(i);
    for (int k = 0; k < N; ++k) out[N * i + static_cast<std::size_t>(k)] = v.data()[k];
  }
  return out;
}

template <int N, class Set>
void unpack(const io::Hdf5File& h5, const std::string& name, std::size_t n, Set set) {
  const std::vector<double> d = h5.read_doubles(name);
  if (d.size() != N * n)
    throw InputError(fmt::format("{}: dataset '{}' has {} values, the case has {} particles", h5.path(), name,
                                 d.size(), n));
  for (std::size_t i = 0; i < n; ++i) set(i, &d[N * i]);
}

// The cavity tracker's state (cavity_tracker.hpp) in its order; units "" = m^dim (an area in 2D).
struct CavityPart {
  const char* name;
  std::ptrdiff_t count;
  const char* units;
};
constexpr std::array<CavityPart, 4> kCavityParts{{{"cavity_centre", 3, "m"},
                                                  {"cavity_radius", 1, "m"},
                                                  {"cavity_initial_size", 1, ""},
                                                  {"cavity_last_time", 1, "s"}}};

// The point mass: per metre of thickness in 2D (particles.hpp).
std::string mass_units(int dim) { return dim == 3 ? "kg" : "kg/m"; }

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters,
                      const std::vector<double>& cavity_state) {
  io::CheckpointWriter h5(file, "mpm", kCheckpointFormat);
  const Particles& p = sim.particles();
  const std::size_t n = p.size();
  h5.set_count("step", sim.step_count());
  h5.set_attribute("time", sim.time());
  h5.set_attribute("dt", sim.last_time_step());
  h5.set_count("dim", sim.grid().dim());
  h5.set_count("series", counters.series);
  h5.set_count("fields", counters.fields);
  h5.set_count("histograms", counters.histograms);
  h5.write("position", "m", pack<3>(n, [&](std::size_t i) { return p.x[i]; }), {n, 3});
  h5.write("velocity", "m/s", pack<3>(n, [&](std::size_t i) { return p.v[i]; }), {n, 3});
  h5.write("velocity_gradient", "1/s", pack<9>(n, [&](std::size_t i) { return p.velocity_gradient[i]; }), {n, 9});
  h5.write("deformation_gradient", "1", pack<9>(n, [&](std::size_t i) { return p.state[i].deformation; }), {n, 9});
  h5.write("deviatoric_stress", "Pa", pack<9>(n, [&](std::size_t i) { return p.state[i].deviatoric.s; }), {n, 9});
  h5.write("back_stress", "Pa", pack<9>(n, [&](std::size_t i) { return p.state[i].deviatoric.back_stress; }), {n, 9});
  std::vector<double> column(n);
  for (std::size_t i = 0; i < n; ++i) column[i] = p.state[i].deviatoric.plastic_strain;
  h5.write("plastic_strain", "1", column);
  for (const ScalarField& s : kScalars) {
    for (std::size_t i = 0; i < n; ++i) column[i] = p.state[i].*s.member;
    h5.write(s.name, s.units, column);
  }
  h5.write("mass", mass_units(sim.grid().dim()), p.mass);
  h5.write("material", "1", std::vector<std::int64_t>(p.material.begin(), p.material.end()));
  h5.write("body", "1", std::vector<std::int64_t>(p.body.begin(), p.body.end()));
  if (!cavity_state.empty()) {
    const std::string size_units = sim.grid().dim() == 3 ? "m3" : "m2";
    auto at = cavity_state.begin();
    for (const CavityPart& part : kCavityParts) {
      h5.write(part.name, *part.units ? part.units : size_units, std::vector<double>(at, at + part.count));
      at += part.count;
    }
  }
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, std::vector<double>& cavity_state) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  checkpoint.require("mpm", kCheckpointFormat);
  Particles& p = sim.particles();
  const std::size_t n = p.size();
  unpack<3>(h5, "position", n, [&](std::size_t i, const double* d) { p.x[i] = Vec3(d); });
  unpack<3>(h5, "velocity", n, [&](std::size_t i, const double* d) { p.v[i] = Vec3(d); });
  unpack<9>(h5, "velocity_gradient", n, [&](std::size_t i, const double* d) { p.velocity_gradient[i] = Mat3(d); });
  unpack<9>(h5, "deformation_gradient", n, [&](std::size_t i, const double* d) { p.state[i].deformation = Mat3(d); });
  unpack<9>(h5, "deviatoric_stress", n, [&](std::size_t i, const double* d) { p.state[i].deviatoric.s = Mat3(d); });
  unpack<9>(h5, "back_stress", n, [&](std::size_t i, const double* d) { p.state[i].deviatoric.back_stress = Mat3(d); });
  unpack<1>(h5, "plastic_strain", n, [&](std::size_t i, const double* d) { p.state[i].deviatoric.plastic_strain = *d; });
  for (const ScalarField& s : kScalars)
    unpack<1>(h5, s.name, n, [&](std::size_t i, const double* d) { p.state[i].*s.member = *d; });
  unpack<1>(h5, "mass", n, [&](std::size_t i, const double* d) {
    if (p.mass[i] != *d)
      throw InputError(fmt::format("{}: particle {} has mass {} {}, the case gives {} (a different sample)", h5.path(),
                                   i, *d, h5.units("mass"), p.mass[i]));
  });
  sim.restore_clock(h5.attribute("time"), checkpoint.count("step"), h5.attribute("dt"));
  cavity_state.clear();
  if (h5.has("cavity_centre"))
    for (const CavityPart& part : kCavityParts) {
      const std::vector<double> v = h5.read_doubles(part.name);
      cavity_state.insert(cavity_state.end(), v.begin(), v.end());
    }
  return {checkpoint.count("series"), checkpoint.count("fields"), checkpoint.count("histograms")};
}

}  // namespace shockfield::mpm
