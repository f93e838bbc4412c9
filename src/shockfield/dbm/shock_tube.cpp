#include "shockfield/dbm/shock_tube.hpp"

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/simulation.hpp"

namespace shockfield::dbm {

Primitive ShockTubeResult::mean_over(double a, double b) const {
  Primitive sum{0, 0, 0};
  int n = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] <= a || x[i] >= b) continue;
    sum.rho += dbm[i].rho;
    sum.u += dbm[i].u;
    sum.p += dbm[i].p;
    ++n;
  }
  if (n == 0) throw InputError("shock tube: no cell inside the averaging window");
  return {sum.rho / n, sum.u / n, sum.p / n};
}

ShockTubeResult run_shock_tube(const ShockTubeSetup& s) {
  Lattice lattice;
  lattice.nx = s.nx;
  lattice.ny = 1;
  lattice.dx = lattice.dy = s.length / s.nx;
  Boundaries boundaries;
  boundaries.side[0].kind = boundaries.side[1].kind = BoundaryKind::outflow;
  BgkSettings settings;
  settings.gamma = s.gamma;
  settings.dt = s.courant * lattice.dx / s.model.max_speed();
  settings.tau = s.tau > 0 ? s.tau : settings.dt;
  Simulation sim(s.model, lattice, boundaries, settings);
  const auto to_macro = [](const Primitive& p) { return Macro{p.rho, p.u, 0.0, p.p / p.rho}; };
  sim.initialize([&](double x, double) { return x < s.x0 ? to_macro(s.left) : to_macro(s.right); });
  const auto steps = static_cast<long long>(std::ceil(s.t_end / settings.dt - 1e-9));
  for (long long n = 0; n < steps; ++n) {
    sim.step();
    if (n % 50 == 0) sim.check_state();
  }
  sim.check_state();

  const ExactRiemann exact(s.left, s.right, s.gamma);
  ShockTubeResult r;
  r.time = sim.time();
  for (int i = 0; i < s.nx; ++i) {
    const Macro m = sim.macro(i, 0);
    const Primitive d{m.rho, m.ux, m.rho * m.T};
    const Primitive e = exact.sample((lattice.x(i) - s.x0) / r.time);
    r.x.push_back(lattice.x(i));
    r.dbm.push_back(d);
    r.exact.push_back(e);
    r.l1_rho += std::abs(d.rho - e.rho) * lattice.dx / s.length;
    r.l1_u += std::abs(d.u - e.u) * lattice.dx / s.length;
    r.l1_p += std::abs(d.p - e.p) * lattice.dx / s.length;
  }
  return r;
}

}  // namespace shockfield::dbm
