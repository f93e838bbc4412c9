#include "shockfield/md/diagnostics/hugoniot.hpp"

#include <fmt/format.h>

#include <cmath>

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
  for (const Profile& p : frames) {
    if (p.time < t_fit) continue;
    const double front = front_position(p, axis, side, piston_speed);
    if (!std::isfinite(front)) continue;
    st += p.time; sx += front; stt += p.time * p.time; stx += p.time * front;
    ++n;
    const double wall = wall0 + side * piston_speed * (p.time - wall_t0);
    const double width = p.bins.size() > 1 ? std::abs(p.bins[1].position - p.bins[0].position) : 1.0;
    // The free end of the sample (partly filled bins, surface relaxation) is not bulk.
    double far_end = side > 0 ? -1e300 : 1e300;
    for (const ProfileBin& b : p.bins)
      if (b.count > 0) far_end = side > 0 ? std::max(far_end, b.position) : std::min(far_end, b.position);
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
  if (n < 3) {
    s.note = "the front was found in fewer than 3 profiles of the fit window";
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
  }
  return s;
}

std::string hugoniot_toml(const HugoniotState& s) {
  return fmt::format(
      "# Hugoniot state from the binned profiles (see docs/md.md, 'Shock diagnostics').\n"
      "us_km_s = {}\nup_km_s = {}\npiston_speed_km_s = {}\npressure_GPa = {}\n"
      "pressure_rankine_hugoniot_GPa = {}\ndensity_g_cc = {}\ndensity_rankine_hugoniot_g_cc = {}\n"
      "density0_g_cc = {}\ntemperature_K = {}\nframes_in_fit = {}\nnote = \"{}\"\n",
      s.us, s.up, s.piston_speed, s.pressure, s.pressure_rh, s.density, s.density_rh, s.density0,
      s.temperature, s.frames, s.note);
}

}  // namespace shockfield::md
