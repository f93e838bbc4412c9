#pragma once
// Measurements the paper's MPM figures are made of (Xu et al. 2015, §4.1.1, Figs 19-28, and Fig 49):
//  - means and standard deviations of density, pressure, temperature and velocity over the
//    particles of a measurement window [lo, hi) along the shock axis (a bottom window [y1, y1+h]
//    and a top window [y_top − h, y_top] following the highest particle);
//  - mean squares of the local rotation |∇×v|², divergence (∇·v)² and strain rate D:D, from the
//    velocity gradient L_p = Σ_i v_i ⊗ ∇N_i(x_p) the solver forms from the nodal velocities
//    (volume-weighted over the window's particles);
//  - material ejected through the free surface.
// Particles have equal mass within a body, so particle means are mass-weighted means. Sums run
// in particle order: the values do not depend on the thread count.
#include <array>
#include <string>
#include <vector>

#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/particles.hpp"

namespace shockfield::mpm {

/// A per-particle quantity of the windows and histograms: its name and its unit spelt as a
/// column suffix (docs/conventions.md, "Units in column names": `kg_m3`, `Pa`, `K`, `m_s`).
struct WindowQuantity {
  std::string name;
  std::string unit;
};
/// density [kg/m³], pressure −tr σ/3 [Pa] (EOS plus artificial viscosity), temperature [K],
/// the velocity components vx, vy (, vz) [m/s] (v: u is a displacement), then the stress along
/// the shock axis (the last axis, a): longitudinal_stress σ_aa and longitudinal_deviator s_aa [Pa]
/// (Cauchy, tension positive: a compressed bar reads σ_aa < 0), and von_mises √(3/2)‖s‖ [Pa]
/// (eq. 3).
std::vector<WindowQuantity> window_quantities(int dim);
/// Quantity q (index into window_quantities(dim)) of particle i.
double quantity(const Particles& p, std::size_t i, std::size_t q, int dim);

/// |∇×v|², (∇·v)², D:D of a velocity gradient L (D = sym L) [1/s²].
std::array<double, 3> gradient_squares(const Mat3& l);

struct WindowStats {
  std::size_t count = 0;
  double bulk_density = 0.0;         ///< window mass / window volume, voids included [kg/m³]
  std::vector<double> mean, std;     ///< per window_quantities() entry (population std)
  std::array<double, 3> gradients{}; ///< volume-weighted ⟨|∇×v|²⟩, ⟨(∇·v)²⟩, ⟨D:D⟩
};

/// Statistics of the particles with lo <= x[axis] < hi; `cross_section` is the window's lateral
/// measure (width in 2D, area in 3D) for the bulk density. Empty window: count 0, NaN means.
WindowStats window_stats(const Particles& p, int dim, double lo, double hi, double cross_section);

/// Largest coordinate along `axis` over the particles.
double highest(const Particles& p, int axis);

struct Ejecta {
  double surface = 0.0;     ///< free-surface height: median over lateral grid columns of the highest particle [m]
  double mass = 0.0;        ///< mass above surface + threshold [kg, per metre in 2D]
  double count = 0.0;       ///< particles above surface + threshold
  double max_height = 0.0;  ///< highest particle above the surface [m]
};
Ejecta ejecta(const Particles& p, const Grid& grid, double threshold);

}  // namespace shockfield::mpm
