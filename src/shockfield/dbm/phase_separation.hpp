#pragma once
// Thermal phase separation of the GLS model (Xu et al. 2015, §4.3): a homogeneous state quenched into the
// two-phase region with density noise, and the diagnostics over time — the TNE strength D(t)
// (eq. 35, domain mean of the net central measures, with its force and gradient parts, eqs.
// 29–31), the boundary length L(t) of the density field at a threshold (Minkowski functional,
// analysis/minkowski), the domain size R(t) = 2π/k₁ from the structure factor
// (analysis/spectral_statistics), the end of spinodal decomposition t_SD at the peak of D(t)
// with D_max = D(t_SD), and the domain-growth speed u_DG, the slope of R(t) after t_SD.
#include <cstdint>
#include <utility>
#include <vector>

#include "shockfield/analysis/grid_field.hpp"
#include "shockfield/dbm/gls.hpp"

namespace shockfield::dbm {

/// The density noise ξ(x, y) of a quench, with the mean square 1/3 of a uniform number in [−1, 1):
/// - shortest wavelength λ = 0: white noise, ξ uniform in [−1, 1) per cell from a counter-based
///   generator of (seed, i, j); a finer grid draws a different field (more, weaker modes);
/// - λ > 0: band-limited noise, the same function of (x, y) on every grid of the same box:
///   ξ = s Σ A_mn cos(k_mn·x + φ_mn) over the box's Fourier modes k_mn = 2π(m/L_x, n/L_y) with
///   0 < |k_mn| ≤ 2π/λ (one of ±k each), A_mn standard normal and φ_mn uniform in [0, 2π) from the
///   generator of (seed, m, n), s = (3 Σ A²/2)^(−1/2); its mean is 0 exactly, its spectrum flat up to
///   the cutoff (docs/theory/dbm.md, "Thermal phase separation").
class QuenchNoise {
 public:
  /// InputError when λ > 0 is shorter than two cells (the grid cannot hold its modes).
  QuenchNoise(std::uint64_t seed, double shortest_wavelength, const Lattice& lattice);
  double operator()(double x, double y) const;
  /// The smallest and largest ξ at the lattice's cell centres, the values the initial state takes.
  std::pair<double, double> extremes_on_cells() const;
  std::size_t modes() const { return modes_.size(); }

 private:
  struct Mode {
    double kx, ky, amplitude, phase;
  };
  std::uint64_t seed_;
  Lattice lattice_;
  std::vector<Mode> modes_;  // empty for white noise
};

/// ρ(x, y) = ρ0 (1 + noise·ξ(x, y)) at rest at temperature T (ξ: QuenchNoise).
struct Quench {
  double rho0 = 1.0, T = 0.9, noise = 0.01;
  std::uint64_t seed = 1;
  double noise_wavelength = 0.0;  // shortest wavelength of the noise; 0: white noise per cell
  QuenchNoise noise_field(const Lattice& lattice) const { return {seed, noise_wavelength, lattice}; }
  Macro state(const QuenchNoise& xi, double x, double y) const;
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
  double t_sd = 0, D_max = 0, R_sd = 0;  // R_SD = R(t_SD)
  double t_L_max = 0, L_max = 0;  // peak of the boundary length (coincides with t_SD, Xu et al. (2015) §4.3)
};
/// Peaks of D(t) and L(t) over the samples (first maximum on ties).
SpinodalEnd spinodal_end(const std::vector<PhaseSample>& samples);

/// The domain-growth speed u_DG of Xu et al. (2015) §4.3 ("the slope of the R(t) curve ... for the
/// domain growth stage", eq. 34): the least-squares slope of R over the samples with t in
/// [t_SD, t_SD + window], the early domain growth (docs/theory/dbm.md, "The domain-growth speed u_DG":
/// later, with a few domains left in the box, the slope depends on the grid). A run that ends
/// before t_SD + window cuts the window at its last sample (t_end says so); fewer than 3 samples
/// in the window give speed = NaN.
struct DomainGrowth {
  double speed = 0;              // u_DG = dR/dt
  double t_begin = 0, t_end = 0;  // the samples' window
};
DomainGrowth domain_growth(const std::vector<PhaseSample>& samples, double t_sd, double window);

}  // namespace shockfield::dbm
