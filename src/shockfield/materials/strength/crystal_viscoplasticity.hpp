#pragma once
// Finite-deformation crystal viscoplasticity, Liu et al. (2025) eqs. 18-41 and Algorithm 1 (Kalidindi,
// Bronkhorst & Anand, JMPS 40 (1992) 537; explicit update after Dumoulin et al., Comput. Mater.
// Sci. 46 (2009) 785), one grain per State. Everything is computed in the crystal frame of the
// grain; `orientation` g (crystal → sample, crystal_lattice.hpp) rotates F in and σ out.
//
//   F = Fe·Fp (eq. 18);  Ee = ½(FeᵀFe − I) (eq. 30);  S = C:Ee with cubic C(c11, c12, c44) (eqs. 31-32)
//   τ^α = (Ce·S) : (m0^α ⊗ n0^α), Ce = FeᵀFe (eq. 35)
//   γ̇^α = γ̇0 |τ^α/g^α|^(1/m) sgn τ^α (eq. 37)
//   ġ^α = Σ_β h(γ_tot) q^αβ |γ̇^β|, h = h0 sech²(h0 γ_tot/(g_s − g0)), q^αα = 1, q^αβ = q (eqs. 38-41)
//   or, with HardeningLaw::power, Kalidindi et al.'s (1992, eq. 25) ġ^α = Σ_β q^αβ h^β |γ̇^β|,
//   h^β = h0 |1 − g^β/g_s|^a sgn(1 − g^β/g_s): every g^β saturates at g_s
//   L̄p = Σ γ̇^α m0^α ⊗ n0^α (eq. 20)
//   σ = Fe·S·Feᵀ / det Fe (eq. 34 divided by J)
// Algorithm 1, applied over sub-increments: the power law with m = 0.012 is far too stiff for one
// forward-Euler step of a wave-propagation time step, so the step is cut into sub-increments in
// which no slip changes by more than Δγ_max = κ·m·min g^α / c44 (κ = `substep_factor`, 0.5 by
// default: forward Euler on τ̇ = −c44·γ̇ is stable below 2), with F interpolated linearly. In each:
//   1-4  τ^α, γ̇^α, ġ^α, L̄p from the state at the start of the sub-increment
//   5-6  Fp ← (I − L̄p h)⁻¹ Fp, then Fp ← Fp / det(Fp)^(1/3)
//   7    γ^α += γ̇^α h, g^α += ġ^α h
// then 8-11: Fe = F Fp⁻¹, σ, Re from the polar decomposition Fe = Re Ue, lattice orientation g·Re.
// Table 1 of the paper lists "c14"; it is c44 (cubic crystals have no c14), and its "a = 2.25" is the
// exponent of Kalidindi's power-law hardening, used only by HardeningLaw::power (the paper's eq. 40
// is the sech² law, whose latent systems saturate at g0 + q·(g_s − g0) instead of g_s).
#include <array>
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/materials/strength/crystal_lattice.hpp"

namespace shockfield::materials {

enum class HardeningLaw {
  sech2,  ///< Liu et al. (2025) eq. 40, driven by the accumulated slip γ_tot
  power,  ///< Kalidindi, Bronkhorst & Anand 1992, driven by each system's own g^β
};

struct CrystalViscoplasticity {
  double reference_rate = 1e-3;  ///< γ̇0 [1/s]
  double rate_sensitivity = 0.012;  ///< m [-]
  double initial_resistance = 16e6;  ///< g0 [Pa]
  double saturation_resistance = 148e6;  ///< g_s [Pa]
  double hardening = 180e6;  ///< h0 [Pa]
  double latent_ratio = 1.4;  ///< q [-]
  HardeningLaw hardening_law = HardeningLaw::sech2;
  double hardening_exponent = 2.25;  ///< a of the power law [-]
  double c11 = 186e9, c12 = 93e9, c44 = 46.5e9;  ///< cubic elastic constants [Pa]
  double substep_factor = 0.5;  ///< κ of the sub-increment limit
  std::vector<SlipSystem> systems = fcc_slip_systems();

  /// Liu et al. (2025) Table 1 (annealed OFHC copper, from Kalidindi et al. 1992).
  static CrystalViscoplasticity ofhc_copper();
  /// InputError naming the parameter when one is out of range; `where` prefixes it.
  void validate(const std::string& where) const;

  struct State {
    Mat3 orientation = Mat3::Identity();  ///< g: crystal → sample, as loaded
    Mat3 lattice = Mat3::Identity();      ///< current lattice orientation g·Re (step 11)
    Mat3 fp = Mat3::Identity();           ///< Fp
    std::vector<double> resistance;       ///< g^α [Pa]
    std::vector<double> slip;             ///< γ^α
    double accumulated_slip = 0.0;        ///< γ_tot (eq. 39)
    long long substeps = 0;               ///< sub-increments taken so far (cost diagnostics)
  };
  State initial_state(const Mat3& orientation) const;
  /// Sub-increments one update may take: a stress far beyond the model's range (C44 = 9.2e18 Pa
  /// in a fuzzed material file) needs slip increments so small that the sub-increments never
  /// reach the end of the step (a hang); past this many the update gives up.
  static constexpr long long kMaxSubsteps = 10000;
  /// Advances the grain from F_old to F_new over dt (both in the sample frame) and returns the
  /// Cauchy stress in the sample frame, or a NaN stress (which the run's health check then
  /// diagnoses) when the step needs more than kMaxSubsteps sub-increments.
  Mat3 update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const;
  /// Second Piola-Kirchhoff stress S = C:Ee in the crystal frame (eqs. 30-32).
  Mat3 elastic_stress(const Mat3& fe) const;
};

}  // namespace shockfield::materials
