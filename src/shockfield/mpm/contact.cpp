#include "shockfield/mpm/contact.hpp"

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::mpm {

void ContactOptions::validate() const {
  if (!(friction >= 0.0 && std::isfinite(friction)))
    throw InputError(fmt::format("mpm: contact friction = {} (expected a finite Coulomb coefficient >= 0)", friction));
}

ContactStats apply_contact(Grid& grid, double friction, double mass_floor, double dt) {
  const std::size_t n = grid.size();
  const auto layers = static_cast<std::size_t>(grid.layers());
  long long corrected = 0;
  double impulse = 0.0;  // Σ |Δp_b| over the corrected bodies and nodes
  if (layers < 2) return {};
#pragma omp parallel for schedule(static) reduction(+ : corrected, impulse)
  for (std::ptrdiff_t q = 0; q < static_cast<std::ptrdiff_t>(n); ++q) {
    const auto i = static_cast<std::size_t>(q);
    int present = 0;
    double mass = 0.0;
    Vec3 momentum = Vec3::Zero();
    for (std::size_t b = 0, at = i; b < layers; ++b, at += n)
      if (grid.mass[at] > mass_floor) ++present, mass += grid.mass[at], momentum += grid.momentum[at];
    if (present < 2) continue;  // one body (or none) at this node: its own field, no contact
    const Vec3 v_cm = momentum / mass;
    bool touched = false;
    for (std::size_t b = 0, at = i; b < layers; ++b, at += n) {
      const double m = grid.mass[at];
      if (!(m > mass_floor)) continue;
      // n_b = unit(∇m_b − Σ_{c≠b} ∇m_c): for two bodies exactly −n of the other (a − b = −(b − a)
      // in floating point), so the two corrections are equal and opposite.
      Vec3 normal = grid.mass_gradient[at];
      for (std::size_t c = 0, other = i; c < layers; ++c, other += n)
        if (c != b) normal -= grid.mass_gradient[other];
      const double length = normal.norm();
      if (!(length > 0.0)) continue;
      normal /= length;
      Vec3& p = grid.momentum[at];
      const Vec3 dv = p / m - v_cm;  // velocity relative to the centre of mass
      const double approach = dv.dot(normal);
      if (!(approach > 0.0)) continue;  // moving apart (or sliding): no contact force
      const Vec3 slip = dv - approach * normal;
      const double slip_speed = slip.norm();
      Vec3 change;  // Δv_b
      if (friction * approach >= slip_speed) change = -dv;  // stick: v_b = v_cm
      else change = -approach * normal - (friction * approach / slip_speed) * slip;  // Coulomb slip
      p += m * change;
      impulse += m * change.norm();
      touched = true;
    }
    if (touched) ++corrected;
  }
  return {static_cast<std::size_t>(corrected), 0.5 * impulse / dt};
}

}  // namespace shockfield::mpm
