#include "shockfield/pd/bond_force.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::pd {

template <class Model>
BondForce<Model>::BondForce(const PointCloud& cloud, const Family& family, Model model, Influence influence,
                            CriticalStretch damage, bool contact)
    : cloud_(cloud), family_(family), model_(model), damage_law_(damage) {
  if (contact) contact_.emplace(cloud, model.contact_micromodulus(family.horizon), family.horizon);
  const std::size_t n = cloud.size();
  omega_.resize(family.bonds());
  weighted_volume_.assign(n, 0.0);
  // PMB has no influence function in LAMMPS (ω = 1 in its weighted volume).
  for (std::size_t i = 0; i < n; ++i)
    for (int b = family.begin(i); b < family.end(i); ++b) {
      const double r0 = family.length[b];
      omega_[b] = Model::uses_dilatation ? influence(r0, family.horizon) : 1.0;
      weighted_volume_[i] += omega_[b] * r0 * r0 * cloud.volume[family.neighbor[b]] * family.volume_scale[b];
    }
  if constexpr (LinearInStretch<Model>) {
    bond_constant_.resize(family.bonds());
    for (std::size_t b = 0; b < family.bonds(); ++b)
      bond_constant_[b] = model.bond_constant(cloud.volume[family.neighbor[b]], family.volume_scale[b]);
  }
  theta_.assign(n, 0.0);
  intact_.assign(family.bonds(), 1);
  s0_.assign(n, std::numeric_limits<double>::max());
  s0_new_ = s0_;
}

template <class Model>
void BondForce<Model>::break_bonds(const std::vector<unsigned char>& cut) {
  if (cut.size() != intact_.size())
    throw InputError(fmt::format("pd {}: {} cut flags for {} bonds", name(), cut.size(), intact_.size()));
  for (std::size_t b = 0; b < cut.size(); ++b)
    if (cut[b]) intact_[b] = 0;
}

template <class Model>
void BondForce<Model>::set_ghost_forward(std::function<void(std::vector<double>&)> forward) {
  forward_ = std::move(forward);
  forward_(weighted_volume_);
}

template <class Model>
BondTerms BondForce<Model>::terms(std::size_t i, int b, double e) const {
  const auto j = static_cast<std::size_t>(family_.neighbor[b]);
  return {family_.length[b], e, omega_[b], theta_[i], theta_[j], weighted_volume_[i], weighted_volume_[j]};
}

template <class Model>
void BondForce<Model>::compute_dilatation(const std::vector<Vec3>& y) {
  if constexpr (!Model::uses_dilatation) {
    return;
  } else {
    // Per bond, not through BondStretches: this sum needs only e, and the staged arrays cost LPS
    // more than the packed square roots save here (measured, bench/RESULTS.md).
    const auto n = static_cast<std::ptrdiff_t>(cloud_.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t si = 0; si < n; ++si) {
      const auto i = static_cast<std::size_t>(si);
      double sum = 0.0;
      for (int b = family_.begin(i); b < family_.end(i); ++b) {
        if (!intact_[b]) continue;
        const int j = family_.neighbor[b];
        double e = (y[j] - y[i]).norm() - family_.length[b];
        if (std::abs(e) < kNearZeroExtension) e = 0.0;
        sum += omega_[b] * family_.length[b] * e * cloud_.volume[j] * family_.volume_scale[b];
      }
      theta_[i] = weighted_volume_[i] != 0.0 ? model_.dilatation_factor() * sum / weighted_volume_[i] : 0.0;
    }
  }
}

template <class Model>
void BondForce<Model>::compute(const Kinematics& k, std::vector<Vec3>& force_density) {
  const auto& y = k.y;
  if (forward_ && damage_law_.enabled()) forward_(s0_);
  if constexpr (Model::uses_dilatation) {
    compute_dilatation(y);
    if (forward_) forward_(theta_);
  }
  if (contact_) contact_->update(y);
  force_density.resize(cloud_.size());
  if (damage_law_.enabled())
    bond_loop<true>(y, force_density);
  else
    bond_loop<false>(y, force_density);
  if (damage_law_.enabled()) std::swap(s0_, s0_new_);
}

