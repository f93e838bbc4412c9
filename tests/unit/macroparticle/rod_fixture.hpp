#pragma once
// Macroparticle specimens for the tests, built from case text through the same reader the run
// uses (Al: Kittel's e0 = 3.39 eV, 2700 kg/m³, 26.9815 u; p = 4, q = 9).
#include <fmt/format.h>

#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/macroparticle/case_file.hpp"
#include "shockfield/macroparticle/rod.hpp"

namespace shockfield::macroparticle::fixture {

inline const std::string kAluminium = R"(method = "macroparticle"
[material]
cohesive_energy = 3.39
density = 2700.0
atomic_mass = 26.9815
[pair]
p = 4
q = 9
)";

inline MacroparticleCase read_case(const std::string& rest) {
  const Config root = Config::parse(kAluminium + rest, "test.toml");
  return read_macroparticle_case(root);
}

/// A free cube of 3×3×3 cells (r0 = 1 mm) with the given [run] and optional [langevin] text.
inline std::string free_box(const std::string& run, const std::string& langevin = "") {
  return "r0 = 0.001\n[specimen]\nshape = \"box\"\ncells = [3, 3, 3]\n[run]\n" + run + "\n" + langevin;
}

/// The rod of n_phi, n_h pulled in tension at `rate` (1/s) to `strain`.
inline std::string rod(int n_phi, int n_h, double rate, double strain, const std::string& run = "") {
  return fmt::format("[specimen]\ndiameter = 0.014\nn_phi = {}\nn_h = {}\n[loading]\nmode = \"tension\"\n"
                     "strain_rate = {:.17g}\nfinal_strain = {:.17g}\n[run]\n{}\n", n_phi, n_h, rate, strain, run);
}

struct ElasticFit {
  double youngs = 0, poisson = 0;  ///< Pa, 1
  std::size_t particles = 0;
  PairLaw law;
};

/// Pulls the rod of n_phi, n_h to 0.1 % strain in `steps` steps at T = 0 and fits E and ν as the
/// least-squares slopes of stress and −lateral strain against strain over the second half (the
/// first half lets the start-up transient settle).
inline ElasticFit elastic_fit(int n_phi, int n_h, int steps) {
  const MacroparticleCase probe = read_case(rod(n_phi, n_h, 1.0, 0.001));
  const double rate = 0.001 / (steps * probe.dt);
  Rod r(read_case(rod(n_phi, n_h, rate, 0.001)));
  double sx = 0, sy = 0, sl = 0, sxx = 0, sxy = 0, sxl = 0;
  int n = 0;
  for (int s = 1; s <= steps; ++s) {
    r.advance(false);
    if (2 * s < steps) continue;
    const RodMeasures m = r.measure();
    sx += m.strain, sy += m.stress, sl += m.lateral_strain;
    sxx += m.strain * m.strain, sxy += m.strain * m.stress, sxl += m.strain * m.lateral_strain;
    ++n;
  }
  const double var = sxx - sx * sx / n;
  return {(sxy - sx * sy / n) / var, -(sxl - sx * sl / n) / var, r.size(), probe.law};
}

}  // namespace shockfield::macroparticle::fixture
