#include "shockfield/macroparticle/pair_potential.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::macroparticle {

namespace {

// x^n for a small positive integer n by multiplication.
inline double int_pow(double x, int n) {
  double r = 1.0;
  for (int k = 0; k < n; ++k) r *= x;
  return r;
}

bool is_small_integer(double v) { return v == std::floor(v) && v >= 1 && v <= 32; }

}  // namespace

MacroparticlePotential::MacroparticlePotential(double p, double q, double cutoff) : p_(p), q_(q), cutoff_(cutoff) {
  if (!(p > 0) || !(q > p))
    throw InputError(fmt::format("pair style macroparticle: exponents p = {}, q = {} have no minimum (expected q > p > 0)", p, q));
  if (!(cutoff > 1.0 && cutoff < std::sqrt(2.0)))
    throw InputError(fmt::format("pair style macroparticle: cutoff {} r0 must lie between the first (r0) and second "
                                 "(√2 r0) neighbour shells", cutoff));
}

void MacroparticlePotential::check_types(const md::Atoms& atoms) const {
  if (atoms.ntypes() != 1)
    throw InputError(fmt::format("pair style macroparticle: one particle type, the system has {}", atoms.ntypes()));
}

void MacroparticlePotential::set_plasticity(const PlasticRoute& route, std::shared_ptr<BondTable> table) {
  plastic_.emplace(p_, q_, route);
  bonds_ = std::move(table);
}

void MacroparticlePotential::compute_plastic(md::Atoms& atoms, const geometry::NeighborList& list,
                                             md::ForceResult& out) {
  const double cutsq = cutoff_ * cutoff_;
  const PlasticBondLaw* law = &*plastic_;
  const BondTable* table = bonds_.get();
  auto* pending = bonds_->pending(omp_get_max_threads()).data();
  const std::int64_t* id = atoms.id.data();
  const int* owner = atoms.ghost_owner.data();
  const auto nlocal = static_cast<int>(atoms.nlocal);
  auto kernel = [=](int i, int j, double rsq, double& fpair, double& energy) {
    if (rsq >= cutsq) return false;
    const double r = std::sqrt(rsq);
    const std::int64_t idj = j < nlocal ? id[j] : id[owner[j - nlocal]];
    const std::uint64_t key = BondTable::key(id[i], idj);
    const BondState* known = table->find(key);
    double tension;
    if (!known && law->elastic_band(r)) {
      tension = law->elastic_tension(r);
      energy = law->elastic_energy(r);
    } else {
      BondState s = known ? *known : law->initial();
      if (law->evaluate(r, s, tension, energy)) pending[omp_get_thread_num()].emplace_back(key, s);
    }
    fpair = -tension / r;  // force on i = −T (x_i − x_j)/r
    return true;
  };
  md::potentials::accumulate_pair_forces(atoms, list, kernel, out, scratch_);
  bonds_->apply_pending();
}

void MacroparticlePotential::compute(md::Atoms& atoms, const geometry::NeighborList& list, md::ForceResult& out) {
  if (plastic_) {
    compute_plastic(atoms, list, out);
    return;
  }
  const double cutsq = cutoff_ * cutoff_;
  const double scale = p_ * q_ / (q_ - p_);
  const double ep = q_ / (q_ - p_), eq = p_ / (q_ - p_);
  if (is_small_integer(p_) && is_small_integer(q_)) {
    // r^-p and r^-q from r^-1 = √(r^-2) by multiplication (p, q ≤ 32).
    const int ip = static_cast<int>(p_), iq = static_cast<int>(q_);
    auto kernel = [=](int, int, double rsq, double& fpair, double& energy) {
      if (rsq >= cutsq) return false;
      const double r2inv = 1.0 / rsq;
      const double rinv = std::sqrt(r2inv);
      const double rp = int_pow(rinv, ip);
      const double rq = rp * int_pow(rinv, iq - ip);
      fpair = scale * (rq - rp) * r2inv;
      energy = eq * rq - ep * rp;
      return true;
    };
    md::potentials::accumulate_pair_forces(atoms, list, kernel, out, scratch_);
    return;
  }
  const double hp = -0.5 * p_, hq = -0.5 * q_;
  auto kernel = [=](int, int, double rsq, double& fpair, double& energy) {
    if (rsq >= cutsq) return false;
    const double rp = std::pow(rsq, hp), rq = std::pow(rsq, hq);
    fpair = scale * (rq - rp) / rsq;
    energy = eq * rq - ep * rp;
    return true;
  };
  md::potentials::accumulate_pair_forces(atoms, list, kernel, out, scratch_);
}

}  // namespace shockfield::macroparticle