template <class Model>
void BondForce<Model>::bond_pull(std::size_t i, BondStretches& bonds) const {
  const int b0 = family_.begin(i);
  const auto m = static_cast<std::size_t>(family_.end(i) - b0);
  if constexpr (LinearInStretch<Model>) {
    const double* k_b = bond_constant_.data() + b0;
    for (std::size_t k = 0; k < m; ++k) bonds.pull[k] = k_b[k] * bonds.stretch[k];
  } else {
    const Model model = model_;  // a local copy: the stores to pull cannot alias its moduli
    for (std::size_t k = 0; k < m; ++k) {
      const int b = b0 + static_cast<int>(k);
      bonds.pull[k] = model.force(terms(i, b, bonds.extension[k])) * cloud_.volume[family_.neighbor[b]] *
                      family_.volume_scale[b];
    }
  }
  bonds.divide_pull_by_length(m);
}

template <class Model>
template <bool kDamage>
void BondForce<Model>::bond_loop(const std::vector<Vec3>& y, std::vector<Vec3>& force_density) {
  for_each_point_measured(y, [&](std::size_t i, BondStretches& bonds) {
    // Contact first, then the bonds, in the order LAMMPS adds them (pair_peri_*.cpp).
    const Vec3 contact = contact_ ? contact_->force_density(i, y) : Vec3::Zero();
    bond_pull(i, bonds);
    const int b0 = family_.begin(i), m = family_.end(i) - b0;
    // Locals for everything the loop reads: its stores to intact_ (unsigned char) may alias any
    // object, so members read through `this` would be reloaded for every bond.
    const double *pull = bonds.pull.data(), *dx = bonds.dx.data(), *dy = bonds.dy.data(), *dz = bonds.dz.data();
    const double* stretch = bonds.stretch.data();
    const int* neighbor = family_.neighbor.data() + b0;
    const double* s0 = s0_.data();
    unsigned char* intact = intact_.data() + b0;
    const double s0_i = s0[i], s00 = damage_law_.s00, alpha = damage_law_.alpha;
    double fx = contact[0], fy = contact[1], fz = contact[2];
    double s0_next = std::numeric_limits<double>::lowest();
    bool any = false;
    for (int k = 0; k < m; ++k) {
      if (!intact[k]) continue;
      fx += pull[k] * dx[k];
      fy += pull[k] * dy[k];
      fz += pull[k] * dz[k];
      if constexpr (kDamage) {
        // LAMMPS: break when s > min(s0_i, s0_j) of the previous step; s0_i of the next step is
        // the largest s00 − α·s over i's bonds intact at the start of this one.
        if (stretch[k] > std::min(s0_i, s0[neighbor[k]])) intact[k] = 0;
        s0_next = std::max(s0_next, s00 - alpha * stretch[k]);
        any = true;
      }
    }
    force_density[i] = Vec3(fx, fy, fz);
    if constexpr (kDamage) s0_new_[i] = any ? s0_next : std::numeric_limits<double>::max();
  });
}

template <class Model>
template <class PerPoint>
void BondForce<Model>::for_each_point_measured(const std::vector<Vec3>& y, PerPoint&& per_point) {
  const auto n = static_cast<std::ptrdiff_t>(cloud_.size());
#pragma omp parallel
  {
    BondStretches bonds;  // one per thread, reused point after point
#pragma omp for schedule(static)
    for (std::ptrdiff_t si = 0; si < n; ++si) {
      const auto i = static_cast<std::size_t>(si);
      bonds.measure(family_, i, y);
      per_point(i, bonds);
    }
  }
}

