#include "shockfield/md/fixes/nphug.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

using units::metal::boltz;
using units::metal::mvv2e;
using units::metal::nktv2p;

namespace {

// The pressure the Hugoniostat holds: P_aa for a uniaxial style, else the scalar pressure.
double hugoniot_pressure(const ThermoState& t, int axis) { return axis >= 0 ? t.pressure_tensor[axis] : t.pressure; }

double degrees_of_freedom(const Simulation& sim) { return 3.0 * static_cast<double>(sim.atoms.nlocal) - 3.0; }

NptSettings with_lammps_mtk(NptSettings npt) {
  npt.lammps_mtk = true;
  return npt;
}

}  // namespace

FixNphug::FixNphug(const NphugSettings& settings, std::uint32_t group_bit)
    : FixNoseHooverNpt(with_lammps_mtk(settings.npt), group_bit), settings_(settings), group_bit_(group_bit) {}

void FixNphug::setup(Simulation& sim) {
  FixNoseHooverNpt::setup(sim);
  const ThermoState t = sim.thermo();
  // LAMMPS FixNH::setup: "Current temperature too close to zero" (the masses scale with it).
  if (!(t.temperature > 1e-6))
    throw RunError(fmt::format("step {}: nphug starts at temperature {} K; its thermostat and barostat masses are "
                               "set from the temperature at the start of the stage, which must be above 0 (give the "
                               "atoms velocities first: [velocity] temperature or an earlier stage)",
                               sim.step, t.temperature));
  set_reference_temperature(t.temperature);
  // LAMMPS FixNPHug::setup: the target is 0.01 K until the first Hugoniot target, which the
  // barostat chain's first half step (before target_temperature()) still uses.
  target_ = 0.01;
  retarget(target_);
  total_mass_ = 0;
  for (std::size_t i = 0; i < sim.atoms.nlocal; ++i) total_mass_ += sim.atoms.mass_of(i);
  v0_ = settings_.v0.value_or(t.volume);
  p0_ = settings_.p0.value_or(hugoniot_pressure(t, settings_.axis));
  e0_ = settings_.e0.value_or(t.kinetic + t.potential);
  steps_done_ = 0;
  averages_ = {};
}

double FixNphug::target_temperature(const Simulation& sim) {
  target_ = sim.thermo().temperature + quantities(sim).dhugoniot;  // eq. (1)
  return target_;
}

NphugQuantities FixNphug::quantities(const Simulation& sim) const {
  const ThermoState t = sim.thermo();
  NphugQuantities q;
  q.pressure = hugoniot_pressure(t, settings_.axis);
  q.volume = t.volume;
  // Eq. (1): the energy missing to the Hugoniot, as a temperature of the 3N − 3 degrees of freedom.
  q.dhugoniot = (0.5 * (q.pressure + p0_) * (v0_ - q.volume) / nktv2p + e0_ - (t.kinetic + t.potential)) /
                (degrees_of_freedom(sim) * boltz);
  // Eq. (3): U_s² = (p − p₀)/(ρ₀ ε), with ρ₀ = M/V₀ in eV ps²/Å⁵ so that U_s is in Å/ps.
  const double strain = 1.0 - q.volume / v0_;
  const double rho0 = nktv2p * mvv2e * total_mass_ / v0_;
  q.us = (strain < 1e-10 || q.pressure < p0_) ? 0.0 : std::sqrt((q.pressure - p0_) / (rho0 * strain));
  q.up = strain * q.us;
  return q;
}

void FixNphug::end_of_step(Simulation& sim) {
  ++steps_done_;
  if (2 * steps_done_ <= settings_.stage_steps) return;
  const ThermoState t = sim.thermo();
  const NphugQuantities q = quantities(sim);
  averages_.samples += 1;
  averages_.pressure += q.pressure;
  averages_.volume += q.volume;
  averages_.temperature += t.temperature;
  averages_.energy += t.kinetic + t.potential;
  averages_.dhugoniot += q.dhugoniot;
}

FixState FixNphug::state() const {
  FixState s = FixNoseHooverNpt::state();
  s.insert(s.end(), {{"mass_temperature", "K", {npt_settings().temperature}},
                     {"target_temperature", "K", {target_}},
                     {"total_mass", "g/mol", {total_mass_}},
                     {"p0", "bar", {p0_}},
                     {"v0", "Angstrom^3", {v0_}},
                     {"e0", "eV", {e0_}},
                     {"steps_done", "1", {static_cast<double>(steps_done_)}},
                     {"average_samples", "1", {averages_.samples}},
                     {"sum_pressure", "bar", {averages_.pressure}},
                     {"sum_volume", "Angstrom^3", {averages_.volume}},
                     {"sum_temperature", "K", {averages_.temperature}},
                     {"sum_energy", "eV", {averages_.energy}},
                     {"sum_dhugoniot", "K", {averages_.dhugoniot}}});
  return s;
}

void FixNphug::restore(const FixState& s) {
  const auto value = [&](const char* key) { return fix_state_value(s, name(), key); };
  // The masses' temperature first (it rebuilds the chains), then the chains' variables and target.
  set_reference_temperature(value("mass_temperature"));
  FixNoseHooverNpt::restore(s);
  target_ = value("target_temperature");
  retarget(target_);
  total_mass_ = value("total_mass");
  p0_ = value("p0");
  v0_ = value("v0");
  e0_ = value("e0");
  steps_done_ = static_cast<std::int64_t>(value("steps_done"));
  averages_ = {value("average_samples"), value("sum_pressure"), value("sum_volume"), value("sum_temperature"),
               value("sum_energy"), value("sum_dhugoniot")};
}

}  // namespace shockfield::md
