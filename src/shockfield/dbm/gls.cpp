#include "shockfield/dbm/gls.hpp"

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::dbm {

double eos_pressure(const GlsEos& eos, double rho, double T) {
  return std::visit([&](const auto& e) { return e.pressure(rho, T); }, eos);
}
double eos_attraction(const GlsEos& eos) {
  return std::visit([](const auto& e) { return e.a; }, eos);
}
double eos_max_density(const GlsEos& eos) {
  return std::visit([](const auto& e) { return e.max_density(); }, eos);
}

void GlsForce::validate(const Simulation& simulation, const Boundaries& boundaries, const GlsSettings& settings) {
  for (const BoundarySide& s : boundaries.side)
    if (s.kind != BoundaryKind::periodic)
      throw InputError(
          "the GLS liquid-vapour model takes its spatial derivatives by FFT and needs periodic "
          "boundaries on all four sides");
  if (simulation.b() != 2.0)
    throw InputError(fmt::format(
        "the GLS liquid-vapour model needs gamma = 2 (b = 2 degrees of freedom, e = rho T), "
        "got b = {}",
        simulation.b()));
  if (!(settings.K >= 0.0)) throw InputError(fmt::format("GLS K = {} must be >= 0", settings.K));
  if (!(settings.zeta >= 0.0))
    throw InputError(fmt::format("GLS bulk viscosity zeta = {} must be >= 0", settings.zeta));
  if (!(settings.q < simulation.settings().tau))
    throw InputError(fmt::format(
        "GLS q = {} must be < tau = {}: the heat conductivity 2 rho T (tau - q) must be positive "
        "(q < 0 raises it above the BGK value)",
        settings.q, simulation.settings().tau));
  std::visit([](const auto& e) { e.validate("GLS equation of state"); }, settings.eos);
}

GlsForce::GlsForce(Simulation& simulation, const Boundaries& boundaries,
                   const GlsSettings& settings)
    : sim_(simulation),
      settings_(settings),
      spectral_(simulation.lattice().nx, simulation.lattice().ny, simulation.lattice().dx,
                simulation.lattice().dy),
      coef_(spectral_.size()) {
  validate(simulation, boundaries, settings);
  simulation.set_source(
      [this](const std::vector<double>& f, std::vector<double>& rhs) {
        coefficients(f);
        apply(f, rhs, false);
      });
}

std::vector<Macro> GlsForce::macros(const std::vector<double>& f) const {
  std::vector<Macro> m;
  macros(f, m);
  return m;
}

void GlsForce::macros(const std::vector<double>& f, std::vector<Macro>& m) const {
  const Lattice& L = sim_.lattice();
  m.resize(spectral_.size());
#pragma omp parallel for schedule(static)
  for (int j = 0; j < L.ny; ++j)
    for (int i = 0; i < L.nx; ++i)
      m[i + static_cast<std::size_t>(L.nx) * j] =
          macro_of(sim_.model(), f.data() + L.at(i, j), L.cells(), sim_.b());
}

namespace {

/// Runs independent jobs over the threads, each one serial (an FFT and its products, writing only its
/// own result): the same numbers for any thread count.
void run_jobs(const std::vector<std::function<void()>>& jobs) {
#pragma omp parallel for schedule(dynamic)
  for (std::size_t j = 0; j < jobs.size(); ++j) jobs[j]();
}

}  // namespace

void GlsForce::coefficients(const std::vector<double>& f) {
  Scratch& w = scratch_;
  macros(f, w.m);
  const std::size_t n = w.m.size();
  const double K = settings_.K, zeta = settings_.zeta, q = settings_.q;
  const double a = eos_attraction(settings_.eos);
  const std::vector<Macro>& m = w.m;
  std::vector<double> &rho = w.rho, &ux = w.ux, &uy = w.uy, &T = w.T, &P = w.P;
  for (auto* v : {&rho, &ux, &uy, &T, &P, &w.div, &w.nonideal, &w.Lxx, &w.Lxy, &w.Lyy, &w.hx, &w.hy}) v->resize(n);
  for (std::size_t c = 0; c < n; ++c) {  // serial: the EOS throws on states outside its domain
    rho[c] = m[c].rho, ux[c] = m[c].ux, uy[c] = m[c].uy, T[c] = m[c].T;
    P[c] = eos_pressure(settings_.eos, rho[c], T[c]);
  }
  const PeriodicSpectral& s = spectral_;
  auto& work = w.work;
  run_jobs({[&] { s.forward(rho, w.s_rho); }, [&] { s.forward(ux, w.s_ux); }, [&] { s.forward(uy, w.s_uy); },
            [&] { s.forward(T, w.s_T); }});
  std::vector<double> &rx = w.rx, &ry = w.ry, &lap = w.lap, &uxx = w.uxx, &uxy = w.uxy, &uyx = w.uyx, &uyy = w.uyy,
                      &Tx = w.Tx, &Ty = w.Ty;
  run_jobs({[&] { s.derivative(w.s_rho, 1, 0, work[0], rx); }, [&] { s.derivative(w.s_rho, 0, 1, work[1], ry); },
            [&] { s.laplacian(w.s_rho, work[2], lap); }, [&] { s.derivative(w.s_ux, 1, 0, work[3], uxx); },
            [&] { s.derivative(w.s_ux, 0, 1, work[4], uxy); }, [&] { s.derivative(w.s_uy, 1, 0, work[5], uyx); },
            [&] { s.derivative(w.s_uy, 0, 1, work[6], uyy); }, [&] { s.derivative(w.s_T, 1, 0, work[7], Tx); },
            [&] { s.derivative(w.s_T, 0, 1, work[8], Ty); }});
  std::vector<double> &div = w.div, &nonideal = w.nonideal, &Lxx = w.Lxx, &Lxy = w.Lxy, &Lyy = w.Lyy, &hx = w.hx,
                      &hy = w.hy;
#pragma omp parallel for schedule(static)
  for (std::size_t c = 0; c < n; ++c) {
    div[c] = uxx[c] + uyy[c];
    nonideal[c] = P[c] - rho[c] * T[c];
    // Λ with ∇(K/T) = −K∇T/T² for a constant K.
    const double g2 = rx[c] * rx[c] + ry[c] * ry[c];
    const double iso = K * (rho[c] * lap[c] + 0.5 * g2) -
                       K * rho[c] * (rx[c] * Tx[c] + ry[c] * Ty[c]) / T[c];
    Lxx[c] = K * rx[c] * rx[c] - iso;
    Lxy[c] = K * rx[c] * ry[c];
    Lyy[c] = K * ry[c] * ry[c] - iso;
    hx[c] = 2.0 * q * rho[c] * T[c] * Tx[c];  // eq. 18 flux
    hy[c] = 2.0 * q * rho[c] * T[c] * Ty[c];
  }
  run_jobs({[&] { s.forward(div, w.s_div); }, [&] { s.forward(nonideal, w.s_ni); }, [&] { s.forward(Lxx, w.s_xx); },
            [&] { s.forward(Lxy, w.s_xy); }, [&] { s.forward(Lyy, w.s_yy); },
            [&] { if (q != 0.0) s.forward(hx, w.s_hx); }, [&] { if (q != 0.0) s.forward(hy, w.s_hy); }});
  std::vector<double> &divx = w.divx, &divy = w.divy, &nix = w.nix, &niy = w.niy, &dLx = w.dLx, &dLy = w.dLy,
                      &dh = w.dh;
  run_jobs({[&] { s.derivative(w.s_div, 1, 0, work[0], divx); }, [&] { s.derivative(w.s_div, 0, 1, work[1], divy); },
            [&] { s.derivative(w.s_ni, 1, 0, work[2], nix); }, [&] { s.derivative(w.s_ni, 0, 1, work[3], niy); },
            [&] { s.divergence(w.s_xx, w.s_xy, work[4], dLx); }, [&] { s.divergence(w.s_xy, w.s_yy, work[5], dLy); },
            [&] {
              if (q != 0.0) s.divergence(w.s_hx, w.s_hy, work[6], dh);
              else dh.assign(n, 0.0);
            }});
#pragma omp parallel for schedule(static)
  for (std::size_t c = 0; c < n; ++c) {
    const double r = rho[c], t = T[c], d = div[c];
    const double Bx = (nix[c] + dLx[c] - zeta * divx[c]) / (r * t);  // eq. 16
    const double By = (niy[c] + dLy[c] - zeta * divy[c]) / (r * t);
    const double g2 = rx[c] * rx[c] + ry[c] * ry[c];
    const double lambda_grad_u = Lxx[c] * uxx[c] + Lxy[c] * (uxy[c] + uyx[c]) + Lyy[c] * uyy[c];
    const double grad_u_rr = rx[c] * rx[c] * uxx[c] + rx[c] * ry[c] * (uxy[c] + uyx[c]) +
                             ry[c] * ry[c] * uyy[c];  // ∇ρ·∇u·∇ρ
    const double C = (nonideal[c] * d + lambda_grad_u - zeta * d * d + a * r * r * d +
                      K * (-0.5 * g2 * d - r * (rx[c] * divx[c] + ry[c] * divy[c]) - grad_u_rr)) /
                     (2.0 * r * t * t);  // eq. 17
    const double Cq = dh[c] / (2.0 * r * t * t);  // eq. 18
    coef_[c] = {-2.0 * (C + Cq) * t, Bx, By, C + Cq};  // eq. 15
  }
}

namespace {

/// 4 × 4 Gauss–Hermite rule for the weight exp(−ξ²/2)/sqrt(2π) per axis (nodes ±sqrt(3 ± sqrt 6),
/// weights 3/(2(ξ³ − 3ξ)²)): exact for polynomials of degree ≤ 7 in each component.
struct HermiteRule {
  std::array<double, 16> x, y, w;
  HermiteRule() {
    std::array<double, 4> node, weight;
    for (int s = 0; s < 2; ++s) {
      const double xi = std::sqrt(3.0 + (s == 0 ? 1.0 : -1.0) * std::sqrt(6.0));
      const double he3 = xi * xi * xi - 3.0 * xi;
      node[2 * s] = xi, node[2 * s + 1] = -xi;
      weight[2 * s] = weight[2 * s + 1] = 1.5 / (he3 * he3);
    }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) x[4 * a + b] = node[a], y[4 * a + b] = node[b],
                                  w[4 * a + b] = weight[a] * weight[b];
  }
};

}  // namespace

