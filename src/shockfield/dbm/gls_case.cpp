#include "shockfield/dbm/gls_case.hpp"

#include <optional>
#include <tuple>

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

// The smallest and largest density ρ0(1 + noise·ξ) of the quench's initial field on the lattice's cells.
std::pair<double, double> initial_density_range(const Quench& q, const QuenchNoise& xi) {
  const auto [xi_min, xi_max] = xi.extremes_on_cells();
  return {q.rho0 * (1.0 + q.noise * xi_min), q.rho0 * (1.0 + q.noise * xi_max)};
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
  std::optional<QuenchNoise> xi;
  try {
    xi.emplace(q.noise_field(lattice));
  } catch (const InputError& e) {
    initial.fail("noise_wavelength", e.what());
  }
  // The densities the field takes on the cells (band-limited noise reaches |ξ| ≈ 4× its rms there; the
  // rigorous bound s Σ|A_mn| of its modes is ~6× looser and refused noise ≥ 0.077 at ρ0 = 1).
  const auto [rho_min, rho_max] = initial_density_range(q, *xi);
  if (rho_max >= max_density)
    initial.fail("noise", fmt::format("the largest initial density rho0 (1 + noise max xi) = {} reaches the EOS limit "
                                      "{} (excluded volume)", rho_max, max_density));
  if (rho_min <= 0.0)
    initial.fail("noise", fmt::format("the smallest initial density rho0 (1 + noise min xi) = {} is not positive",
                                      rho_min));
  return q;
}

void expected_density_range(GlsCaseSpec& spec, const Lattice& lattice) {
  const Quench& q = spec.quench;
  // The initial densities ρ0(1 + noise·ξ) at the cells: |ξ| ≤ 1 for white noise, up to ~4·rms for
  // band-limited noise.
  std::tie(spec.rho_vapour, spec.rho_liquid) = initial_density_range(q, q.noise_field(lattice));
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
