#pragma once
// The kinetic sharp-front option of `method = "phasefield"` (`[model] kind = "sharp_front"`,
// docs/theory/phasefield.md §"The sharp-front option"): hcp domains as spheres (discs in 2D,
// segments in 1D) whose surface moves along its normal at
//
//   v = c₀ + s D κ,   κ the mean curvature (k₁ + k₂ in 3D), positive for a convex hcp domain,
//
//   law "paper":      s = +1, Xu et al. (2015) eq 43 as printed, v = c₀ + Dk with k = +2/R for
//                     an hcp sphere (their Ṙ = c₀ + 2D/R): small domains grow faster;
//   law "allen_cahn": s = −1, the sharp-interface limit of the well-posed field model
//                     (v = c₀ − Dκ): small domains grow slower, or shrink.
//
// A sphere stays a sphere, Ṙ = c₀ + s(n − 1)D/R. Any other shape is not followed: about a sphere
// the shape mode l (Legendre degree in 3D, Fourier order in 2D) of amplitude δ grows as
// δ̇ = s D (l − 1)(l + n − 1)/R² δ, unbounded in l for s = +1 (ill-posed: the finest mode a
// discretisation holds grows fastest) and damped for s = −1.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "shockfield/phasefield/grid.hpp"
#include "shockfield/phasefield/initial.hpp"

namespace shockfield::phasefield {

enum class FrontLaw { paper, allen_cahn };

FrontLaw front_law_from_name(const std::string& name);  ///< "paper", "allen_cahn"
const char* front_law_name(FrontLaw law);

struct SharpFrontLaw {
  FrontLaw law = FrontLaw::paper;
  double c0 = 0.0;  ///< flat-front speed into bcc (length/time)
  double D = 0.0;   ///< curvature coefficient (length²/time), > 0
  int dim = 3;

  /// s = +1 (paper), −1 (allen_cahn).
  double sign() const { return law == FrontLaw::paper ? 1.0 : -1.0; }
  /// σ = s (n − 1) D: Ṙ = c₀ + σ/R.
  double sigma() const { return sign() * (dim - 1) * D; }
  /// Ṙ = c₀ + s(n − 1)D/R.
  double rate(double R) const { return c0 + sigma() / R; }
  /// The radius where Ṙ = 0, −σ/c₀ when positive (else infinite): unstable for allen_cahn with
  /// c₀ > 0 (the critical radius), stable for paper with c₀ < 0 (every domain tends to it).
  double fixed_radius() const;
  /// The closed form of the law, the time from R₀ to R (docs/theory/phasefield.md):
  /// t = (R − R₀)/c₀ − (σ/c₀²) ln((c₀R + σ)/(c₀R₀ + σ)) (c₀ ≠ 0), (R² − R₀²)/(2σ) (c₀ = 0),
  /// (R − R₀)/c₀ (σ = 0, 1D); NaN when R is not reached from R₀ (beyond the fixed radius).
  double time_between(double R0, double R) const;
  /// Growth rate of the shape mode l ≥ 0 of a sphere of radius R: δ̇/δ = s D (l − 1)(l + n − 1)/R²
  /// (l = 0 is the radius itself, dṘ/dR; l = 1 a translation).
  double mode_growth_rate(int l, double R) const;
  /// R after a step dt from R: RK4 on u = R², u̇ = 2c₀√u + 2σ (regular at R = 0, so a
  /// shrinking domain is followed to its end); 0 when the domain vanished within the step.
  double advance(double R, double dt) const;
};

/// One hcp domain of the sharp-front model.
struct SharpDomain {
  std::int64_t track = 0;  ///< its number, 1 … in the case's order (kept when others vanish)
  std::array<double, 3> center{0, 0, 0};
  double radius = 0.0;
};

/// The sharp-front domains from the case's domains (every one a sphere; InputError otherwise).
std::vector<SharpDomain> sharp_domains(const std::vector<Domain>& domains);

/// Advances every domain by dt and removes those that vanished.
void advance_domains(const SharpFrontLaw& law, double dt, std::vector<SharpDomain>& domains);

/// The domains on the grid's nodes: a node is inside a domain within its radius (minimum image
/// along periodic axes).
struct NodeCover {
  double volume_fraction = 0.0;   ///< share of nodes inside at least one domain
  double overlap_fraction = 0.0;  ///< share of nodes inside two or more (domains that met)
  std::vector<std::int64_t> nodes_inside;  ///< per domain
  std::vector<double> indicator;           ///< 1 inside a domain, 0 outside (node order); only if asked
};
NodeCover cover_nodes(const Grid& grid, const std::vector<SharpDomain>& domains, bool indicator);

/// Volume of the n-ball of radius R (n = 1: the segment 2R) and its inverse.
double ball_volume(double R, int dim);
double equivalent_radius(double volume, int dim);

}  // namespace shockfield::phasefield
