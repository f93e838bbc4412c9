#pragma once
// Thermal phase separation of the GLS model (Xu et al. 2015, §4.3): a homogeneous state quenched into the
// two-phase region with density noise, and the diagnostics over time — the TNE strength D(t)
// (eq. 35, domain mean of the net central measures, with its force and gradient parts, eqs.
// 29–31), the boundary length L(t) of the density field at a threshold (Minkowski functional,
// analysis/minkowski), the domain size R(t) = 2π/k₁ from the structure factor
// (analysis/spectral_statistics), and the end of spinodal decomposition t_SD at the peak of D(t)
// with D_max = D(t_SD).
#include <cstdint>
#include <vector>

#include "shockfield/analysis/grid_field.hpp"
#include "shockfield/dbm/gls.hpp"

namespace shockfield::dbm {

/// ρ(x, y) = ρ0 (1 + noise·ξ), ξ uniform in [−1, 1) from a counter-based generator of (seed, cell),
/// at rest at temperature T. The noise has zero mean only statistically.
struct Quench {
  double rho0 = 1.0, T = 0.9, noise = 0.01;
  std::uint64_t seed = 1;
  Macro state(const Lattice& lattice, double x, double y) const;
};

struct PhaseSample {
  double t = 0;
  double D = 0, D_force = 0, D_gradient = 0;  // eq. 35 of Δ*, Δ*^F, Δ*^G (domain means)
  double boundary_length = 0;                 // L of ρ at the threshold
  double domain_size = 0;                     // R = 2π/k₁ (0 while the field is uniform)
  double density_variance = 0;                // ⟨(ρ − ⟨ρ⟩)²⟩
  double mass = 0, energy = 0;                // Σρ dA and e_T (eq. after 19)
};

/// The density of the interior cells as an analysis field (periodic, spacing dx, dy).
analysis::GridField density_field(const Simulation& simulation);

/// One sample of the diagnostics of the current state; `threshold` is the density that separates
/// liquid from vapour for L(t).
PhaseSample sample_phase_separation(const Simulation& simulation, GlsForce& force,
                                    double threshold);

struct SpinodalEnd {
  double t_sd = 0, D_max = 0;
  double t_L_max = 0, L_max = 0;  // peak of the boundary length (coincides with t_SD, seed §4.3)
};
/// Peaks of D(t) and L(t) over the samples (first maximum on ties).
SpinodalEnd spinodal_end(const std::vector<PhaseSample>& samples);

}  // namespace shockfield::dbm
