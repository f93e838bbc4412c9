#include "shockfield/dbm/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::dbm {
namespace {

double dof_of(const BgkSettings& s) {
  if (!(s.gamma > 1.0 && s.gamma <= 2.0))
    throw InputError(fmt::format(
        "gamma = {} is outside (1, 2]: a 2D DBM has b = 2/(gamma-1) >= 2 degrees of freedom",
        s.gamma));
  return 2.0 / (s.gamma - 1.0);
}

}  // namespace

Simulation::Simulation(VelocityModel model, const Lattice& lattice, const Boundaries& boundaries,
                       const BgkSettings& settings, bool allocate_now)
    : model_(std::move(model)),
      inversion_(model_),
      lattice_(lattice),
      settings_(settings),
      b_(dof_of(settings)),
      ghosts_(model_, inversion_, b_, lattice_, boundaries) {
  if (!(settings.tau > 0.0) || !std::isfinite(settings.tau))
    throw InputError(fmt::format("tau = {} must be a positive number", settings.tau));
  if (!(settings.dt > 0.0) || !std::isfinite(settings.dt))
    throw InputError(fmt::format("dt = {} must be a positive number", settings.dt));
  if (settings.dt / settings.tau > BgkSettings::max_dt_over_tau)
    throw InputError(fmt::format(
        "dt/tau = {:.3g} > {}: the explicit collision term is unstable; use dt <= {:.4g} or a "
        "larger tau",
        settings.dt / settings.tau, BgkSettings::max_dt_over_tau,
        BgkSettings::max_dt_over_tau * settings.tau));
  const double courant = model_.max_speed() * settings.dt / std::min(lattice.dx, lattice.dy);
  if (courant > BgkSettings::max_courant)
    throw InputError(fmt::format(
        "Courant number max|v| dt/dx = {:.3g} > {} (max|v| = {:.4g}): the convection is "
        "unstable; use dt <= {:.4g}",
        courant, BgkSettings::max_courant, model_.max_speed(),
        BgkSettings::max_courant * std::min(lattice.dx, lattice.dy) / model_.max_speed()));
  if (settings.filter_state && !settings.spectral_convection)
    throw InputError("the state filter acts on FFT spectra and needs spectral convection");
  if (settings.spectral_convection) {
    for (const BoundarySide& s : boundaries.side)
      if (s.kind != BoundaryKind::periodic)
        throw InputError("spectral (FFT) convection needs periodic boundaries on all four sides");
  }
  if (allocate_now) allocate();
}

void Simulation::allocate() {
  const std::size_t n = lattice_.cells() * static_cast<std::size_t>(model_.size());
  if (f_.size() == n) return;
  if (settings_.spectral_convection) {
    spectral_ = std::make_unique<PeriodicSpectral>(lattice_.nx, lattice_.ny, lattice_.dx, lattice_.dy);
    convection_.assign(spectral_->size() * model_.size(), 0.0);
    const auto batch = [&](int count) {
      return std::unique_ptr<VelocityPlans>(new VelocityPlans{
          {*spectral_, count, lattice_.stride(), lattice_.cells()}, {*spectral_, count, lattice_.nx, spectral_->size()}});
    };
    full_batch_ = batch(std::min(kVelocityBatch, model_.size()));
    if (model_.size() > kVelocityBatch && model_.size() % kVelocityBatch != 0)
      last_batch_ = batch(model_.size() % kVelocityBatch);
  }
  f_.assign(n, 0.0);
  f1_.assign(n, 0.0);
  work_.assign(n, 0.0);
}

double Simulation::bytes(const Lattice& lattice, const VelocityModel& model, bool spectral_convection) {
  // f, f1 and work (ghosts included), and with spectral convection v·∇f of every velocity
  // (interior cells) and the FFT's two complex work arrays of half the cells.
  const double q = model.size(), cells = static_cast<double>(lattice.cells());
  const double interior = static_cast<double>(lattice.nx) * lattice.ny;
  return 8.0 * (3.0 * q * cells + (spectral_convection ? q * interior + 2.0 * interior : 0.0));
}

