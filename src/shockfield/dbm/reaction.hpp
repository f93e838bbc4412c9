#pragma once
// One-step reactive DBM for detonation (Xu et al. 2015, §2.3.3 and §4.3; the chemical-reaction DBM of
// Yan, Xu, Zhang, Ying, Li, Front. Phys. 8, 94 (2013), refs 39–40 of the paper). A progress variable
// λ (mass fraction of reactant, 1 fresh → 0 burnt) is carried as the reactant density φ = ρλ:
//   ∂φ/∂t + ∇·(φu) = −ρω,                    ω = −dλ/dt ≥ 0 the consumption rate,
// and the reaction heat Q per unit mass enters the kinetic equation as the change of f^eq with
// the temperature the reaction adds (Yan et al.: the reaction raises T at fixed ρ and u):
//   ∂f_k/∂t + v_k·∇f_k = −(f_k − f_k^eq)/τ + R_k,    R_k = ∂f_k^eq/∂T · (dT/dt)_chem,
//   (dT/dt)_chem = 2Qω/b,                  f^eq = C⁻¹·M^eq (eqs. 20–26), so R = C⁻¹·∂M^eq/∂T·2Qω/b.
// R adds no mass or momentum and adds ρQω to the energy E = ρ(bT + u²)/2 (eq. 22), so E + Qφ is
// conserved. The mass flux of φ is the DBM's own: at each cell face the NND face values of f_k
// (the ones the convection uses) give the face mass flux Σ_k v_k f_k, which carries the upwind,
// minmod-limited face value of λ; a uniform λ therefore stays uniform.
//
// Rate laws (only where T ≥ T_ign):
//   Arrhenius:  ω = k λ exp(−E_a/T)
//   Cochran, a pressure-dependent rate (λ_p = 1 − λ the product fraction):
//               dλ_p/dt = ω1 p^m (1 − λ_p) + ω2 p^n λ_p (1 − λ_p),  i.e. ω = ω1 p^m λ + ω2 p^n λ(1 − λ);
//   the pressure-dependent rate of the Xu-group DBM papers (Lin, Xu, Zhang, Li, arXiv:1308.0653),
//   written from memory: the form is not checked against the paper.
//
// φ is advanced with the same third-order Runge–Kutta stages as f: the source installed on the
// Simulation is called once per stage, in order, with the stage's f (Simulation::step), and keeps
// φ's stages in step with it.
#include <vector>

#include "shockfield/dbm/boundary.hpp"
#include "shockfield/dbm/simulation.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

enum class RateKind { arrhenius, cochran };

struct RateLaw {
  RateKind kind = RateKind::arrhenius;
  double heat_release = 1.0;          ///< Q per unit mass of reactant
  double ignition_temperature = 0.0;  ///< no reaction below T_ign
  double rate = 1.0;                  ///< Arrhenius k
  double activation = 0.0;            ///< Arrhenius E_a (in units of T)
  double omega1 = 0.0, omega2 = 0.0, m = 1.0, n = 1.0;  ///< Cochran

  /// ω = −dλ/dt for reactant fraction λ at density ρ and temperature T (p = ρT).
  double consumption(double lambda, double rho, double T) const;
};

/// ∂M^eq/∂T at fixed ρ, u (the T-derivative of equilibrium_moments(), same order).
Eigen::Matrix<double, kMoments, 1> equilibrium_moments_dT(double rho, double ux, double uy,
                                                          double T, double b);

class ReactiveFlow {
 public:
  /// Installs the reaction source on `simulation` (which must outlive this object and use NND
  /// convection). `inflow_lambda` is λ of the gas entering through inflow sides.
  ReactiveFlow(Simulation& simulation, const Boundaries& boundaries, const RateLaw& law,
               double inflow_lambda = 1.0);
  ReactiveFlow(const ReactiveFlow&) = delete;
  ReactiveFlow& operator=(const ReactiveFlow&) = delete;

  /// φ = ρ(f)·λ(x, y) on every interior cell (call after the Simulation's f is set).
  void initialize(const std::function<double(double x, double y)>& lambda);
  const RateLaw& law() const { return law_; }
  double lambda(int i, int j) const;
  /// ω of cell (i, j) in the current state.
  double consumption(int i, int j) const;
  /// Q·Σφ·ΔxΔy over the interior: the chemical energy still stored in the reactant.
  double chemical_energy() const;
  /// φ per storage cell (lattice.cells(); interior cells meaningful), for checkpoints.
  std::vector<double>& reactant_density() { return phi_; }
  const std::vector<double>& reactant_density() const { return phi_; }

 private:
  void source(const std::vector<double>& f, std::vector<double>& rhs);
  /// dφ/dt of the stage (f, φ) into dphi_, and R_k added to rhs.
  void stage_rates(const std::vector<double>& f, const std::vector<double>& phi,
                   std::vector<double>& rhs);
  /// λ on interior and ghost cells of (f, φ) into lambda_.
  void fill_lambda(const std::vector<double>& f, const std::vector<double>& phi);
  /// Face mass flux Σ_k v_k f_k^face at the face between c and c + s (NND face values).
  double face_mass_flux(const std::vector<double>& f, std::size_t c, std::ptrdiff_t s,
                        const std::vector<double>& v) const;

  Simulation& sim_;
  Boundaries boundaries_;
  RateLaw law_;
  double inflow_lambda_;
  std::vector<double> phi_, phi0_, phi_stage_, dphi_, lambda_;
  int stage_ = 0;
  long long stage_step_ = -1;
};

}  // namespace shockfield::dbm
