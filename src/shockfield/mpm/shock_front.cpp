#include "shockfield/mpm/shock_front.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/analysis/line_fit.hpp"
#include "shockfield/mpm/diagnostics.hpp"

namespace shockfield::mpm {

namespace {

using analysis::WeightedMoments;

// Indices into profile_quantities(dim): density first, then pressure, temperature, the velocity
// components, the longitudinal stress σ_aa, its deviator, von Mises, the bulk density last.
constexpr std::size_t kDensity = 0, kPressure = 1, kTemperature = 2;
std::size_t bulk_density(int dim) { return profile_quantities(dim).size() - 1; }
std::size_t axis_velocity(int dim) { return 3 + static_cast<std::size_t>(dim) - 1; }
std::size_t longitudinal_stress(int dim) { return 3 + static_cast<std::size_t>(dim); }

}  // namespace

double hugoniot_elastic_limit(const materials::SolidMaterial& m) {
  const double g = m.strength.shear_modulus, y0 = m.strength.yield_stress0;
  if (!(g > 0 && y0 > 0)) return 0.0;
  const double bulk = m.eos.rho0 * m.eos.c0 * m.eos.c0;
  return (bulk + 4.0 * g / 3.0) * y0 / (2.0 * g);
}

std::vector<WindowQuantity> profile_quantities(int dim) {
  std::vector<WindowQuantity> q = window_quantities(dim);
  q.push_back({"bulk_density", "kg_m3"});
  return q;
}

ShockProfile shock_profile(const Particles& p, int dim, int body, double lo, double hi, double width,
                           double cross_section, double time) {
  const int axis = dim - 1;
  const auto bins = static_cast<std::size_t>(std::max(1.0, std::ceil((hi - lo) / width - 1e-9)));
  const std::size_t nq = window_quantities(dim).size();
  ShockProfile s;
  s.time = time;
  s.mass.assign(bins, 0.0);
  s.means.assign(nq + 1, std::vector<double>(bins, 0.0));
  for (std::size_t k = 0; k < bins; ++k) s.position.push_back(lo + (static_cast<double>(k) + 0.5) * width);
  const auto last = static_cast<double>(bins - 1);
  for (std::size_t i = 0; i < p.size(); ++i) {  // particle order: independent of the thread count
    if (p.body[i] != body) continue;
    // The point's extent along the axis, its reference box stretched by F_aa (as cpGIMP's), shared
    // among the slabs it overlaps: a slab's mass does not jump as rows of points cross its faces.
    const double half = p.half_size[i][axis] * std::abs(p.state[i].deformation(axis, axis));
    const double a = (p.x[i][axis] - half - lo) / width, b = (p.x[i][axis] + half - lo) / width;
    for (double k = std::clamp(std::floor(a), 0.0, last); k <= std::clamp(std::floor(b), 0.0, last); ++k) {
      const double overlap = b > a ? (std::min(b, k + 1.0) - std::max(a, k)) / (b - a) : 1.0;
      if (!(overlap > 0.0)) continue;
      const auto u = static_cast<std::size_t>(k);
      const double m = p.mass[i] * overlap;
      s.mass[u] += m;
      for (std::size_t q = 0; q < nq; ++q) s.means[q][u] += m * quantity(p, i, q, dim);
    }
  }
  for (std::size_t q = 0; q < nq; ++q)
    for (std::size_t k = 0; k < bins; ++k) s.means[q][k] = s.mass[k] > 0.0 ? s.means[q][k] / s.mass[k] : NAN;
  // Slab mass over slab volume, voids included (the body filling the lateral extent).
  for (std::size_t k = 0; k < bins; ++k) s.means[nq][k] = s.mass[k] > 0.0 ? s.mass[k] / (width * cross_section) : NAN;
  return s;
}

FrontFrame analyse_front(const ShockProfile& profile, int dim, const ShockFrontSettings& s) {
  const std::size_t nq = profile.means.size(), sq = longitudinal_stress(dim);
  const int dir = s.direction;
  const double margin = s.margin_bins * s.bin_width;
  FrontFrame f;
  f.time = profile.time;
  f.plateau.assign(nq, WeightedMoments{});
  f.precursor_plateau.assign(nq, WeightedMoments{});
  f.ahead.assign(nq, NAN);
  std::vector<double> compression(profile.position.size());  // −σ_aa: the shocked state above the level
  double peak = -INFINITY, low_end = NAN, high_end = NAN;
  for (std::size_t k = 0; k < compression.size(); ++k) {
    compression[k] = -profile.means[sq][k];
    if (!(profile.mass[k] > 0.0)) continue;
    peak = std::max(peak, compression[k]);
    if (std::isnan(low_end)) low_end = profile.position[k];
    high_end = profile.position[k];
  }
  if (std::isnan(low_end) || !(peak > 0.0)) return f;  // no particle, or nothing compressed
  f.face = dir > 0 ? low_end : high_end;
  f.free_end = dir > 0 ? high_end : low_end;
  const auto crossing = [&](double level) {
    return analysis::front_crossing(profile.position, compression, profile.mass, level, dir);
  };
  const auto window = [&](std::size_t q, double from, double to) {
    if (!(dir * (to - from) >= 0.0)) return WeightedMoments{};
    return analysis::window_moments(profile.position, profile.means[q], profile.mass, from, to);
  };
  const auto ahead_of = [&](double leading, std::size_t q) {
    return window(q, leading + dir * margin, f.free_end - dir * margin).mean;
  };
  // The plateau: the part of [face + margin, top − margin] next to the top of the front.
  const auto plateau_behind = [&](double top, std::size_t q) {
    const double to = top - dir * margin, from = f.face + dir * margin;
    return window(q, to - s.window_fraction * (to - from), to);
  };
  // The precursor's plateau: the half of the stretch between the fronts next to the precursor
  // (the plastic front's foot reaches far ahead: it does not steepen in a linear bulk response),
  // `margin` kept from the precursor.
  const auto precursor_plateau = [&](double precursor, std::size_t q) {
    return window(q, 0.5 * (f.front + precursor), precursor - dir * margin);
  };
  // Pass 1: the state ahead of the leading edge (half the HEL, or half the peak), a first front
  // at half the peak above it and the plateau behind that.
  const double lead = crossing(s.hel > 0.0 ? std::min(0.5 * peak, 0.5 * s.hel) : 0.5 * peak);
  double ahead = -ahead_of(lead, sq);
  if (!std::isfinite(ahead)) ahead = 0.0;  // no undisturbed slab left: the body is taken as unstressed
  const double plateau = -plateau_behind(crossing(ahead + 0.5 * (peak - ahead)), sq).mean;
  if (!std::isfinite(plateau)) return f;
  // Pass 2: the front at half the plateau's jump above the HEL (two waves) or above the state ahead.
  const bool two_wave = s.hel > 0.0 && plateau - ahead > s.hel;
  f.front = crossing(ahead + 0.5 * ((two_wave ? s.hel : 0.0) + plateau - ahead));
  if (!std::isfinite(f.front)) return f;
  // The top of the front: where the compression first reaches 90 % of the jump. With the linear
  // artificial viscosity the rise is longer behind the half-jump point than ahead of it (Al at
  // 1000 m/s: u_p read 1.4 % low over a window ending 6 slabs behind the half-jump point).
  const double base = ahead + (two_wave ? s.hel : 0.0), rise = crossing(base + 0.9 * (plateau - base));
  f.rise = std::isfinite(rise) ? rise : f.front;
  if (two_wave) {
    // A second wave ahead: more than two margins ahead, and carrying the HEL. A stretch between
    // the crossings whose mean lies outside [σ_HEL/2, 2σ_HEL] above the state ahead is the foot of
    // a smeared, overdriven shock (Al's at 1000 m/s on a wall: 5σ_HEL ± 4σ_HEL), not a precursor.
    const double precursor = crossing(ahead + 0.5 * s.hel);
    if (dir * (precursor - f.front) > 2.0 * margin) {
      const double carried = -precursor_plateau(precursor, sq).mean - ahead;
      if (carried >= 0.5 * s.hel && carried <= 2.0 * s.hel) f.precursor = precursor;
    }
  }
  // The leading edge of the disturbance: the precursor, else where the compression first reaches
  // half the HEL (the foot of the shock) or half its peak.
  f.leading = std::isfinite(f.precursor) ? f.precursor : std::isfinite(lead) ? lead : f.front;
  f.at_free_end = dir * (f.free_end - f.leading) <= margin;
  for (std::size_t q = 0; q < nq; ++q) {
    f.ahead[q] = ahead_of(f.leading, q);
    f.plateau[q] = plateau_behind(f.rise, q);
    if (std::isfinite(f.precursor)) f.precursor_plateau[q] = precursor_plateau(f.precursor, q);
  }
  return f;
}

namespace {

// The state a wave runs into: σ_aa, ρ and the velocity along the shock relative to the material ahead.
struct Upstream {
  double stress = 0.0, density = NAN, velocity = 0.0;
};

template <class Position, class Plateau>
WaveState fit_wave(const std::vector<const FrontFrame*>& frames, int dim, const ShockFrontSettings& s,
                   double v_ahead, const Upstream& one, Position position, Plateau plateau_of) {
  const int dir = s.direction;
  std::vector<double> t, x;
  std::vector<std::vector<WeightedMoments>> parts(profile_quantities(dim).size());
  for (const FrontFrame* f : frames) {
    t.push_back(f->time), x.push_back(position(*f));
    for (std::size_t q = 0; q < parts.size(); ++q) parts[q].push_back(plateau_of(*f)[q]);
  }
  WaveState w;
  const analysis::LineFit line = analysis::fit_line(t, x);
  w.us = dir * line.slope - dir * v_ahead;  // relative to the material ahead
  w.us_stderr = line.slope_stderr;
  for (auto& p : parts) w.plateau.push_back(analysis::pooled_moments(p));
  w.up = dir * (w.plateau[axis_velocity(dim)].mean - v_ahead);
  // Jump conditions across a steady front (mass and momentum; e.g. Meyers 1994, ch. 4), with the
  // velocities relative to the material ahead of the leading front.
  const double flux = one.density * (w.us - one.velocity);
  w.density_rh = flux / (w.us - w.up);
  w.stress_rh = one.stress - flux * (w.up - one.velocity);
  w.frames = static_cast<int>(frames.size());
  w.fit_start = t.front(), w.fit_end = t.back();
  return w;
}

}  // namespace

ShockHugoniot fit_hugoniot(const std::vector<FrontFrame>& frames, int dim, const ShockFrontSettings& s) {
  ShockHugoniot h;
  const std::size_t sq = longitudinal_stress(dim), vq = axis_velocity(dim);
  std::vector<const FrontFrame*> found;
  double reached_end = NAN;
  for (const FrontFrame& f : frames) {
    if (!std::isfinite(f.front) || !(f.plateau[sq].weight > 0.0)) continue;
    if (f.at_free_end) {  // from here on the free surface moves and a release runs back
      reached_end = f.time;
      break;
    }
    found.push_back(&f);
  }
  const std::string free_end =
      std::isfinite(reached_end)
          ? fmt::format("the front reached the free end of the body at t = {} s; the fit uses the frames before it", reached_end)
          : "";
  std::vector<const FrontFrame*> fit;
  if (!found.empty()) {
    const double t_fit = found.front()->time + s.skip_fraction * (found.back()->time - found.front()->time);
    for (const FrontFrame* f : found)
      if (f->time >= t_fit) fit.push_back(f);
  }
  if (fit.size() < 3) {
    h.note = fmt::format("the front and a plateau behind it were found in {} frames of the fit window (3 needed): "
                         "write frames more often (series_interval), run longer or use a longer body{}",
                         fit.size(), free_end.empty() ? "" : "; " + free_end);
    return h;
  }
  h.ahead.assign(profile_quantities(dim).size(), 0.0);
  for (std::size_t q = 0; q < h.ahead.size(); ++q) {
    double n = 0.0;
    for (const FrontFrame* f : fit)
      if (std::isfinite(f->ahead[q])) h.ahead[q] += f->ahead[q], n += 1.0;
    h.ahead[q] = n > 0 ? h.ahead[q] / n : NAN;
  }
  const double v_ahead = std::isfinite(h.ahead[vq]) ? h.ahead[vq] : 0.0;
  const std::size_t bq = bulk_density(dim);
  const Upstream undisturbed{std::isfinite(h.ahead[sq]) ? h.ahead[sq] : 0.0, h.ahead[bq], 0.0};
  Upstream into_shock = undisturbed;
  std::vector<const FrontFrame*> with_precursor;
  for (const FrontFrame* f : fit)
    if (std::isfinite(f->precursor) && f->precursor_plateau[sq].weight > 0.0) with_precursor.push_back(f);
  if (with_precursor.size() >= 3) {
    h.precursor = fit_wave(with_precursor, dim, s, v_ahead, undisturbed, [](const FrontFrame& f) { return f.precursor; },
                           [](const FrontFrame& f) -> const std::vector<WeightedMoments>& { return f.precursor_plateau; });
    into_shock = {h.precursor->plateau[sq].mean, h.precursor->plateau[bq].mean, h.precursor->up};
  }
  h.shock = fit_wave(fit, dim, s, v_ahead, into_shock, [](const FrontFrame& f) { return f.front; },
                     [](const FrontFrame& f) -> const std::vector<WeightedMoments>& { return f.plateau; });
  if (!std::isfinite(h.ahead[bq]))
    h.note = "no undisturbed slab ahead of the front (initial density unknown): use a longer body or stop earlier";
  if (!free_end.empty() && h.note.empty()) h.note = free_end;
  if (!h.complete() && h.note.empty()) h.note = "a value of the Hugoniot state is not finite";
  return h;
}

bool ShockHugoniot::complete() const {
  if (shock.plateau.empty() || ahead.empty()) return false;
  for (double v : {shock.us, shock.up, shock.density_rh, shock.stress_rh, ahead[kDensity], ahead.back()})
    if (!std::isfinite(v)) return false;
  return std::all_of(shock.plateau.begin(), shock.plateau.end(), [](const WeightedMoments& m) { return std::isfinite(m.mean); });
}

namespace {

void add(std::string& text, const std::string& key, double value) {
  if (std::isfinite(value)) text += fmt::format("{} = {}\n", key, value);
}

// us, up, the plateau's means named as MD's state (density, pressure, temperature) and the
// stresses, the jump conditions and the fit's extent.
std::string wave_keys(const WaveState& w, int dim) {
  std::string text;
  const auto mean = [&](std::size_t q) { return w.plateau.empty() ? NAN : w.plateau[q].mean; };
  const std::size_t sq = longitudinal_stress(dim);
  add(text, "us_m_s", w.us);
  add(text, "us_stderr_m_s", w.us_stderr);
  add(text, "up_m_s", w.up);
  add(text, "density_kg_m3", mean(kDensity));
  add(text, "bulk_density_kg_m3", w.plateau.empty() ? NAN : w.plateau.back().mean);
  add(text, "density_rankine_hugoniot_kg_m3", w.density_rh);
  add(text, "pressure_Pa", mean(kPressure));
  add(text, "longitudinal_stress_Pa", mean(sq));
  add(text, "longitudinal_stress_rankine_hugoniot_Pa", w.stress_rh);
  add(text, "longitudinal_deviator_Pa", mean(sq + 1));
  add(text, "von_mises_Pa", mean(sq + 2));
  add(text, "temperature_K", mean(kTemperature));
  add(text, "fit_start_s", w.fit_start);
  add(text, "fit_end_s", w.fit_end);
  text += fmt::format("frames_in_fit = {}\n", w.frames);
  return text;
}

std::string plateau_table(const std::string& name, const WaveState& w, int dim) {
  std::string text = fmt::format("\n[{}]  # mean and scatter (mass-weighted std over slabs and frames) behind the front\n", name);
  const auto quantities = profile_quantities(dim);
  for (std::size_t q = 0; q < quantities.size() && q < w.plateau.size(); ++q) {
    add(text, quantities[q].name + "_mean_" + quantities[q].unit, w.plateau[q].mean);
    add(text, quantities[q].name + "_std_" + quantities[q].unit, w.plateau[q].std);
  }
  return text;
}

}  // namespace

std::string hugoniot_toml(const ShockHugoniot& h, int dim, const std::string& title) {
  std::string text = fmt::format("# {} (docs/mpm.md: 'Shock front and Hugoniot')\n", title);
  text += wave_keys(h.shock, dim);
  if (!h.ahead.empty()) add(text, "density0_kg_m3", h.ahead[kDensity]);
  if (!h.ahead.empty()) add(text, "bulk_density0_kg_m3", h.ahead.back());
  if (!h.ahead.empty()) add(text, "velocity_ahead_m_s", h.ahead[axis_velocity(dim)]);
  text += fmt::format("two_wave = {}\ncomplete = {}\nnote = \"{}\"\n", h.precursor.has_value(), h.complete(), h.note);
  text += plateau_table("plateau", h.shock, dim);
  if (h.precursor) {
    text += "\n[precursor]  # the elastic precursor ahead of the plastic front\n" + wave_keys(*h.precursor, dim);
    text += plateau_table("precursor.plateau", *h.precursor, dim);
  }
  return text;
}

}  // namespace shockfield::mpm
