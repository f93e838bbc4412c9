#include "shockfield/analysis/gaussian_random_field.hpp"

#include <cmath>
#include <random>

#include "shockfield/analysis/fft.hpp"

namespace shockfield::analysis {

GaussianRandomField gaussian_random_field(std::size_t nx, std::size_t ny, std::size_t nz,
                                          double correlation_length, std::uint64_t seed) {
  GaussianRandomField out;
  out.field = GridField::filled(nx, ny, nz, 0.0);
  const fft::Layout l{out.field.n, out.field.spacing, out.field.dimension()};
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<double> noise(l.real_size());
  for (auto& v : noise) v = normal(rng);
  auto spectrum = fft::forward(l, noise);
  // White noise has ⟨|F|²⟩ = N; filtering by √P gives variance Σ_k P(k) / N over the full k set.
  double variance = 0.0, slope = 0.0;
  const double l2 = correlation_length * correlation_length;
  for (std::size_t c = 0; c < spectrum.size(); ++c) {
    double kx2 = 0.0;
    const double k2 = l.k_squared(c, &kx2);
    const double p = c == 0 ? 0.0 : std::exp(-0.5 * k2 * l2);
    spectrum[c] *= std::sqrt(p);
    variance += l.multiplicity(c) * p;
    slope += l.multiplicity(c) * p * kx2;
  }
  variance /= double(l.real_size());
  out.lambda = slope / (variance * double(l.real_size()));
  const double scale = 1.0 / (std::sqrt(variance) * double(l.real_size()));
  out.field.values = fft::backward(l, std::move(spectrum));
  for (auto& v : out.field.values) v *= scale;
  return out;
}

}  // namespace shockfield::analysis
