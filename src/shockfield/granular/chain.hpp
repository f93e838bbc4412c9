#pragma once
// A chain of spheres on a line (grain 0 on top, index = depth order), stored as structure of
// arrays: per grain mass and radius, per contact k (between grains k and k+1) the Hertz
// coefficient κ_k and the rest overlap. The state of a run is measured from the initial
// configuration (the static equilibrium under gravity, computed exactly: contact k carries the
// weight W_k = g Σ_{i≤k} m_i of the grains above it, so δ_k = (W_k/κ_k)^{2/3}, and the bottom
// wall carries the whole weight). Depth grows downward; gravity points down the chain.
#include <cstddef>
#include <optional>
#include <vector>

namespace shockfield::granular {

/// One grain whose properties differ from the chain's (an impurity): the ratios multiply the
/// chain's values. radius_ratio also scales the mass by radius_ratio³ (same density). Its own
/// Poisson ratio, if given, replaces the chain's in the Hertz κ of its two contacts (and the wall's).
struct Impurity {
  long long index = 0;
  double mass_ratio = 1.0;
  double radius_ratio = 1.0;
  double modulus_ratio = 1.0;
  std::optional<double> poisson_ratio;  ///< ν of this grain; none: the chain's
};

enum class WallKind { none, rigid, elastic };

/// What a chain is made of; SI units.
struct ChainSpec {
  long long grains = 100;
  double radius = 1e-3;            ///< R [m]
  double density = 7850.0;         ///< ρ [kg/m³]; m = (4/3)πR³ρ
  double youngs_modulus = 200e9;   ///< E [Pa]
  double poisson_ratio = 0.3;      ///< ν
  double gravity = 0.0;            ///< g along the chain, toward the bottom [m/s²]; 0: horizontal
  double damping = 0.0;            ///< viscous contact damping γ [N·s/m]
  double gap = 0.0;                ///< initial gap between neighbours [m] (horizontal chains)
  WallKind wall = WallKind::none;  ///< the bottom wall (flat, fixed)
  double wall_youngs_modulus = 0.0;  ///< elastic wall's E [Pa]
  double wall_poisson_ratio = 0.0;   ///< elastic wall's ν
  std::vector<Impurity> impurities;
};

struct Chain {
  // per grain
  std::vector<double> mass, inv_mass, radius, youngs_modulus, poisson_ratio;
  std::vector<double> depth;  ///< initial centre depth z_i [m] (z_0 = R_0, grain 0 touching z = 0)
  // per contact k = (k, k+1), size N − 1
  std::vector<double> kappa;         ///< Hertz κ_k [N/m^{3/2}]
  std::vector<double> rest_overlap;  ///< δ_k in the initial configuration [m]
  // the bottom wall (contact of grain N − 1 with a flat wall)
  bool has_wall = false;
  double wall_kappa = 0.0;
  double wall_rest_overlap = 0.0;
  double gravity = 0.0;
  double damping = 0.0;

  std::size_t size() const { return mass.size(); }
  std::size_t contacts() const { return kappa.size(); }
};

/// Builds the chain in its static equilibrium. InputError (without a file: the case reader has
/// already named keys) for sizes, radii, moduli or impurities that make no chain.
Chain build_chain(const ChainSpec& spec);

}  // namespace shockfield::granular
