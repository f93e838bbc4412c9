#pragma once
// Counter-based random numbers: a value is a pure function of (seed, stream, counter), so
// results do not depend on the thread count or on where a run was stopped and resumed, and no
// generator state has to be checkpointed. Mixing: SplitMix64 finaliser (Steele et al., 2014).
#include <cmath>
#include <cstdint>

namespace shockfield::rng {

inline std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline std::uint64_t hash(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0) {
  return mix(mix(mix(mix(seed) ^ a) ^ b) ^ c);
}

/// Uniform in (0, 1), never 0 or 1.
inline double uniform(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0) {
  return (static_cast<double>(hash(seed, a, b, c) >> 11) + 0.5) * 0x1.0p-53;
}

/// Standard normal by Box–Muller on two independent uniforms.
inline double normal(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0) {
  const double u1 = uniform(seed, a, b, 2 * c);
  const double u2 = uniform(seed, a, b, 2 * c + 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

}  // namespace shockfield::rng
