#include "shockfield/analysis/fft.hpp"

#include <fftw3.h>

#include <numbers>

namespace shockfield::analysis::fft {
namespace {

std::array<int, 3> fftw_dims(const Layout& l) {  // slowest first
  if (l.dimension == 3) return {int(l.n[2]), int(l.n[1]), int(l.n[0])};
  return {int(l.n[1]), int(l.n[0]), 1};
}

}  // namespace

double Layout::wavenumber(int a, std::size_t i) const {
  const auto m = static_cast<double>(n[a]);
  const double f = i <= n[a] / 2 ? double(i) : double(i) - m;
  return 2.0 * std::numbers::pi * f / (m * spacing[a]);
}

double Layout::k_squared(std::size_t c, double* kx_squared) const {
  const std::size_t hx = half_x();
  const double kx = wavenumber(0, c % hx), ky = wavenumber(1, (c / hx) % n[1]),
               kz = dimension == 3 ? wavenumber(2, c / (hx * n[1])) : 0.0;
  if (kx_squared) *kx_squared = kx * kx;
  return kx * kx + ky * ky + kz * kz;
}

double Layout::multiplicity(std::size_t c) const {
  const std::size_t ix = c % half_x();
  return (ix == 0 || (n[0] % 2 == 0 && ix == n[0] / 2)) ? 1.0 : 2.0;
}

std::vector<std::complex<double>> forward(const Layout& layout, const std::vector<double>& real) {
  std::vector<double> in(real);
  std::vector<std::complex<double>> out(layout.complex_size());
  const auto d = fftw_dims(layout);
  auto* o = reinterpret_cast<fftw_complex*>(out.data());
  fftw_plan p = layout.dimension == 3 ? fftw_plan_dft_r2c_3d(d[0], d[1], d[2], in.data(), o, FFTW_ESTIMATE)
                                      : fftw_plan_dft_r2c_2d(d[0], d[1], in.data(), o, FFTW_ESTIMATE);
  fftw_execute(p);
  fftw_destroy_plan(p);
  return out;
}

std::vector<double> backward(const Layout& layout, std::vector<std::complex<double>> spectrum) {
  std::vector<double> out(layout.real_size());
  const auto d = fftw_dims(layout);
  auto* i = reinterpret_cast<fftw_complex*>(spectrum.data());
  fftw_plan p = layout.dimension == 3 ? fftw_plan_dft_c2r_3d(d[0], d[1], d[2], i, out.data(), FFTW_ESTIMATE)
                                      : fftw_plan_dft_c2r_2d(d[0], d[1], i, out.data(), FFTW_ESTIMATE);
  fftw_execute(p);
  fftw_destroy_plan(p);
  return out;
}

}  // namespace shockfield::analysis::fft
