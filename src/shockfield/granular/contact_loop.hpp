#pragma once
// The generic force loop of a chain, written once for every contact law (contact_law.hpp).
// Grain i's state is its displacement w_i from the initial configuration (+ down) and velocity
// v_i, so contact k = (k, k+1) has overlap δ_k = δ⁰_k + w_k − w_{k+1} and overlap rate
// δ̇_k = v_k − v_{k+1}: measuring from the static equilibrium keeps overlaps of 1e-9 m exact
// next to depths of km. Two branch-free passes that the compiler vectorises: the contact forces
// F_k, then the net force on each grain f_i = F_{i−1} − F_i + m_i g (+ the wall, + the push on
// grain 0). A chain step is a few flops per grain, so threads only pay on long chains
// (bench/RESULTS.md, "## Granular"): below kThreadedGrains the loops run on one thread.
#include <cstddef>

#include "shockfield/granular/contact_law.hpp"

namespace shockfield::granular {

/// Chains shorter than this run their force loops on one thread.
inline constexpr std::size_t kThreadedGrains = 200000;

/// The arrays a force evaluation reads and writes (n grains, n − 1 contacts).
struct ChainArrays {
  std::size_t n = 0;
  const double* w = nullptr;
  const double* v = nullptr;
  const double* kappa = nullptr;
  const double* rest_overlap = nullptr;
  const double* mass = nullptr;
  double* contact_force = nullptr;  ///< F_k, size n − 1
  double* force = nullptr;          ///< f_i, size n
};

/// F_k of every contact, then f_i; `wall_force` is the force of the bottom wall on grain n − 1
/// (upward, subtracted), `top_force` the external push on grain 0 (+ down).
template <ContactLaw L>
void evaluate_chain_forces(const L& law, const ChainArrays& a, double gravity, double wall_force,
                           double top_force) {
  const std::size_t nc = a.n - 1;
  const double* w = a.w;
  const double* v = a.v;
  const double* kappa = a.kappa;
  const double* rest = a.rest_overlap;
  const double* m = a.mass;
  double* F = a.contact_force;
  double* f = a.force;
  const bool threaded = a.n >= kThreadedGrains;
#pragma omp parallel if (threaded)
  {
#pragma omp for simd schedule(static)
    for (std::size_t k = 0; k < nc; ++k)
      F[k] = law.force(kappa[k], rest[k] + w[k] - w[k + 1], v[k] - v[k + 1]);
#pragma omp for simd schedule(static)
    for (std::size_t i = 1; i < nc; ++i) f[i] = F[i - 1] - F[i] + m[i] * gravity;
  }
  f[0] = -F[0] + m[0] * gravity + top_force;
  f[nc] = F[nc - 1] + m[nc] * gravity - wall_force;
}

}  // namespace shockfield::granular
