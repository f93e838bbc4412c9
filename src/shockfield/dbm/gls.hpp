#pragma once
// The GLS liquid–vapour discrete Boltzmann model (Gonnella, Lamura, Sofonea; Xu et al. (2015) §2.3.2) as
// the force term of the BGK equation (eq. 13):
//   I_k = −[A + B·(v_k − u) + (C + C_q)(v_k − u)²] f_k^eq                        (eq. 14)
//   A = −2(C + C_q)T                                                              (eq. 15)
//   B = [∇(P − ρT) + ∇·Λ − ∇(ζ∇·u)]/(ρT)                                          (eq. 16)
//   C = {(P − ρT)∇·u + Λ:∇u − ζ(∇·u)² + aρ²∇·u
//        + K[−½|∇ρ|²∇·u − ρ∇ρ·∇(∇·u) − ∇ρ·∇u·∇ρ]}/(2ρT²)                         (eq. 17)
//   C_q = ∇·[2qρT∇T]/(2ρT²)                                                       (eq. 18)
//   Λ = K∇ρ∇ρ − K(ρ∇²ρ + |∇ρ|²/2)I − ρT∇ρ·∇(K/T) I
// with P the van der Waals or Carnahan–Starling pressure (eq. 19; aρ² is the attraction term of
// either, 9ρ²/8 for the paper's vdW). Σ_k I_k = 0 and the momentum source is −ρTB, so mass and
// momentum are conserved and the total energy e_T = ρT − aρ² + K|∇ρ|²/2 + ρu²/2 is conserved by
// the continuum equations. Spatial derivatives by FFT (seed refs 34–35), so the model needs
// periodic boundaries; the moments used assume b = 2 (γ = 2, no extra degrees of freedom).
// The BGK heat conductivity 2ρTτ becomes 2ρT(τ − q) with the C_q term.
#include <array>
#include <string>
#include <variant>
#include <vector>

#include "shockfield/dbm/simulation.hpp"
#include "shockfield/dbm/spectral.hpp"
#include "shockfield/dbm/tne.hpp"
#include "shockfield/materials/eos/carnahan_starling.hpp"
#include "shockfield/materials/eos/van_der_waals.hpp"

namespace shockfield::dbm {

using GlsEos = std::variant<materials::VanDerWaals, materials::CarnahanStarling>;

double eos_pressure(const GlsEos& eos, double rho, double T);
double eos_attraction(const GlsEos& eos);  // a of the aρ² term
double eos_max_density(const GlsEos& eos);

struct GlsSettings {
  GlsEos eos = materials::VanDerWaals{};
  double K = 1e-4;     // surface tension coefficient
  double zeta = 0.0;   // bulk viscosity ζ
  double q = 0.0;      // heat-conduction correction of eq. 18
};

/// Energy budget of eq. 19's e_T summed over the domain (times the cell area).
struct GlsEnergy {
  double thermal = 0, kinetic = 0, attraction = 0, interfacial = 0;
  double total() const { return thermal + kinetic + attraction + interfacial; }
};

/// Δ (eq. 27/30), its force part Δ^F = M(τI) (eq. 29) and gradient part Δ^G (eq. 31).
struct GlsTne {
  TneFields net, force, gradient;
};

/// The force term of eq. 14, installed as the simulation's source. Must outlive the stepping.
class GlsForce {
 public:
  /// InputError unless all boundaries are periodic, γ = 2, K ≥ 0, ζ ≥ 0, q ≥ 0 and the EOS
  /// parameters are valid.
  GlsForce(Simulation& simulation, const Boundaries& boundaries, const GlsSettings& settings);
  /// The constructor's checks alone, without the FFT arrays (`shockfield run --check`).
  static void validate(const Simulation& simulation, const Boundaries& boundaries, const GlsSettings& settings);
  GlsForce(const GlsForce&) = delete;
  GlsForce& operator=(const GlsForce&) = delete;

  /// I_k of f on every interior cell (Q arrays of lattice.cells()); RunError when a density
  /// leaves the EOS domain.
  void force_term(const std::vector<double>& f, std::vector<double>& out);
  GlsEnergy energy() const;
  GlsTne tne();
  /// Bulk pressure P(ρ, T) of the current state per interior cell (i + nx·j).
  std::vector<double> pressure() const;
  const GlsSettings& settings() const { return settings_; }

 private:
  /// A, B, C + C_q of f (eqs. 15–18) into coef_ (4 per interior cell).
  void coefficients(const std::vector<double>& f);
  /// I_k (from coef_) added to out, or written over it.
  void apply(const std::vector<double>& f, std::vector<double>& out, bool overwrite) const;
  std::vector<Macro> macros(const std::vector<double>& f) const;
  void macros(const std::vector<double>& f, std::vector<Macro>& out) const;

  /// The fields and spectra of coefficients(), kept between calls: allocated per call (≈ 45 arrays of
  /// the lattice's size, 15 calls per 5 steps) their fresh pages took ~12% of a step's CPU.
  struct Scratch {
    std::vector<Macro> m;
    std::vector<double> rho, ux, uy, T, P, rx, ry, lap, uxx, uxy, uyx, uyy, Tx, Ty;  // uxy = ∂y ux, uyx = ∂x uy
    std::vector<double> div, nonideal, Lxx, Lxy, Lyy, hx, hy, divx, divy, nix, niy, dLx, dLy, dh;
    PeriodicSpectral::Spectrum s_rho, s_ux, s_uy, s_T, s_div, s_ni, s_xx, s_xy, s_yy, s_hx, s_hy;
    std::array<PeriodicSpectral::Spectrum, 9> work;  // one per concurrent inverse transform
  };

  Simulation& sim_;
  GlsSettings settings_;
  PeriodicSpectral spectral_;
  std::vector<std::array<double, 4>> coef_;
  Scratch scratch_;
};

}  // namespace shockfield::dbm
