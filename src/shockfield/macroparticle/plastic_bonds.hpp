#pragma once
// The plastic pair law of Saitoh et al. (eq 16, Fig 2), per bond, in the engine's reduced units
// (r0 = D = 1, k = φ_E″(1) = pq). With T(r) = dφ/dr the bond's tension:
//   elastic      φ_E(r) = [p r^-q − q r^-p]/(q − p)                     (eq 5)
//   plastic      T_P(r) = T_E(r_y) + k Σ_n h_n (r − r_y)^n,  r ≥ r_y = 1 + ε_y    (tension route)
//                T_P(r) = T_E(r_c) − k Σ_n h_n (r_c − r)^n,  r ≤ r_c = 1 − ε_c    (compression route)
//                (ε_c = ε_y unless the compression yield strain is given)
//                (φ_P = ∫ T_P dr: polynomials in r, the paper's "φ_P is just a polynomial of r_ij");
//                with a saturation strain ε_s the route's tension stops changing at r − r_y = ε_s
//                (r_c − r = ε_s): T_P(r) = T_P(r_y + ε_s) beyond it, a perfectly plastic bond
//   unloading    φ_U(r) = φ_E(r − Δr0) + C_φ                            (eq 16)
// A bond whose shifted elastic tension T_E(r − Δr0) passes a route follows the route; there Δr0
// is set so that T_E(r − Δr0) = T_P(r) on the stiff branch (r − Δr0 below the inflection of φ_E)
// and C_φ so that φ_U stays continuous at r: force and energy are continuous where unloading
// starts, reloading meets the route where it left it (Fig 2), and the energy is the work ∫T dr
// done on the bond (to first order in the step along a route, whatever the path). Beyond the
// limit separation 1 + ε_limit (or a route tension above the elastic curve's peak) the bond
// breaks: no force, constant energy.
// The state lives in a BondTable keyed by the particles' ids, so neighbour-list rebuilds keep it;
// FixBondHistory puts it into md's checkpoints.
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "shockfield/macroparticle/inverse_powers.hpp"
#include "shockfield/md/fix.hpp"

namespace shockfield::macroparticle {

struct BondState {
  double shift = 0;        ///< Δr0
  double offset = 0;       ///< C_φ
  double r_max = 0, r_min = 0;  ///< farthest separations reached on the routes (diagnostic)
  bool broken = false;
  /// The separation of the last update: evaluating there again changes nothing (a resumed run
  /// re-evaluates the checkpointed step and must leave the states bitwise as they were).
  double r_route = -1;
};

struct PlasticRoute {
  double yield_strain = 0;           ///< ε_y of the bond (tension route)
  std::vector<double> hardening;     ///< h_1, h_2, ... as fractions of k
  double limit_strain = 1e300;       ///< the bond breaks beyond 1 + ε_limit
  double saturation_strain = 1e300;  ///< ε_s: the route's tension is constant beyond r_y + ε_s
  double compression_yield_strain = 0;  ///< ε_c: the compression route starts at 1 − ε_c (0: ε_y)
};

class PlasticBondLaw {
 public:
  PlasticBondLaw(double p, double q, PlasticRoute route);
  /// Tension T = dφ/dr and energy φ of a bond at separation r in state `s`; returns true when the
  /// bond is (or stays) off its elastic curve and `s` was updated.
  bool evaluate(double r, BondState& s, double& tension, double& energy) const;
  /// True when a bond in its initial state is elastic at r (no table entry needed).
  bool elastic_band(double r) const { return r > r_c_ && r < r_y_; }
  BondState initial() const { return {0.0, 0.0, r_y_, r_c_, false, -1.0}; }
  double elastic_tension(double s) const;
  double elastic_energy(double s) const;

 private:
  double elastic_curvature(double s) const;
  double route_tension(double r, bool tension_side) const;
  /// s with T_E(s) = t on the stiff branch (s below the inflection); false if t exceeds T_E's peak.
  bool stiff_branch(double t, double guess, double& s) const;

  double p_, q_, k_;
  InversePowers powers_;
  PlasticRoute route_;
  double r_y_, r_c_, r_inflection_, t_peak_;
  double t_yield_, t_compression_yield_;  ///< T_E(r_y), T_E(r_c): where the routes start
};

/// Bond states by pair of particle ids; updates found during a force evaluation are collected
/// per thread and applied after it (each bond is visited once per evaluation, so the table does
/// not depend on the thread count).
class BondTable {
 public:
  static std::uint64_t key(std::int64_t a, std::int64_t b) {
    const auto lo = static_cast<std::uint64_t>(a < b ? a : b), hi = static_cast<std::uint64_t>(a < b ? b : a);
    return (lo << 32) | hi;
  }
  const BondState* find(std::uint64_t k) const {
    const auto it = states_.find(k);
    return it == states_.end() ? nullptr : &it->second;
  }
  /// Per-thread buffers of updates for one evaluation.
  std::vector<std::vector<std::pair<std::uint64_t, BondState>>>& pending(int nthreads);
  void apply_pending();
  std::size_t size() const { return states_.size(); }
  std::size_t broken() const;
  /// The table for checkpoints, one variable per bond field in the order of the sorted keys:
  /// bond_id_lo, bond_id_hi (the pair's particle ids), shift, offset, r_max, r_min, broken (1/0),
  /// r_route (the engine's reduced units); restore() reads it back (InputError on a mismatch).
  md::FixState state() const;
  void restore(const md::FixState& state, const std::string& fix);

 private:
  std::unordered_map<std::uint64_t, BondState> states_;
  std::vector<std::vector<std::pair<std::uint64_t, BondState>>> pending_;
};

/// Carries the bond table through md's checkpoints (Fix::state/restore); does nothing in a step.
class FixBondHistory final : public md::Fix {
 public:
  explicit FixBondHistory(std::shared_ptr<BondTable> table) : table_(std::move(table)) {}
  std::string name() const override { return "bond_history"; }
  md::FixState state() const override { return table_->state(); }
  void restore(const md::FixState& s) override { table_->restore(s, name()); }

 private:
  std::shared_ptr<BondTable> table_;
};

}  // namespace shockfield::macroparticle