void GlsForce::apply(const std::vector<double>& f, std::vector<double>& out,
                     bool overwrite) const {
  // I_k = C⁻¹·M(I): the 16 moments of eq. 14 applied to the continuous Maxwellian of (ρ, u, T)
  // (by the Gauss–Hermite rule, exact here: degree ≤ 6), inverted like f^eq = C⁻¹·M^eq.
  // Evaluating eq. 14 on the discrete f^eq instead makes M_3(I) and M_(4,2)(I) depend on moments
  // of f^eq beyond eq. 26 that D2V16 does not fix, and the runs blow up.
  static const HermiteRule rule;
  const Lattice& L = sim_.lattice();
  const VelocityModel& model = sim_.model();
  const int Q = model.size();
  const std::size_t N = L.cells();
#pragma omp parallel
  {
    std::vector<double> I(Q);
#pragma omp for schedule(static)
    for (int j = 0; j < L.ny; ++j)
      for (int i = 0; i < L.nx; ++i) {
        const std::size_t id = i + static_cast<std::size_t>(L.nx) * j, cell = L.at(i, j);
        const Macro m = macro_of(model, f.data() + cell, N, sim_.b());
        const auto& [A, Bx, By, C] = coef_[id];
        const double s = std::sqrt(m.T);
        Eigen::Matrix<double, kMoments, 1> moments = Eigen::Matrix<double, kMoments, 1>::Zero();
        for (int q = 0; q < 16; ++q) {
          const double cx = s * rule.x[q], cy = s * rule.y[q];
          const double theta = -(A + Bx * cx + By * cy + C * (cx * cx + cy * cy));  // eq. 14
          moments += (m.rho * rule.w[q] * theta) * moment_row(m.ux + cx, m.uy + cy, 0.0);
        }
        sim_.inversion().distribution(moments, I.data());
        for (int k = 0; k < Q; ++k) {
          double& o = out[k * N + cell];
          o = overwrite ? I[k] : o + I[k];
        }
      }
  }
}

