#include "shockfield/pd/bond_stretch.hpp"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shockfield::pd {
namespace {

// r, e and s of bonds [k, k + 1] as packed SSE2 operations (x86-64's baseline; the compiler does
// not pack std::sqrt itself, which may set errno): the same IEEE values as measure_one and divide_pull_one.
#if defined(__SSE2__)
inline void measure_two(std::size_t k, const double* x, const double* y, const double* z, const double* r0,
                        double* r, double* e, double* s) {
  const __m128d vx = _mm_loadu_pd(x + k), vy = _mm_loadu_pd(y + k), vz = _mm_loadu_pd(z + k);
  const __m128d length =
      _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, vx), _mm_mul_pd(vy, vy)), _mm_mul_pd(vz, vz)));
  const __m128d reference = _mm_loadu_pd(r0 + k);
  __m128d ext = _mm_sub_pd(length, reference);
  const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), ext);
  ext = _mm_andnot_pd(_mm_cmplt_pd(magnitude, _mm_set1_pd(kNearZeroExtension)), ext);  // |e| < NEAR_ZERO → 0
  _mm_storeu_pd(r + k, length);
  _mm_storeu_pd(e + k, ext);
  _mm_storeu_pd(s + k, _mm_div_pd(ext, reference));
}

inline void divide_pull_two(std::size_t k, const double* r, double* pull) {
  const __m128d length = _mm_loadu_pd(r + k);
  const __m128d positive = _mm_cmpgt_pd(length, _mm_setzero_pd());
  // r = 0 → divide by 1 and keep 0 (no force along an undefined direction).
  const __m128d divisor = _mm_or_pd(_mm_and_pd(positive, length), _mm_andnot_pd(positive, _mm_set1_pd(1.0)));
  _mm_storeu_pd(pull + k, _mm_and_pd(positive, _mm_div_pd(_mm_loadu_pd(pull + k), divisor)));
}
#endif

inline void measure_one(std::size_t k, const double* x, const double* y, const double* z, const double* r0, double* r,
                        double* e, double* s) {
  r[k] = std::sqrt(x[k] * x[k] + y[k] * y[k] + z[k] * z[k]);
  const double ext = r[k] - r0[k];
  e[k] = std::abs(ext) < kNearZeroExtension ? 0.0 : ext;
  s[k] = e[k] / r0[k];
}

inline void divide_pull_one(std::size_t k, const double* r, double* pull) {
  pull[k] = r[k] > 0.0 ? pull[k] / r[k] : 0.0;
}

}  // namespace

void BondStretches::measure(const Family& family, std::size_t i, const std::vector<Vec3>& y) {
  const int b0 = family.begin(i);
  const auto m = static_cast<std::size_t>(family.end(i) - b0);
  if (r.size() < m)
    for (auto* a : {&dx, &dy, &dz, &r, &extension, &stretch, &pull}) a->resize(m);
  const Vec3 yi = y[i];
  const int* neighbor = family.neighbor.data() + b0;
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3& yj = y[static_cast<std::size_t>(neighbor[k])];
    dx[k] = yj[0] - yi[0];
    dy[k] = yj[1] - yi[1];
    dz[k] = yj[2] - yi[2];
  }
  const double* r0 = family.length.data() + b0;
  std::size_t k = 0;
#if defined(__SSE2__)
  for (; k + 2 <= m; k += 2) measure_two(k, dx.data(), dy.data(), dz.data(), r0, r.data(), extension.data(), stretch.data());
#endif
  for (; k < m; ++k) measure_one(k, dx.data(), dy.data(), dz.data(), r0, r.data(), extension.data(), stretch.data());
}

void BondStretches::divide_pull_by_length(std::size_t count) {
  std::size_t k = 0;
#if defined(__SSE2__)
  for (; k + 2 <= count; k += 2) divide_pull_two(k, r.data(), pull.data());
#endif
  for (; k < count; ++k) divide_pull_one(k, r.data(), pull.data());
}

}  // namespace shockfield::pd
