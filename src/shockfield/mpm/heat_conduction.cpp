#include "shockfield/mpm/heat_conduction.hpp"

#include <algorithm>
#include <limits>

namespace shockfield::mpm {

void HeatConduction::step(const Transfer& transfer, std::size_t nodes, Particles& p,
                          const std::vector<materials::SolidMaterial>& materials, double dt) {
  auto thermal = [&](std::size_t q) -> const materials::Thermal& {
    return materials[static_cast<std::size_t>(p.material[q])].thermal;
  };
  capacity_.assign(nodes, 0.0);
  temperature_.assign(nodes, 0.0);
  rate_.assign(nodes, 0.0);
  transfer.scatter_each([&](std::size_t q, auto each) {  // C_i and Σ m c_v T N
    const double mc = p.mass[q] * thermal(q).heat_capacity;
    const double mct = mc * p.state[q].temperature;
    each([&](std::size_t i, double w, const auto&) {
      capacity_[i] += w * mc;
      temperature_[i] += w * mct;
    });
  });
  for (std::size_t i = 0; i < nodes; ++i)
    if (capacity_[i] > 0.0) temperature_[i] /= capacity_[i];
  transfer.scatter_each([&](std::size_t q, auto each) {  // ∇T_p, then Q_i
    const double k = thermal(q).conductivity;
    if (k == 0.0) return;
    double grad[3] = {0.0, 0.0, 0.0};
    each([&](std::size_t i, double, const auto& g) {
      for (int r = 0; r < 3; ++r) grad[r] += temperature_[i] * g[static_cast<std::size_t>(r)];
    });
    const double vk = p.volume(q) * k;
    each([&](std::size_t i, double, const auto& g) {
      rate_[i] -= vk * (grad[0] * g[0] + grad[1] * g[1] + grad[2] * g[2]);
    });
  });
  for (std::size_t i = 0; i < nodes; ++i)
    if (capacity_[i] > 0.0) rate_[i] /= capacity_[i];   // Q_i / C_i
  transfer.gather_each([&](std::size_t q, auto each) {  // ΔT_p = Δt Σ N Q/C, Δe_p = c_v ΔT_p
    double dtemp = 0.0;
    each([&](std::size_t i, double w, const auto&) { dtemp += w * rate_[i]; });
    dtemp *= dt;
    p.state[q].temperature += dtemp;
    p.state[q].energy += thermal(q).heat_capacity * dtemp;
  });
}

double HeatConduction::stable_time_step(const Particles& p,
                                        const std::vector<materials::SolidMaterial>& materials,
                                        double courant, double min_cell_size, int dim) {
  double alpha = 0.0;  // max_p k / (ρ c_v)
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static) reduction(max : alpha)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto u = static_cast<std::size_t>(q);
    const auto& th = materials[static_cast<std::size_t>(p.material[u])].thermal;
    if (th.conductivity > 0.0)
      alpha = std::max(alpha, th.conductivity / (p.density(u) * th.heat_capacity));
  }
  if (alpha == 0.0) return std::numeric_limits<double>::infinity();
  return courant * min_cell_size * min_cell_size / (2.0 * dim * alpha);
}

}  // namespace shockfield::mpm
