#include "shockfield/dbm/detonation_theory.hpp"

#include <cmath>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::dbm {

ChapmanJouguet chapman_jouguet(const GasState& fresh, double gamma, double Q) {
  if (!(gamma > 1.0) || !(Q > 0.0) || !(fresh.rho > 0.0) || !(fresh.p > 0.0))
    throw InputError(fmt::format(
        "Chapman-Jouguet state needs gamma > 1, Q > 0, rho0 > 0 and p0 > 0 (got gamma = {}, Q = {}, "
        "rho0 = {}, p0 = {})",
        gamma, Q, fresh.rho, fresh.p));
  const double rho0 = fresh.rho, p0 = fresh.p;
  const double c0_sq = gamma * p0 / rho0;
  const double heat = 0.5 * (gamma * gamma - 1.0) * Q;
  const double D = std::sqrt(c0_sq + heat) + std::sqrt(heat);  // gas frame
  ChapmanJouguet r;
  r.speed = fresh.u + D;
  // CJ point: sonic outflow, u_CJ from mass, momentum and D − u = c_CJ.
  const double u_cj = (rho0 * D * D - gamma * p0) / ((gamma + 1.0) * rho0 * D);
  r.cj = {rho0 * D / (D - u_cj), fresh.u + u_cj, p0 + rho0 * D * u_cj};
  // Von Neumann point: the inert shock at D.
  const double M2 = D * D / c0_sq;
  const double rho_vn = rho0 * (gamma + 1.0) * M2 / ((gamma - 1.0) * M2 + 2.0);
  r.von_neumann = {rho_vn, fresh.u + D * (1.0 - rho0 / rho_vn),
                   p0 * (1.0 + 2.0 * gamma * (M2 - 1.0) / (gamma + 1.0))};
  return r;
}

}  // namespace shockfield::dbm
