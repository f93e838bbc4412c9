#include "shockfield/md/diagnostics/hugoniot.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "shockfield/core/units.hpp"

namespace shockfield::md {

using units::metal::A_per_ps_to_km_per_s;

double front_position(const Profile& p, int axis, int side, double piston_speed) {
  const int n = static_cast<int>(p.bins.size());
  const double half = 0.5 * piston_speed;
  // Walk from the undisturbed end towards the piston.
  for (int k = 0; k < n; ++k) {
    const int b = side > 0 ? n - 1 - k : k;
    if (p.bins[b].count == 0) continue;
    const double u = side * p.bins[b].velocity[axis];
    if (u <= half) continue;
    const int ahead = b + side;
    if (ahead < 0 || ahead >= n || p.bins[ahead].count == 0) return p.bins[b].position;
    const double ua = side * p.bins[ahead].velocity[axis];
    const double f = (u - half) / (u - ua);
    return p.bins[b].position + f * (p.bins[ahead].position - p.bins[b].position);
  }
  return NAN;
}

HugoniotState extract_hugoniot(const std::vector<Profile>& frames, int axis, int side,
                               double piston_speed, double wall0, double wall_t0,
                               double skip_fraction, int margin_bins) {
  HugoniotState s;
  s.piston_speed = piston_speed * A_per_ps_to_km_per_s;
  if (frames.size() < 3) {
    s.note = "fewer than 3 profiles: write profiles more often";
    return s;
  }
  const double t_first = frames.front().time, t_last = frames.back().time;
  const double t_fit = t_first + skip_fraction * (t_last - t_first);
  // Least-squares line through (t, front).
  double st = 0, sx = 0, stt = 0, stx = 0;
  int n = 0;
  double rho = 0, up = 0, temp = 0, press = 0, rho0 = 0, weight = 0, weight0 = 0;
  double reached_end_at = NAN;  // time of the first profile whose front is at the free end
  for (const Profile& p : frames) {
    if (p.time < t_fit) continue;
    const double front = front_position(p, axis, side, piston_speed);
    if (!std::isfinite(front)) continue;
    const double wall = wall0 + side * piston_speed * (p.time - wall_t0);
    const double width = p.bins.size() > 1 ? std::abs(p.bins[1].position - p.bins[0].position) : 1.0;
    // The free end of the sample (partly filled bins, surface relaxation) is not bulk.
    double far_end = side > 0 ? -1e300 : 1e300;
    for (const ProfileBin& b : p.bins)
      if (b.count > 0) far_end = side > 0 ? std::max(far_end, b.position) : std::min(far_end, b.position);
    // A front within the margin of the free end has no undisturbed material ahead of it; from
    // then on the free surface moves and a release wave runs back: no later profile is a
    // steady shock.
    if (side * (far_end - front) <= margin_bins * width) {
      reached_end_at = p.time;
      break;
    }
    st += p.time; sx += front; stt += p.time * p.time; stx += p.time * front;
    ++n;
    for (const ProfileBin& b : p.bins) {
      if (b.count == 0) continue;
      const double from_wall = side * (b.position - wall), to_front = side * (front - b.position);
      if (from_wall > margin_bins * width && to_front > margin_bins * width) {
        rho += b.count * b.density;
        up += b.count * side * b.velocity[axis];
        temp += b.count * b.temperature;
        press += b.count * b.pressure[axis];
        weight += b.count;
      } else if (to_front < -margin_bins * width && side * (far_end - b.position) > margin_bins * width) {
        rho0 += b.count * b.density;
        weight0 += b.count;
      }
    }
  }
  s.frames = n;
  const std::string free_end =
      std::isfinite(reached_end_at)
          ? fmt::format("the shock front reached the free end of the sample at t = {} ps: make the sample longer or "
                        "the stage shorter",
                        reached_end_at)
          : "";
  if (n < 3) {
    s.note = free_end.empty() ? "the front was found in fewer than 3 profiles of the fit window"
                              : free_end + " (fewer than 3 profiles of the fit window came before)";
    return s;
  }
  const double denom = n * stt - st * st;
  s.us = side * (n * stx - st * sx) / denom * A_per_ps_to_km_per_s;
  if (weight > 0) {
    s.density = rho / weight;
    s.up = up / weight * A_per_ps_to_km_per_s;
    s.temperature = temp / weight;
    s.pressure = press / weight;
  } else {
    s.note = "no bins between the piston and the front: run longer or use thinner bins";
  }
  if (weight0 > 0) {
    s.density0 = rho0 / weight0;
    // ρ [g/cm³] · U [km/s] · U [km/s] = GPa.
    s.pressure_rh = s.density0 * s.us * s.up;
    s.density_rh = s.density0 * s.us / (s.us - s.up);
  } else if (s.note.empty()) {
    s.note = "no undisturbed bins ahead of the front (initial density unknown): make the sample longer or the stage "
             "shorter";
  }
  if (!free_end.empty() && s.note.empty()) s.note = free_end + "; the fit uses the profiles before it";
  if (!s.complete() && s.note.empty()) s.note = "a value of the Hugoniot state is not finite";
  return s;
}

bool HugoniotState::complete() const {
  for (double v : {us, up, piston_speed, pressure, pressure_rh, density, density_rh, density0, temperature})
    if (!std::isfinite(v)) return false;
  return true;
}

HugoniotState cell_hugoniot_state(double us, double up, double pressure, double density, double density0,
                                  double temperature, double samples, std::string note) {
  HugoniotState h;
  h.us = us;
  h.up = h.piston_speed = up;
  h.pressure = pressure;
  h.pressure_rh = density0 * us * up;  // g/cm³ · km²/s² = GPa
  h.density = density;
  h.density_rh = density0 * us / (us - up);
  h.density0 = density0;
  h.temperature = temperature;
  h.frames = static_cast<int>(samples);
  h.note = std::move(note);
  return h;
}

std::string hugoniot_toml(const HugoniotState& s) {
  // TOML has no "missing": a value that could not be measured is left out (never written as
  // nan), `complete` says whether all are there and `note` why not.
  std::string text = "# Hugoniot state (docs/md.md: 'Shock diagnostics' for a piston stage, msst and nphug for theirs).\n";
  const std::pair<const char*, double> values[] = {
      {"us_km_s", s.us}, {"up_km_s", s.up}, {"piston_speed_km_s", s.piston_speed}, {"pressure_GPa", s.pressure},
      {"pressure_rankine_hugoniot_GPa", s.pressure_rh}, {"density_g_cc", s.density},
      {"density_rankine_hugoniot_g_cc", s.density_rh}, {"density0_g_cc", s.density0},
      {"temperature_K", s.temperature}};
  for (const auto& [key, value] : values)
    if (std::isfinite(value)) text += fmt::format("{} = {}\n", key, value);
  text += fmt::format("frames_in_fit = {}\ncomplete = {}\nnote = \"{}\"\n", s.frames, s.complete(), s.note);
  return text;
}

}  // namespace shockfield::md
