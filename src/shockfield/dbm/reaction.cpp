#include "shockfield/dbm/reaction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/bgk_row.hpp"
#include "shockfield/dbm/convection.hpp"

namespace shockfield::dbm {

double RateLaw::consumption(double lambda, double rho, double T) const {
  if (T < ignition_temperature) return 0.0;
  if (kind == RateKind::arrhenius) return rate * lambda * std::exp(-activation / T);
  const double p = rho * T;
  return omega1 * std::pow(p, m) * lambda + omega2 * std::pow(p, n) * lambda * (1.0 - lambda);
}

Eigen::Matrix<double, kMoments, 1> equilibrium_moments_dT(double rho, double ux, double uy,
                                                          double T, double b) {
  // T-derivatives of eqs. 20–26 as written in equilibrium_moments(): M0, M1 do not depend on T;
  // E = ρ(bT + u²)/2; M2 = ρ(T I + uu); M3 = ρ(T (u δ)_sym + uuu); M3,1 = ρu((b+2)T + u²)/2;
  // M4,2 = ρ[hT I + g uu] with h = ((b+2)T + u²)/2, g = ((b+4)T + u²)/2.
  const double u2 = ux * ux + uy * uy;
  const double dhT = (b + 2.0) * T + 0.5 * u2;  // d(hT)/dT
  const double dg = 0.5 * (b + 4.0);
  Eigen::Matrix<double, kMoments, 1> d;
  d << 0.0, 0.0, 0.0, 0.5 * rho * b,                                   //
      rho, 0.0, rho,                                                    //
      3 * rho * ux, rho * uy, rho * ux, 3 * rho * uy,                   //
      0.5 * (b + 2.0) * rho * ux, 0.5 * (b + 2.0) * rho * uy,           //
      rho * (dhT + dg * ux * ux), rho * dg * ux * uy, rho * (dhT + dg * uy * uy);
  return d;
}

ReactiveFlow::ReactiveFlow(Simulation& simulation, const Boundaries& boundaries,
                           const RateLaw& law, double inflow_lambda)
    : sim_(simulation), boundaries_(boundaries), law_(law), inflow_lambda_(inflow_lambda) {
  if (sim_.settings().spectral_convection)
    throw InputError(
        "the reactive DBM carries the reactant with the NND face fluxes: use convection = \"nnd\"");
  if (!(law.heat_release > 0.0))
    throw InputError(fmt::format("reaction heat release Q = {} must be positive", law.heat_release));
  const std::size_t n = sim_.lattice().cells();
  phi_.assign(n, 0.0);
  phi0_ = phi_stage_ = dphi_ = lambda_ = phi_;
  sim_.set_source([this](const std::vector<double>& f, std::vector<double>& rhs) { source(f, rhs); });
}

void ReactiveFlow::initialize(const std::function<double(double, double)>& lambda) {
  const Lattice& l = sim_.lattice();
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) phi_[l.at(i, j)] = sim_.macro(i, j).rho * lambda(l.x(i), l.y(j));
}

double ReactiveFlow::lambda(int i, int j) const {
  return phi_[sim_.lattice().at(i, j)] / sim_.macro(i, j).rho;
}

double ReactiveFlow::consumption(int i, int j) const {
  const Macro m = sim_.macro(i, j);
  return law_.consumption(lambda(i, j), m.rho, m.T);
}

double ReactiveFlow::chemical_energy() const {
  const Lattice& l = sim_.lattice();
  double sum = 0.0;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) sum += phi_[l.at(i, j)];
  return law_.heat_release * sum * l.dx * l.dy;
}

void ReactiveFlow::source(const std::vector<double>& f, std::vector<double>& rhs) {
  // The RK3 stages of Simulation::step applied to φ: φ1 = φ + Δt L(φ); φ2 = ¾φ + ¼(φ1 + Δt L(φ1));
  // φ ← ⅓φ + ⅔(φ2 + Δt L(φ2)), with L evaluated together with the stage's f.
  const bool new_step = sim_.steps() != stage_step_;
  if (new_step != (stage_ == 0))
    throw std::logic_error("ReactiveFlow: the reaction source was not called once per Runge-Kutta stage");
  stage_step_ = sim_.steps();
  const double dt = sim_.settings().dt;
  const Lattice& l = sim_.lattice();
  if (stage_ == 0) phi0_ = phi_;
  stage_rates(f, stage_ == 0 ? phi0_ : phi_stage_, rhs);
  static constexpr double kKeep[3] = {0.0, 0.75, 1.0 / 3.0};
  const double a = kKeep[stage_];
  std::vector<double>& target = stage_ == 2 ? phi_ : phi_stage_;
  const std::vector<double>& previous = stage_ == 0 ? phi0_ : phi_stage_;
#pragma omp parallel for collapse(2) schedule(static)
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const std::size_t c = l.at(i, j);
      target[c] = runge_kutta_stage(a, phi0_[c], previous[c], dt, dphi_[c]);
    }
  stage_ = (stage_ + 1) % 3;
}