void Simulation::initialize(const std::function<Macro(double, double)>& state) {
  const std::size_t N = lattice_.cells();
  std::vector<double> eq(model_.size());
  for (int j = 0; j < lattice_.ny; ++j)
    for (int i = 0; i < lattice_.nx; ++i) {
      const Macro m = state(lattice_.x(i), lattice_.y(j));
      inversion_.equilibrium(m.rho, m.ux, m.uy, m.T, b_, eq.data());
      for (int k = 0; k < model_.size(); ++k) f_[k * N + lattice_.at(i, j)] = eq[k];
    }
  fill_ghosts(f_);
}

void Simulation::fill_ghosts(std::vector<double>& f) const {
  if (!halo_) return ghosts_.fill(f);
  for (int axis = 0; axis < 2; ++axis) {
    halo_->exchange(f.data(), axis);
    for (int high = 0; high < 2; ++high)
      if (!halo_->has_neighbour(axis, high)) ghosts_.fill_side(f, 2 * axis + high);
  }
}

Macro Simulation::macro(int i, int j) const {
  return macro_of(model_, f_.data() + lattice_.at(i, j), lattice_.cells(), b_);
}

const Simulation::VelocityPlans& Simulation::plans(int b) const {
  return last_batch_ && b == velocity_batches() - 1 ? *last_batch_ : *full_batch_;
}

namespace {

/// Forward transforms of the velocities of f (batch b's first interior cell at first(b), plans(b)),
/// op(spectrum, k) on velocity k's spectrum, back(b, spectra) for the batch's inverse transform.
/// Batches spread over the threads, each transform serial: the same numbers for any thread count.
template <class First, class Plans, class Op, class Back>
void over_velocity_spectra(int batches, int per_batch, std::size_t spectrum_size, First first, Plans plans, Op op,
                           Back back) {
#pragma omp parallel
  {
    std::vector<std::complex<double>> s(spectrum_size * per_batch);
#pragma omp for schedule(static)
    for (int b = 0; b < batches; ++b) {
      const SpectralBatch& forward = plans(b).ghosted;
      forward.forward(first(b), s.data());
      for (int m = 0; m < forward.count(); ++m) op(s.data() + m * spectrum_size, b * per_batch + m);
      back(b, s.data());
    }
  }
}

}  // namespace

void Simulation::spectral_convection(const std::vector<double>& f) {
  const std::size_t n = spectral_->size(), N = lattice_.cells();
  const auto plans = [this](int b) -> const VelocityPlans& { return this->plans(b); };
  over_velocity_spectra(
      velocity_batches(), kVelocityBatch, spectral_->spectrum_size(),
      [&](int b) { return f.data() + b * kVelocityBatch * N + lattice_.at(0, 0); }, plans,
      [&](std::complex<double>* s, int k) { spectral_->convect(s, model_.vx[k], model_.vy[k]); },
      [&](int b, std::complex<double>* s) { plans(b).compact.backward(s, convection_.data() + b * kVelocityBatch * n); });
}

void Simulation::apply_state_filter() {
  const std::size_t N = lattice_.cells();
  const auto first = [&](int b) { return f_.data() + b * kVelocityBatch * N + lattice_.at(0, 0); };
  const auto plans = [this](int b) -> const VelocityPlans& { return this->plans(b); };
  over_velocity_spectra(
      velocity_batches(), kVelocityBatch, spectral_->spectrum_size(), first, plans,
      [&](std::complex<double>* s, int) { spectral_->apply_state_filter(s); },
      [&](int b, std::complex<double>* s) { plans(b).ghosted.backward(s, first(b)); });
}

