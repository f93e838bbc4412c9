#include "shockfield/materials/strength/crystal_compression.hpp"

#include <cmath>

namespace shockfield::materials {

Mat3 isochoric_compression(double strain, int axis) {
  Vec3 stretch = Vec3::Constant(std::exp(-0.5 * strain));  // eq. 44
  stretch[axis] = std::exp(strain);
  return stretch.asDiagonal();
}

double axial_stress(const Mat3& sigma, int axis) {
  return 1.5 * sigma(axis, axis) - 0.5 * sigma.trace();  // eq. 45: σ_aa − ½(sum of the two lateral σ)
}

long long CompressionPath::steps() const {
  return static_cast<long long>(std::ceil(std::abs(end_strain) / strain_increment - 1e-9));
}

TaylorAggregate::State compress_aggregate(const TaylorAggregate& aggregate, const CompressionPath& path,
                                          const CompressionObserver& observe, int axis) {
  TaylorAggregate::State state = aggregate.initial_state();
  const auto grains = static_cast<long long>(state.size());
  std::vector<Mat3> sigma(state.size(), Mat3::Zero());
  observe(0, 0.0, 0.0, state, sigma, Mat3::Zero());
  const long long steps = path.steps();
  const double dt = path.end_strain / path.strain_rate / static_cast<double>(steps);
  Mat3 f_old = Mat3::Identity();
  for (long long k = 1; k <= steps; ++k) {
    const double t = dt * static_cast<double>(k), strain = k == steps ? path.end_strain : path.strain_rate * t;
    const Mat3 f_new = isochoric_compression(strain, axis);
#pragma omp parallel for schedule(dynamic)
    for (long long g = 0; g < grains; ++g) {
      const auto i = static_cast<std::size_t>(g);
      sigma[i] = aggregate.crystal.update(state[i], f_old, f_new, dt);
    }
    Mat3 sum = Mat3::Zero();
    for (const Mat3& s : sigma) sum += s;
    observe(k, t, strain, state, sigma, sum / static_cast<double>(grains));  // eq. 43
    f_old = f_new;
  }
  return state;
}

}  // namespace shockfield::materials
