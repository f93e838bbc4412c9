#include "shockfield/md/msst_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/core/units.hpp"

namespace shockfield::md {

using units::metal::A_per_ps_to_km_per_s;
using units::metal::amu_per_A3_to_g_per_cc;
using units::metal::bar_to_GPa;

const FixMsst* find_msst(const Simulation& sim) {
  for (const auto& fix : sim.fixes)
    if (auto* m = dynamic_cast<const FixMsst*>(fix.get())) return m;
  return nullptr;
}

std::vector<std::string> msst_thermo_columns() { return {"Vol", "Pshock", "Econs", "Up", "dHug", "dRay", "LagPos"}; }

std::vector<double> msst_thermo_values(const Simulation& sim, int axis) {
  const ThermoState t = sim.thermo();
  double added = 0;
  for (const auto& fix : sim.fixes) added += fix->energy_added();
  const double econs = t.kinetic + t.potential - added;
  const FixMsst* fix = find_msst(sim);
  if (!fix) return {t.volume, t.pressure_tensor[axis], econs, NAN, NAN, NAN, NAN};
  const MsstQuantities q = fix->quantities(sim);
  return {t.volume, q.pressure_axis, econs, q.lagrangian_speed, q.dhugoniot, q.drayleigh, q.lagrangian_position};
}

MsstReport make_msst_report(const Simulation& sim, const FixMsst& fix, const std::string& stage) {
  MsstReport r;
  r.stage = stage;
  r.shock_speed = fix.settings().shock_speed * A_per_ps_to_km_per_s;
  r.v0 = fix.v0();
  r.p0 = fix.p0();
  r.e0 = fix.e0();
  r.density0 = fix.total_mass() / fix.v0() * amu_per_A3_to_g_per_cc;
  r.final_state = fix.quantities(sim);
  const ThermoState t = sim.thermo();
  r.final_temperature = t.temperature;
  r.mean = fix.averages();
  if (r.mean.samples > 0) {
    const double n = r.mean.samples;
    r.mean.up /= n;
    r.mean.pressure_axis /= n;
    r.mean.volume /= n;
    r.mean.temperature /= n;
  } else {  // a stage of one step has no second half: no means (null in summary.json)
    r.mean.up = r.mean.pressure_axis = r.mean.volume = r.mean.temperature = NAN;
  }
  r.conserved_start = fix.conserved_at_start();
  r.conserved_end = t.kinetic + t.potential + r.final_state.energy;
  r.atoms = sim.atoms.nlocal;
  return r;
}

namespace {
double mean_density(const MsstReport& r) { return r.density0 * r.v0 / r.mean.volume; }
}  // namespace

std::string msst_log_line(const MsstReport& r) {
  return fmt::format(
      "[{}] MSST at Us = {:.4g} km/s, mean of the last half ({} steps): Up = {:.4f} km/s, P = {:.3f} GPa, "
      "rho = {:.4f} g/cc (rho0 = {:.4f}), V/V0 = {:.4f}, T = {:.0f} K; conserved quantity drift {:.3g} eV/atom",
      r.stage, r.shock_speed, r.mean.samples, r.mean.up * A_per_ps_to_km_per_s, r.mean.pressure_axis * bar_to_GPa,
      mean_density(r), r.density0, r.mean.volume / r.v0, r.mean.temperature,
      (r.conserved_end - r.conserved_start) / static_cast<double>(r.atoms));
}

Json msst_json(const MsstReport& r) {
  const double us = r.shock_speed, up = r.mean.up * A_per_ps_to_km_per_s;
  return Json::object()
      .set("stage", r.stage)
      .set("shock_speed_km_s", us)
      .set("v0_A3", r.v0)
      .set("p0_bar", r.p0)
      .set("e0_eV", r.e0)
      .set("initial_density_g_cc", r.density0)
      .set("mean_samples", r.mean.samples)
      .set("particle_speed_km_s", up)
      .set("pressure_GPa", r.mean.pressure_axis * bar_to_GPa)
      .set("pressure_rankine_hugoniot_GPa", r.density0 * us * up)  // ρ₀ U_s U_p: g/cc·km²/s² = GPa
      .set("density_g_cc", mean_density(r))
      .set("volume_ratio", r.mean.volume / r.v0)
      .set("temperature_K", r.mean.temperature)
      .set("final", Json::object()
                        .set("particle_speed_km_s", r.final_state.lagrangian_speed * A_per_ps_to_km_per_s)
                        .set("pressure_GPa", r.final_state.pressure_axis * bar_to_GPa)
                        .set("volume_A3", r.final_state.volume)
                        .set("temperature_K", r.final_temperature)
                        .set("dhugoniot_K", r.final_state.dhugoniot)
                        .set("drayleigh_bar", r.final_state.drayleigh)
                        .set("lagrangian_position_A", r.final_state.lagrangian_position))
      .set("conserved_start_eV", r.conserved_start)
      .set("conserved_end_eV", r.conserved_end)
      .set("conserved_drift_eV_per_atom", (r.conserved_end - r.conserved_start) / static_cast<double>(r.atoms));
}

HugoniotState msst_hugoniot_state(const MsstReport& r) {
  return cell_hugoniot_state(r.shock_speed, r.mean.up * A_per_ps_to_km_per_s, r.mean.pressure_axis * bar_to_GPa,
                             mean_density(r), r.density0, r.mean.temperature, r.mean.samples,
                             "msst stage: means over its second half");
}

}  // namespace shockfield::md
