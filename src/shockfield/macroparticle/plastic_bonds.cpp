#include "shockfield/macroparticle/plastic_bonds.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace shockfield::macroparticle {

PlasticBondLaw::PlasticBondLaw(double p, double q, PlasticRoute route)
    : p_(p), q_(q), k_(p * q), powers_(p, q), route_(std::move(route)), r_y_(1.0 + route_.yield_strain),
      r_c_(1.0 - (route_.compression_yield_strain > 0 ? route_.compression_yield_strain : route_.yield_strain)) {
  // φ_E″ = 0 at r^(q−p) = (q + 1)/(p + 1): the largest tension the elastic curve can carry.
  r_inflection_ = std::pow((q_ + 1.0) / (p_ + 1.0), 1.0 / (q_ - p_));
  t_peak_ = elastic_tension(r_inflection_);
  t_yield_ = elastic_tension(r_y_);
  t_compression_yield_ = elastic_tension(r_c_);
}

double PlasticBondLaw::elastic_energy(double s) const {
  double sp, sq;
  powers_(s, sp, sq);
  return (p_ * sq - q_ * sp) / (q_ - p_);
}

double PlasticBondLaw::elastic_tension(double s) const {
  double sp, sq;
  powers_(s, sp, sq);
  return p_ * q_ / (q_ - p_) * (sp - sq) / s;
}

double PlasticBondLaw::elastic_curvature(double s) const {
  double sp, sq;
  powers_(s, sp, sq);
  return p_ * q_ / (q_ - p_) * ((q_ + 1.0) * sq - (p_ + 1.0) * sp) / (s * s);
}

double PlasticBondLaw::route_tension(double r, bool tension_side) const {
  const double u = std::min(tension_side ? r - r_y_ : r_c_ - r, route_.saturation_strain);
  double sum = 0, un = 1;
  for (double h : route_.hardening) sum += h * (un *= u);
  return tension_side ? t_yield_ + k_ * sum : t_compression_yield_ - k_ * sum;
}

bool PlasticBondLaw::stiff_branch(double t, double guess, double& s) const {
  if (t >= t_peak_) return false;
  // Newton on the monotonic branch (0, r_inflection], kept inside a shrinking bracket.
  double lo = 0.5, hi = r_inflection_;
  while (elastic_tension(lo) > t) lo *= 0.5;
  s = std::clamp(guess, lo, hi);
  // The guess is the last step's solution, a few ulps to 1e-6 away: Newton converges in 1–3
  // steps; stop when the tension matches to round-off (1e-14 of the route tension's scale k).
  for (int it = 0; it < 40; ++it) {
    const double f = elastic_tension(s) - t;
    if (std::abs(f) <= 1e-14 * k_) return true;
    if (f > 0) hi = s; else lo = s;
    double next = s - f / elastic_curvature(s);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    s = next;
  }
  return true;
}

bool PlasticBondLaw::evaluate(double r, BondState& st, double& tension, double& energy) const {
  if (st.broken) {
    tension = 0;
    energy = st.offset;
    return false;
  }
  const double t_unload = elastic_tension(r - st.shift);
  const double e_unload = elastic_energy(r - st.shift) + st.offset;  // φ_U(r), eq 16
  if (r > 1.0 + route_.limit_strain) {
    st.broken = true;
    st.offset = e_unload;
    tension = 0;
    return true;
  }
  const bool on_tension = r >= r_y_ && t_unload > route_tension(r, true);
  const bool on_compression = !on_tension && r <= r_c_ && t_unload < route_tension(r, false);
  tension = t_unload;
  energy = e_unload;
  if (r == st.r_route) {  // the state already holds this point of its route
    tension = route_tension(r, r > 1.0);
    return false;
  }
  if (!on_tension && !on_compression) return false;
  // On a route: its tension, and the curve shifted to carry it from here. The energy stays that
  // of the curve the bond came on (C_φ absorbs the change of Δr0), so it is the work ∫T dr done
  // on the bond to first order in the step, plastic work included.
  tension = route_tension(r, on_tension);
  double s = 0;
  if (!stiff_branch(tension, r - st.shift, s)) {  // more than the elastic curve's peak: it breaks
    st.broken = true;
    st.offset = e_unload;
    tension = 0;
    return true;
  }
  st.shift = r - s;                          // Δr0: T_E(r − Δr0) = T_P(r)
  st.offset = e_unload - elastic_energy(s);  // C_φ: φ_U continuous at r
  st.r_route = r;
  if (on_tension) st.r_max = std::max(st.r_max, r);
  else st.r_min = std::min(st.r_min, r);
  return true;
}

std::vector<std::vector<std::pair<std::uint64_t, BondState>>>& BondTable::pending(int nthreads) {
  pending_.resize(static_cast<std::size_t>(nthreads));
  for (auto& p : pending_) p.clear();
  return pending_;
}

void BondTable::apply_pending() {
  for (const auto& p : pending_)
    for (const auto& [k, s] : p) states_[k] = s;
  for (auto& p : pending_) p.clear();
}

std::size_t BondTable::broken() const {
  return static_cast<std::size_t>(std::count_if(states_.begin(), states_.end(), [](const auto& e) { return e.second.broken; }));
}

namespace {
constexpr std::array<const char*, 8> kBondFields{"bond_id_lo", "bond_id_hi", "shift", "offset",
                                                 "r_max",      "r_min",      "broken", "r_route"};
}  // namespace

md::FixState BondTable::state() const {
  std::vector<std::uint64_t> keys;
  keys.reserve(states_.size());
  for (const auto& e : states_) keys.push_back(e.first);
  std::sort(keys.begin(), keys.end());
  md::FixState out;
  for (const char* field : kBondFields) out.push_back({field, "1", {}});
  for (const auto k : keys) {
    const BondState& s = states_.at(k);
    // The key as two 32-bit halves: exact in doubles.
    const std::array<double, 8> row{static_cast<double>(k >> 32), static_cast<double>(k & 0xffffffffu), s.shift,
                                    s.offset, s.r_max, s.r_min, s.broken ? 1.0 : 0.0, s.r_route};
    for (std::size_t f = 0; f < row.size(); ++f) out[f].values.push_back(row[f]);
  }
  return out;
}

void BondTable::restore(const md::FixState& state, const std::string& fix) {
  states_.clear();
  const auto held = std::find_if(state.begin(), state.end(), [](const md::FixStateItem& s) { return s.name == "shift"; });
  const std::size_t n = held == state.end() ? 0 : held->values.size();
  std::array<const std::vector<double>*, 8> f{};
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = &md::fix_state_values(state, fix, kBondFields[k], n);
  for (std::size_t b = 0; b < n; ++b) {
    const auto k = (static_cast<std::uint64_t>((*f[0])[b]) << 32) | static_cast<std::uint64_t>((*f[1])[b]);
    states_[k] = {(*f[2])[b], (*f[3])[b], (*f[4])[b], (*f[5])[b], (*f[6])[b] != 0.0, (*f[7])[b]};
  }
}

}  // namespace shockfield::macroparticle
