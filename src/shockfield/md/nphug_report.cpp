#include "shockfield/md/nphug_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/core/units.hpp"

namespace shockfield::md {

using units::metal::A_per_ps_to_km_per_s;
using units::metal::amu_per_A3_to_g_per_cc;
using units::metal::bar_to_GPa;
using units::metal::mvv2e;
using units::metal::nktv2p;

const FixNphug* find_nphug(const Simulation& sim) {
  for (const auto& fix : sim.fixes)
    if (auto* h = dynamic_cast<const FixNphug*>(fix.get())) return h;
  return nullptr;
}

std::vector<std::string> nphug_thermo_columns() { return {"PHug", "dHug", "Us", "Up", "TTarget"}; }

std::vector<double> nphug_thermo_values(const Simulation& sim) {
  const FixNphug* fix = find_nphug(sim);
  if (!fix) return {NAN, NAN, NAN, NAN, NAN};
  const NphugQuantities q = fix->quantities(sim);
  return {q.pressure, q.dhugoniot, q.us, q.up, fix->last_target()};
}

namespace {

std::string style_name(const NphugSettings& s) {
  if (s.axis >= 0) return std::string(1, static_cast<char>('x' + s.axis));
  return s.npt.iso ? "iso" : "aniso";
}

}  // namespace

NphugReport make_nphug_report(const Simulation& sim, const FixNphug& fix, const std::string& stage) {
  NphugReport r;
  r.stage = stage;
  r.style = style_name(fix.settings());
  r.target_pressure = fix.settings().npt.pressure;
  r.v0 = fix.v0();
  r.p0 = fix.p0();
  r.e0 = fix.e0();
  r.density0 = fix.total_mass() / fix.v0() * amu_per_A3_to_g_per_cc;
  r.mean = fix.averages();
  if (r.mean.samples > 0) {
    const double n = r.mean.samples;
    for (double* v : {&r.mean.pressure, &r.mean.volume, &r.mean.temperature, &r.mean.energy, &r.mean.dhugoniot})
      *v /= n;
    // Eq. (3) of nphug.hpp at the means: the Rayleigh line through (V₀, p₀) and (⟨V⟩, ⟨p⟩).
    const double strain = 1.0 - r.mean.volume / r.v0;
    const double rho0 = nktv2p * mvv2e * fix.total_mass() / r.v0;
    r.us = (strain < 1e-10 || r.mean.pressure < r.p0) ? 0.0 : std::sqrt((r.mean.pressure - r.p0) / (rho0 * strain));
    r.up = strain * r.us;
    // Eq. (2) of nphug.hpp at the means.
    r.rh_lhs = r.mean.energy - r.e0;
    r.rh_rhs = 0.5 * (r.mean.pressure + r.p0) * (r.v0 - r.mean.volume) / nktv2p;
  } else {  // a stage of one step has no second half: no means (null in summary.json)
    r.mean.pressure = r.mean.volume = r.mean.temperature = r.mean.energy = r.mean.dhugoniot = NAN;
    r.us = r.up = r.rh_lhs = r.rh_rhs = NAN;
  }
  r.final_state = fix.quantities(sim);
  r.final_temperature = sim.thermo().temperature;
  r.atoms = sim.atoms.nlocal;
  return r;
}

namespace {
double mean_density(const NphugReport& r) { return r.density0 * r.v0 / r.mean.volume; }
double per_atom(const NphugReport& r, double e) { return e / static_cast<double>(r.atoms); }
}  // namespace

std::string nphug_log_line(const NphugReport& r) {
  return fmt::format(
      "[{}] Hugoniostat ({}, P = {:.4g} GPa), mean of the last half ({} steps): P = {:.3f} GPa, rho = {:.4f} g/cc "
      "(rho0 = {:.4f}), V/V0 = {:.4f}, T = {:.0f} K, Us = {:.4f} km/s, Up = {:.4f} km/s; E - E0 = {:.5f} eV/atom "
      "against 1/2 (P + P0)(V0 - V) = {:.5f} eV/atom",
      r.stage, r.style, r.target_pressure * bar_to_GPa, r.mean.samples, r.mean.pressure * bar_to_GPa,
      mean_density(r), r.density0, r.mean.volume / r.v0, r.mean.temperature, r.us * A_per_ps_to_km_per_s,
      r.up * A_per_ps_to_km_per_s, per_atom(r, r.rh_lhs), per_atom(r, r.rh_rhs));
}

Json nphug_json(const NphugReport& r) {
  return Json::object()
      .set("stage", r.stage)
      .set("style", r.style)
      .set("target_pressure_GPa", r.target_pressure * bar_to_GPa)
      .set("v0_A3", r.v0)
      .set("p0_bar", r.p0)
      .set("e0_eV", r.e0)
      .set("initial_density_g_cc", r.density0)
      .set("mean_samples", r.mean.samples)
      .set("pressure_GPa", r.mean.pressure * bar_to_GPa)
      .set("density_g_cc", mean_density(r))
      .set("volume_ratio", r.mean.volume / r.v0)
      .set("temperature_K", r.mean.temperature)
      .set("dhugoniot_K", r.mean.dhugoniot)
      .set("shock_speed_km_s", r.us * A_per_ps_to_km_per_s)
      .set("particle_speed_km_s", r.up * A_per_ps_to_km_per_s)
      .set("energy_change_eV_per_atom", per_atom(r, r.rh_lhs))
      .set("hugoniot_energy_eV_per_atom", per_atom(r, r.rh_rhs))
      .set("final", Json::object()
                        .set("pressure_GPa", r.final_state.pressure * bar_to_GPa)
                        .set("volume_A3", r.final_state.volume)
                        .set("temperature_K", r.final_temperature)
                        .set("dhugoniot_K", r.final_state.dhugoniot)
                        .set("shock_speed_km_s", r.final_state.us * A_per_ps_to_km_per_s)
                        .set("particle_speed_km_s", r.final_state.up * A_per_ps_to_km_per_s));
}

HugoniotState nphug_hugoniot_state(const NphugReport& r) {
  return cell_hugoniot_state(r.us * A_per_ps_to_km_per_s, r.up * A_per_ps_to_km_per_s, r.mean.pressure * bar_to_GPa,
                             mean_density(r), r.density0, r.mean.temperature, r.mean.samples,
                             "nphug stage: means over its second half");
}

}  // namespace shockfield::md
