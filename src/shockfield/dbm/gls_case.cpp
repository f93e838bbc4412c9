#include "shockfield/dbm/gls_case.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/dbm/coexistence.hpp"

namespace shockfield::dbm {
namespace {

template <class E>
E read_eos_parameters(const Config& model, E eos) {
  eos.a = model.get_double_or("eos_a", eos.a, Range::positive());
  eos.b = model.get_double_or("eos_b", eos.b, Range::positive());
  return eos;
}

}  // namespace

GlsSettings read_gls_model(const Config& model, double tau) {
  GlsSettings s;
  // vdW: the paper's a = 9/8, b = 1/3 (T_c = ρ_c = 1); Carnahan–Starling: a, b with T_c = ρ_c = 1
  // (bρ_c = 0.5218, bT_c/a = 0.3773).
  if (model.get_choice_or("eos", {"vdw", "carnahan_starling"}, "vdw") == "vdw")
    s.eos = read_eos_parameters(model, materials::VanDerWaals{});
  else
    s.eos = read_eos_parameters(model, materials::CarnahanStarling{0.5218 / 0.3773, 0.5218});
  s.K = model.get_double("K", Range::non_negative());
  s.zeta = model.get_double_or("zeta", 0.0, Range::non_negative());
  s.q = model.get_double_or("q", 0.0);
  if (!(s.q < tau))
    model.fail("q", fmt::format("{} must be < tau = {}: the heat conductivity 2 rho T (tau - q) must be positive; "
                                "q < 0 raises it above the BGK value 2 rho T tau",
                                s.q, tau));
  return s;
}

Quench read_quench(const Config& initial, const GlsSettings& gls, const Lattice& lattice) {
  Quench q;
  const double max_density = eos_max_density(gls.eos);
  q.rho0 = initial.get_double("rho0", {0.0, max_density, true, true});
  q.T = initial.get_double("T", Range::positive());
  // noise > 0: a uniform quench is a steady state of the model and never separates (nothing to measure).
  q.noise = initial.get_double_or("noise", 0.01, {0.0, 1.0, true, true});
  q.seed = static_cast<std::uint64_t>(initial.get_int_or("seed", 1, Range::non_negative()));
  q.noise_wavelength = initial.get_double_or("noise_wavelength", 0.0, Range::non_negative());
  double bound = 1.0;
  try {
    bound = q.noise_field(lattice).bound();
  } catch (const InputError& e) {
    initial.fail("noise_wavelength", e.what());
  }
  if (q.rho0 * (1.0 + q.noise * bound) >= max_density)
    initial.fail("noise", fmt::format("rho0 (1 + noise max|xi|) = {} reaches the EOS limit {} (excluded volume)",
                                      q.rho0 * (1.0 + q.noise * bound), max_density));
  if (q.rho0 * (1.0 - q.noise * bound) <= 0.0)
    initial.fail("noise", fmt::format("rho0 (1 - noise max|xi|) = {} is not positive (max|xi| = {:.3g})",
                                      q.rho0 * (1.0 - q.noise * bound), bound));
  return q;
}

void expected_density_range(GlsCaseSpec& spec, const Lattice& lattice) {
  const Quench& q = spec.quench;
  // The initial densities ρ0(1 + noise·ξ) at the cells: |ξ| ≤ 1 for white noise, up to ~4·rms for
  // band-limited noise (its rigorous bound s Σ|A_mn| is ~6x looser and would cut the Δt limit through ζ/ρ_vapour).
  const auto [xi_min, xi_max] = q.noise_field(lattice).extremes_on_cells();
  spec.rho_vapour = q.rho0 * (1.0 + q.noise * xi_min), spec.rho_liquid = q.rho0 * (1.0 + q.noise * xi_max);
  std::visit(
      [&](const auto& eos) {
        if (q.T >= critical_point(eos).T) return;
        const Coexistence co = maxwell_construction(eos, q.T);
        spec.rho_vapour = std::min(spec.rho_vapour, co.rho_vapour);
        spec.rho_liquid = std::max(spec.rho_liquid, co.rho_liquid);
      },
      spec.settings.eos);
}

void check_gls_time_step(const Config& run, const GlsCaseSpec& spec, const Lattice& lattice,
                         double max_speed, double tau, double dt) {
  const GlsStepLimit limit =
      gls_step_limit(spec.settings, lattice, max_speed, tau, spec.quench.T, spec.rho_vapour, spec.rho_liquid);
  if (dt > limit.dt)
    run.fail("dt", fmt::format("{:.4g} is above the stable limit {:.4g} of the GLS model, set by {} (bounds: free "
                               "streaming {:.3g}, capillary waves {:.3g}, diffusion {:.3g}, collision {:.3g}; "
                               "liquid density {:.4g}); use dt <= {:.4g}",
                               dt, limit.dt, limit.cause, limit.streaming, limit.capillary, limit.diffusion,
                               limit.collision, spec.rho_liquid, limit.dt));
}

}  // namespace shockfield::dbm