double ReactiveFlow::face_mass_flux(const std::vector<double>& f, std::size_t c, std::ptrdiff_t s,
                                    const std::vector<double>& v) const {
  const std::size_t N = sim_.lattice().cells();
  double flux = 0.0;
  for (int k = 0; k < static_cast<int>(v.size()); ++k) {
    const double* p = f.data() + k * N + c;
    // The face value the convection of f_k uses (convection.hpp).
    if (v[k] != 0.0) flux += v[k] * nnd_face_value(p, s, v[k] > 0.0);
  }
  return flux;
}

void ReactiveFlow::stage_rates(const std::vector<double>& f, const std::vector<double>& phi,
                               std::vector<double>& rhs) {
  fill_lambda(f, phi);
  const Lattice& l = sim_.lattice();
  const VelocityModel& model = sim_.model();
  const std::size_t N = l.cells();
  const int Q = model.size();
  const double b = sim_.b(), heat = law_.heat_release;
  const std::ptrdiff_t sx = 1, sy = l.stride();
  // φ flux through the face between c and c + s: mass flux × upwind limited face value of λ.
  auto phi_flux = [&](std::size_t c, std::ptrdiff_t s, const std::vector<double>& v) {
    const double mass = face_mass_flux(f, c, s, v);
    const double* lam = lambda_.data() + c;
    return mass * nnd_face_value(lam, s, mass > 0.0);
  };
#pragma omp parallel
  {
    std::vector<double> r(Q);
#pragma omp for collapse(2) schedule(static)
    for (int j = 0; j < l.ny; ++j)
      for (int i = 0; i < l.nx; ++i) {
        const std::size_t c = l.at(i, j);
        const double divergence =
            (phi_flux(c, sx, model.vx) - phi_flux(c - sx, sx, model.vx)) / l.dx +
            (phi_flux(c, sy, model.vy) - phi_flux(c - sy, sy, model.vy)) / l.dy;
        const Macro m = macro_of(model, f.data() + c, N, b);
        const double omega = law_.consumption(lambda_[c], m.rho, m.T);
        dphi_[c] = -divergence - m.rho * omega;
        if (omega == 0.0) continue;
        // R = C⁻¹·∂M^eq/∂T·(dT/dt)_chem with (dT/dt)_chem = 2Qω/b.
        sim_.inversion().distribution(
            equilibrium_moments_dT(m.rho, m.ux, m.uy, m.T, b) * (2.0 * heat * omega / b), r.data());
        for (int k = 0; k < Q; ++k) rhs[k * N + c] += r[k];
      }
  }
}

void ReactiveFlow::fill_lambda(const std::vector<double>& f, const std::vector<double>& phi) {
  const Lattice& l = sim_.lattice();
  const std::size_t N = l.cells();
  const int Q = sim_.model().size();
#pragma omp parallel for collapse(2) schedule(static)
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const std::size_t c = l.at(i, j);
      double rho = 0.0;
      for (int k = 0; k < Q; ++k) rho += f[k * N + c];
      lambda_[c] = phi[c] / rho;
    }
  // Ghosts as GhostFiller fills f: x sides on interior rows, y sides on every column.
  const int g = Lattice::ghosts;
  for (int side = 0; side < 4; ++side) {
    const int axis = side / 2;
    const bool high = side % 2 == 1;
    const int n = axis == 0 ? l.nx : l.ny;
    const int lo = axis == 0 ? 0 : -g, hi = axis == 0 ? l.ny : l.nx + g;
    const BoundaryKind kind = boundaries_.side[side].kind;
    for (int a = lo; a < hi; ++a)
      for (int layer = 0; layer < g; ++layer) {
        const int ghost = high ? n + layer : -1 - layer;
        int source = std::clamp(high ? n - 1 - layer : layer, 0, n - 1);  // mirror image
        if (kind == BoundaryKind::periodic) source = ((ghost % n) + n) % n;
        if (kind == BoundaryKind::outflow) source = high ? n - 1 : 0;
        auto cell = [&](int q) { return axis == 0 ? l.at(q, a) : l.at(a, q); };
        lambda_[cell(ghost)] = feeds_gas(kind) ? inflow_lambda_ : lambda_[cell(source)];
      }
  }
}

}  // namespace shockfield::dbm
