#include "shockfield/mpm/checkpoint.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checkpoint_file.hpp"

namespace shockfield::mpm {
namespace {

constexpr double kFormatVersion = 2;  // 2: damage added
// Scalars of materials::PointState in checkpoint order.
constexpr int kScalars = 10;

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
void unpack(const std::vector<double>& d, std::size_t n, const std::string& name, const std::string& file, Set set) {
  if (d.size() != N * n)
    throw InputError(fmt::format("{}: dataset '{}' has {} values, the case has {} particles", file, name, d.size(), n));
  for (std::size_t i = 0; i < n; ++i) set(i, &d[N * i]);
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Simulation& sim, const OutputCounters& counters,
                      const std::vector<double>& cavity_state) {
  io::CheckpointWriter h5(file);
  const Particles& p = sim.particles();
  const std::size_t n = p.size();
  h5.set_attribute("format_version", kFormatVersion);
  h5.set_attribute("step", static_cast<double>(sim.step_count()));
  h5.set_attribute("time", sim.time());
  h5.set_attribute("dt", sim.last_time_step());
  h5.set_attribute("series", static_cast<double>(counters.series));
  h5.set_attribute("fields", static_cast<double>(counters.fields));
  h5.set_attribute("histograms", static_cast<double>(counters.histograms));
  h5.write("x", pack<3>(n, [&](std::size_t i) { return p.x[i]; }), {n, 3});
  h5.write("v", pack<3>(n, [&](std::size_t i) { return p.v[i]; }), {n, 3});
  h5.write("L", pack<9>(n, [&](std::size_t i) { return p.velocity_gradient[i]; }), {n, 9});
  h5.write("F", pack<9>(n, [&](std::size_t i) { return p.state[i].deformation; }), {n, 9});
  h5.write("s", pack<9>(n, [&](std::size_t i) { return p.state[i].deviatoric.s; }), {n, 9});
  h5.write("back_stress", pack<9>(n, [&](std::size_t i) { return p.state[i].deviatoric.back_stress; }), {n, 9});
  h5.write("scalars", pack<kScalars>(n, [&](std::size_t i) {
             const auto& s = p.state[i];
             return Eigen::Matrix<double, kScalars, 1>(
                 (Eigen::Matrix<double, kScalars, 1>() << s.deviatoric.plastic_strain, s.pressure, s.viscous_pressure,
                  s.energy, s.temperature, s.shock_volume, s.plastic_work, s.sound_speed, p.mass[i], s.damage)
                     .finished());
           }), {n, kScalars});
  if (!cavity_state.empty()) h5.write("cavity", cavity_state);
  h5.commit();
}

OutputCounters read_checkpoint(const std::filesystem::path& file, Simulation& sim, std::vector<double>& cavity_state) {
  const io::CheckpointReader checkpoint(file);
  const io::Hdf5File& h5 = checkpoint.h5();
  const std::string f = file.string();
  checkpoint.require_format(kFormatVersion);
  Particles& p = sim.particles();
  const std::size_t n = p.size();
  unpack<3>(h5.read_doubles("x"), n, "x", f, [&](std::size_t i, const double* d) { p.x[i] = Vec3(d); });
  unpack<3>(h5.read_doubles("v"), n, "v", f, [&](std::size_t i, const double* d) { p.v[i] = Vec3(d); });
  unpack<9>(h5.read_doubles("L"), n, "L", f, [&](std::size_t i, const double* d) { p.velocity_gradient[i] = Mat3(d); });
  unpack<9>(h5.read_doubles("F"), n, "F", f, [&](std::size_t i, const double* d) { p.state[i].deformation = Mat3(d); });
  unpack<9>(h5.read_doubles("s"), n, "s", f, [&](std::size_t i, const double* d) { p.state[i].deviatoric.s = Mat3(d); });
  unpack<9>(h5.read_doubles("back_stress"), n, "back_stress", f,
            [&](std::size_t i, const double* d) { p.state[i].deviatoric.back_stress = Mat3(d); });
  unpack<kScalars>(h5.read_doubles("scalars"), n, "scalars", f, [&](std::size_t i, const double* d) {
    auto& s = p.state[i];
    s.deviatoric.plastic_strain = d[0], s.pressure = d[1], s.viscous_pressure = d[2], s.energy = d[3];
    s.temperature = d[4], s.shock_volume = d[5], s.plastic_work = d[6], s.sound_speed = d[7], s.damage = d[9];
    if (p.mass[i] != d[8])
      throw InputError(fmt::format("{}: particle {} has mass {} kg, the case gives {} kg (a different sample)", f, i, d[8],
                                   p.mass[i]));
  });
  sim.restore_clock(h5.attribute("time"), checkpoint.count("step"), h5.attribute("dt"));
  cavity_state = h5.has("cavity") ? h5.read_doubles("cavity") : std::vector<double>{};
  return {checkpoint.count("series"), checkpoint.count("fields"),
          checkpoint.count("histograms")};
}

}  // namespace shockfield::mpm