void GlsForce::force_term(const std::vector<double>& f, std::vector<double>& out) {
  out.assign(f.size(), 0.0);
  coefficients(f);
  apply(f, out, true);
}

std::vector<double> GlsForce::pressure() const {
  const std::vector<Macro> m = macros(sim_.f());
  std::vector<double> P(m.size());
  for (std::size_t c = 0; c < m.size(); ++c) P[c] = eos_pressure(settings_.eos, m[c].rho, m[c].T);
  return P;
}

GlsEnergy GlsForce::energy() const {
  const std::vector<Macro> m = macros(sim_.f());
  std::vector<double> rho(m.size());
  for (std::size_t c = 0; c < m.size(); ++c) rho[c] = m[c].rho;
  const auto s_rho = spectral_.forward(rho);
  const auto rx = spectral_.derivative(s_rho, 1, 0), ry = spectral_.derivative(s_rho, 0, 1);
  const double a = eos_attraction(settings_.eos);
  GlsEnergy e;
  for (std::size_t c = 0; c < m.size(); ++c) {  // fixed order: thread-count independent
    const Macro& x = m[c];
    e.thermal += x.rho * x.T;
    e.kinetic += 0.5 * x.rho * (x.ux * x.ux + x.uy * x.uy);
    e.attraction -= a * x.rho * x.rho;
    e.interfacial += 0.5 * settings_.K * (rx[c] * rx[c] + ry[c] * ry[c]);
  }
  const double area = sim_.lattice().dx * sim_.lattice().dy;
  e.thermal *= area, e.kinetic *= area, e.attraction *= area, e.interfacial *= area;
  return e;
}

