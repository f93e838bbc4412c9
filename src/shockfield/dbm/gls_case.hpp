#pragma once
// The GLS liquid–vapour part of a dbm case file (Xu et al. 2015, eqs. 13–19, §4.3): [model] kind = "gls"
// with its equation of state, K, ζ, q, and [initial] type = "quench" (a homogeneous state at rest
// with seeded density noise). Kept apart from the compressible reader so each model's keys live
// in one place (docs/dbm.md, "Liquid–vapour (GLS) runs").
#include "shockfield/core/config.hpp"
#include "shockfield/dbm/gls.hpp"
#include "shockfield/dbm/gls_stability.hpp"
#include "shockfield/dbm/phase_separation.hpp"

namespace shockfield::dbm {

struct GlsCaseSpec {
  GlsSettings settings;
  Quench quench;
  double threshold = 0.0;    ///< density level of the boundary length L(t); default ρ0
  std::vector<double> extra_thresholds;  ///< more levels of L(t) (series columns L_rho<level>)
  double growth_window = 0.5;  ///< u_DG is the slope of R(t) over [t_SD, t_SD + growth_window]
  double rho_vapour = 0.0;   ///< density range expected in the run (Maxwell construction at the
  double rho_liquid = 0.0;   ///< quench T, or the initial field's range above T_c): EOS domain and Δt check
};

/// [model] keys of kind = "gls": eos, eos_a, eos_b, K, zeta, q (the relaxation time τ is read by
/// the caller). InputError naming the key for values out of range.
GlsSettings read_gls_model(const Config& model, double tau);

/// [initial] type = "quench": rho0, T, noise, seed, noise_wavelength (0: white noise per cell); refuses
/// densities outside the EOS domain and a noise wavelength the lattice cannot hold.
Quench read_quench(const Config& initial, const GlsSettings& gls, const Lattice& lattice);

/// The densities the quench will reach: those of its initial field on `lattice`, widened to the Maxwell
/// construction's vapour and liquid at T below T_c.
void expected_density_range(GlsCaseSpec& spec, const Lattice& lattice);

/// Refuses (under [run].dt) a Δt above the stable limit of gls_step_limit, naming its cause.
void check_gls_time_step(const Config& run, const GlsCaseSpec& spec, const Lattice& lattice,
                         double max_speed, double tau, double dt);

}  // namespace shockfield::dbm