void Simulation::stage(std::vector<double>& f, const RowOutput& output) {
  fill_ghosts(f);
  if (spectral_) spectral_convection(f);
#pragma omp parallel
  {
    BgkRow row(model_, inversion_, lattice_, b_, settings_.tau);
    const int chunks = BgkRow::chunks(lattice_.nx);
#pragma omp for schedule(static)
    for (int t = 0; t < BgkRow::blocks(lattice_.ny) * chunks; ++t)
      row.rhs(f.data(), t / chunks, t % chunks, spectral_ ? convection_.data() : nullptr, output);
  }
}

void Simulation::step() {
  // Third-order TVD Runge–Kutta (Shu & Osher): f1 = f + Δt L(f); f2 = ¾f + ¼(f1 + Δt L(f1));
  // f ← ⅓f + ⅔(f2 + Δt L(f2)).
  const double dt = settings_.dt;
  if (!source_) {
    // Each stage is completed row by row as L is computed: f1 in f1_, f2 in work_, f in f1_.
    stage(f_, {f1_.data(), f_.data(), 0.0, dt});
    stage(f1_, {work_.data(), f_.data(), 0.75, dt});
    stage(work_, {f1_.data(), f_.data(), 1.0 / 3.0, dt});
  } else {
    // A source needs the whole L(f) first: L in work_, then the stage update.
    const std::size_t N = lattice_.cells();
    const int Q = model_.size();
    auto combine = [&](double a, std::vector<double>& in, std::vector<double>& out) {
      stage(in, {work_.data()});
      source_(in, work_);
#pragma omp parallel for collapse(2) schedule(static)
      for (int j = 0; j < lattice_.ny; ++j)
        for (int k = 0; k < Q; ++k) {
          const std::size_t row = k * N + lattice_.at(0, j);
          runge_kutta_row(a, f_.data() + row, in.data() + row, dt, work_.data() + row, lattice_.nx,
                          out.data() + row);
        }
    };
    combine(0.0, f_, f1_);
    combine(0.75, f1_, f1_);
    combine(1.0 / 3.0, f1_, f1_);
  }
  if (f_in_place_)
    std::copy(f1_.begin(), f1_.end(), f_.begin());
  else
    std::swap(f_, f1_);
  if (settings_.filter_state) apply_state_filter();
  time_ += dt;
  ++steps_;
}

void Simulation::check_state() const {
  for (int j = 0; j < lattice_.ny; ++j)
    for (int i = 0; i < lattice_.nx; ++i) {
      const Macro m = macro(i, j);
      if (!(m.rho > 0.0) || !(m.T > 0.0) || !std::isfinite(m.rho + m.ux + m.uy + m.T))
        throw RunError(fmt::format(
            "DBM state broke down at step {} (t = {:.6g}) in cell ({}, {}): rho = {}, v = ({}, "
            "{}), T = {}; reduce dt or soften the initial jump; if a smooth mode grew, the state is "
            "unstable for this dx/tau (a larger tau helps at jumps, a smaller tau or a coarser dx "
            "for moving hot states: see the stability check, docs/theory/dbm.md)",
            steps_, time_, i, j, m.rho, m.ux, m.uy, m.T));
    }
}

std::array<double, 4> Simulation::totals() const {
  std::vector<std::array<double, 4>> rows(lattice_.ny, {0, 0, 0, 0});
#pragma omp parallel for schedule(static)
  for (int j = 0; j < lattice_.ny; ++j)
    for (int i = 0; i < lattice_.nx; ++i) {
      const Macro m = macro(i, j);
      rows[j][0] += m.rho;
      rows[j][1] += m.rho * m.ux;
      rows[j][2] += m.rho * m.uy;
      rows[j][3] += 0.5 * m.rho * (b_ * m.T + m.ux * m.ux + m.uy * m.uy);
    }
  std::array<double, 4> total{0, 0, 0, 0};
  const double area = lattice_.dx * lattice_.dy;
  for (const auto& r : rows)
    for (int q = 0; q < 4; ++q) total[q] += r[q] * area;
  return total;
}

}  // namespace shockfield::dbm
