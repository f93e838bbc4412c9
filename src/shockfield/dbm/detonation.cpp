#include "shockfield/dbm/detonation.hpp"

#include <stdexcept>

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

}  // namespace shockfield::dbm