template <class Model>
double BondForce<Model>::stable_step(const std::vector<double>& density) const {
  // Silling & Askari (2005): Δt_i = √(2ρ_i / Σ_j V_j·β·k_ij), with k_ij = ∂t/∂e; for LPS the
  // dilatation coupling adds its row sum |A|·(d/m_i²)·(Σ_j ω r0 V β)²·2 (A = 3K − 5G in 3D).
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    double row = 0.0, lever = 0.0;
    for (int b = family_.begin(i); b < family_.end(i); ++b) {
      const double vb = cloud_.volume[family_.neighbor[b]] * family_.volume_scale[b];
      row += model_.stiffness(terms(i, b, 0.0)) * vb;
      lever += omega_[b] * family_.length[b] * vb;
    }
    if constexpr (Model::uses_dilatation)
      if (weighted_volume_[i] > 0.0)
        row += 2.0 * model_.dilatation_coupling() * model_.dilatation_factor() * lever * lever /
               (weighted_volume_[i] * weighted_volume_[i]);
    if (row > 0.0) dt = std::min(dt, std::sqrt(2.0 * density[i] / row));
  }
  return dt;
}

template <class Model>
std::vector<double> BondForce<Model>::damage() const {
  std::vector<double> phi(cloud_.size(), 0.0);
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    double all = 0.0, broken = 0.0;
    for (int b = family_.begin(i); b < family_.end(i); ++b) {
      const double vb = cloud_.volume[family_.neighbor[b]];
      all += vb;
      if (!intact_[b]) broken += vb;
    }
    phi[i] = all > 0.0 ? broken / all : 0.0;
  }
  return phi;
}

template <class Model>
std::vector<double> BondForce<Model>::energy_density(const std::vector<Vec3>& y) {
  compute_dilatation(y);
  std::vector<double> w(cloud_.size(), 0.0);
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    w[i] = model_.point_energy(theta_[i]);
    for (int b = family_.begin(i); b < family_.end(i); ++b) {
      if (!intact_[b]) continue;
      const int j = family_.neighbor[b];
      const double e = (y[j] - y[i]).norm() - family_.length[b];
      w[i] += model_.bond_energy(terms(i, b, e)) * cloud_.volume[j] * family_.volume_scale[b];
    }
  }
  return w;
}

template <class Model>
double BondForce<Model>::potential_energy(const std::vector<Vec3>& y) {
  const std::vector<double> w = energy_density(y);
  double u = 0.0;
  for (std::size_t i = 0; i < cloud_.size(); ++i) u += cloud_.volume[i] * w[i];
  return contact_ ? u + contact_->energy(y) : u;
}

template <class Model>
std::size_t BondForce<Model>::intact_bonds() const {
  return static_cast<std::size_t>(std::count(intact_.begin(), intact_.end(), 1));
}

template <class Model>
ModelState BondForce<Model>::saved_state() const {
  ModelStateArray intact{"bond_intact", "1", intact_.size(), {}, true, {}, {}};
  intact.counts.assign(intact_.begin(), intact_.end());
  return {std::move(intact), {"critical_stretch", "1", s0_.size(), {}, false, s0_, {}}};
}

template <class Model>
void BondForce<Model>::restore_state(const ModelState& state) {
  const std::vector<std::int64_t>& intact = saved_array(state, name(), "bond_intact", intact_.size(), 1, true).counts;
  const std::vector<double>& s0 = saved_array(state, name(), "critical_stretch", s0_.size(), 1, false).reals;
  std::transform(intact.begin(), intact.end(), intact_.begin(), [](std::int64_t flag) { return flag != 0 ? 1 : 0; });
  std::copy(s0.begin(), s0.end(), s0_.begin());
}

template <class Model>
std::string BondForce<Model>::name() const {
  return Model::uses_dilatation ? "lps" : "pmb";
}

template class BondForce<PmbModel>;
template class BondForce<LpsModel>;

}  // namespace shockfield::pd