GlsTne GlsForce::tne() {
  const std::vector<double>& f = sim_.f();
  const Lattice& L = sim_.lattice();
  const int Q = sim_.model().size();
  const std::size_t N = L.cells();
  std::vector<double> force;
  force_term(f, force);
  const std::vector<Macro> m = macros(f);
  std::vector<double> net(f.size(), 0.0);
  const double tau = sim_.settings().tau;
#pragma omp parallel
  {
    std::vector<double> eq(Q);
#pragma omp for schedule(static)
    for (int j = 0; j < L.ny; ++j)
      for (int i = 0; i < L.nx; ++i) {
        const Macro& x = m[i + static_cast<std::size_t>(L.nx) * j];
        sim_.inversion().equilibrium(x.rho, x.ux, x.uy, x.T, sim_.b(), eq.data());
        for (int k = 0; k < Q; ++k) {
          const std::size_t c = k * N + L.at(i, j);
          net[c] = f[c] - eq[k];  // eq. 27
          force[c] *= tau;        // eq. 29: τI
        }
      }
  }
  std::vector<double> gradient(f.size());
  for (std::size_t c = 0; c < f.size(); ++c) gradient[c] = net[c] - force[c];  // eq. 31
  const VelocityModel& model = sim_.model();
  return {tne_measures(model, L, net, m), tne_measures(model, L, force, m),
          tne_measures(model, L, gradient, m)};
}

}  // namespace shockfield::dbm
