#include "shockfield/dbm/detonation.hpp"

#include <cmath>
#include <stdexcept>

#include "shockfield/dbm/tne.hpp"

namespace shockfield::dbm {

void initialize_detonation(Simulation& sim, ReactiveFlow& flow, const IgnitionSpec& ignition,
                           const ChapmanJouguet& cj, const std::function<Macro(double, double)>& rest) {
  const auto macro = [](const GasState& s) { return Macro{s.rho, s.u, 0.0, s.p / s.rho}; };
  const Macro burnt = macro(cj.cj), shocked = macro(cj.von_neumann);
  sim.initialize([&](double x, double y) {
    if (x < ignition.x) return burnt;
    if (x < ignition.x + ignition.width) return shocked;
    return rest(x, y);
  });
  flow.initialize([&](double x, double) { return x < ignition.x ? 0.0 : 1.0; });
}

double pressure_front(const Simulation& sim, int row, double threshold) {
  const Lattice& l = sim.lattice();
  const auto p = [&](int i) {
    const Macro m = sim.macro(i, row);
    return m.rho * m.T;
  };
  double right = p(l.nx - 1);
  for (int i = l.nx - 2; i >= 0; --i) {
    const double left = p(i);
    if (left > threshold && right <= threshold)
      return l.x(i) + l.dx * (left - threshold) / (left - right);
    right = left;
  }
  return l.x(l.nx - 1);
}

double fitted_speed(const std::vector<double>& t, const std::vector<double>& x) {
  if (t.size() != x.size() || t.size() < 2)
    throw std::invalid_argument("fitted_speed needs two or more (t, x) pairs of equal count");
  const double n = static_cast<double>(t.size());
  double st = 0, sx = 0, stt = 0, stx = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    st += t[k], sx += x[k], stt += t[k] * t[k], stx += t[k] * x[k];
  }
  return (n * stx - st * sx) / (n * stt - st * st);
}

DetonationTubeResult run_detonation_tube(const DetonationTubeSetup& d) {
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l;
  l.nx = static_cast<int>(std::lround(d.length / d.dx));
  l.dx = l.dy = d.dx;
  DetonationTubeResult r;
  r.theory = chapman_jouguet(d.fresh, d.gamma, d.law.heat_release);
  const GasState& vn = r.theory.von_neumann;
  Boundaries bc;
  bc.side[0].kind = d.piston ? BoundaryKind::inflow : BoundaryKind::reflecting;
  bc.side[0].state = {vn.rho, vn.u, 0.0, vn.p / vn.rho};
  bc.side[1].kind = BoundaryKind::outflow;
  BgkSettings s;
  s.gamma = d.gamma, s.dt = 0.1 * d.dx, s.tau = d.tau;  // Courant 0.4 with max|v| = 4
  Simulation sim(model, l, bc, s);
  ReactiveFlow flow(sim, bc, d.law);
  const Macro fresh{d.fresh.rho, d.fresh.u, 0.0, d.fresh.p / d.fresh.rho};
  initialize_detonation(sim, flow, {d.piston ? 0.0 : 0.5, d.ignition_width}, r.theory,
                        [&](double, double) { return fresh; });
  const double threshold = 0.5 * (d.fresh.p + r.theory.cj.p);
  std::vector<double> t, front;
  const long long steps = std::llround(d.t_end / s.dt);
  for (long long n = 1; n <= steps; ++n) {
    sim.step();
    if (n % 20 == 0 && sim.time() >= 0.5 * d.t_end) {
      t.push_back(sim.time());
      front.push_back(pressure_front(sim, 0, threshold));
    }
  }
  sim.check_state();
  r.speed = fitted_speed(t, front);
  const TneFields tne = tne_measures(sim);
  for (int i = 0; i < l.nx; ++i) {
    const Macro m = sim.macro(i, 0);
    r.x.push_back(l.x(i));
    r.rho.push_back(m.rho);
    r.p.push_back(m.rho * m.T);
    r.lambda.push_back(flow.lambda(i, 0));
    r.d2xx.push_back(tne.central[0][i]);
  }
  return r;
}

}  // namespace shockfield::dbm
