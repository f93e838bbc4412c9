#include "shockfield/dbm/spectral.hpp"

#include <fftw3.h>

#include <cmath>
#include <numbers>

namespace shockfield::dbm {

double PeriodicSpectral::derivative_filter(double eta_x, double eta_y) {
  return std::exp(-36.0 * (std::pow(eta_x, 8) + std::pow(eta_y, 8)));
}

double PeriodicSpectral::state_filter(double eta_x, double eta_y) {
  return std::exp(-36.0 * (std::pow(eta_x, 16) + std::pow(eta_y, 16)));
}

PeriodicSpectral::PeriodicSpectral(int nx, int ny, double dx, double dy)
    : nx_(nx), ny_(ny), hx_(nx / 2 + 1), kx_(hx_), ky_(ny) {
  for (int i = 0; i < hx_; ++i) kx_[i] = 2.0 * std::numbers::pi * i / (nx * dx);
  for (int j = 0; j < ny; ++j)
    ky_[j] = 2.0 * std::numbers::pi * (j <= ny / 2 ? j : j - ny) / (ny * dy);
  // Exponential filter exp(−36 η^8) per axis (η = |k|/k_Nyquist): it leaves the resolved modes
  // alone and removes the Nyquist mode, which a centred spectral derivative leaves uncoupled
  // (odd–even decoupling that the non-linear force otherwise drives unstable).
  filter_.resize(static_cast<std::size_t>(hx_) * ny);
  state_filter_.resize(filter_.size());
  for (int iy = 0; iy < ny; ++iy)
    for (int ix = 0; ix < hx_; ++ix) {
      const double ex = 2.0 * ix / nx, ey = 2.0 * std::abs(iy <= ny / 2 ? iy : iy - ny) / ny;
      filter_[ix + static_cast<std::size_t>(hx_) * iy] = derivative_filter(ex, ey);
      state_filter_[ix + static_cast<std::size_t>(hx_) * iy] = state_filter(ex, ey);
    }
  std::vector<double> real(size());
  Spectrum spec(static_cast<std::size_t>(hx_) * ny_);
  auto* c = reinterpret_cast<fftw_complex*>(spec.data());
  // FFTW_ESTIMATE never touches the arrays, and new-array execution needs only equal (16-byte)
  // alignment, which std::vector's allocator gives every array.
  forward_plan_ = fftw_plan_dft_r2c_2d(ny, nx, real.data(), c, FFTW_ESTIMATE);
  backward_plan_ = fftw_plan_dft_c2r_2d(ny, nx, c, real.data(), FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
}

PeriodicSpectral::~PeriodicSpectral() {
  fftw_destroy_plan(static_cast<fftw_plan>(forward_plan_));
  fftw_destroy_plan(static_cast<fftw_plan>(backward_plan_));
}

PeriodicSpectral::Spectrum PeriodicSpectral::forward(const std::vector<double>& field) const {
  Spectrum out;
  forward(field, out);
  return out;
}

std::vector<double> PeriodicSpectral::derivative(const Spectrum& s, int ax, int ay) const {
  Spectrum work;
  std::vector<double> out;
  derivative(s, ax, ay, work, out);
  return out;
}

std::vector<double> PeriodicSpectral::divergence(const Spectrum& sx, const Spectrum& sy) const {
  Spectrum work;
  std::vector<double> out;
  divergence(sx, sy, work, out);
  return out;
}

std::vector<double> PeriodicSpectral::laplacian(const Spectrum& s) const {
  Spectrum work;
  std::vector<double> out;
  laplacian(s, work, out);
  return out;
}

void PeriodicSpectral::forward(const std::vector<double>& field, Spectrum& out) const {
  out.resize(spectrum_size());
  // FFTW's r2c transforms leave their input alone (no FFTW_DESTROY_INPUT).
  fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_plan_), const_cast<double*>(field.data()),
                       reinterpret_cast<fftw_complex*>(out.data()));
}

void PeriodicSpectral::backward(Spectrum& s, std::vector<double>& out) const {
  out.resize(size());
  fftw_execute_dft_c2r(static_cast<fftw_plan>(backward_plan_), reinterpret_cast<fftw_complex*>(s.data()), out.data());
  const double norm = 1.0 / static_cast<double>(size());
  for (double& v : out) v *= norm;
}

std::complex<double> PeriodicSpectral::factor(int ix, int iy, int ax, int ay) const {
  std::complex<double> f = filter_[ix + static_cast<std::size_t>(hx_) * iy];
  for (int a = 0; a < ax; ++a) f *= std::complex<double>(0.0, kx_[ix]);
  for (int a = 0; a < ay; ++a) f *= std::complex<double>(0.0, ky_[iy]);
  return f;
}

void PeriodicSpectral::derivative(const Spectrum& s, int ax, int ay, Spectrum& work, std::vector<double>& out) const {
  work.resize(s.size());
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 0; ix < hx_; ++ix) {
      const std::size_t c = ix + static_cast<std::size_t>(hx_) * iy;
      work[c] = factor(ix, iy, ax, ay) * s[c];
    }
  backward(work, out);
}

void PeriodicSpectral::divergence(const Spectrum& sx, const Spectrum& sy, Spectrum& work,
                                  std::vector<double>& out) const {
  work.resize(sx.size());
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 0; ix < hx_; ++ix) {
      const std::size_t c = ix + static_cast<std::size_t>(hx_) * iy;
      work[c] = factor(ix, iy, 1, 0) * sx[c] + factor(ix, iy, 0, 1) * sy[c];
    }
  backward(work, out);
}

void PeriodicSpectral::laplacian(const Spectrum& s, Spectrum& work, std::vector<double>& out) const {
  work.resize(s.size());
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 0; ix < hx_; ++ix) {
      const std::size_t c = ix + static_cast<std::size_t>(hx_) * iy;
      work[c] = (factor(ix, iy, 2, 0) + factor(ix, iy, 0, 2)) * s[c];
    }
  backward(work, out);
}

void PeriodicSpectral::convect(std::complex<double>* s, double vx, double vy) const {
  for (int iy = 0; iy < ny_; ++iy)
    for (int ix = 0; ix < hx_; ++ix) {
      const std::size_t c = ix + static_cast<std::size_t>(hx_) * iy;
      s[c] = factor(ix, iy, 1, 0) * (s[c] * vx) + factor(ix, iy, 0, 1) * (s[c] * vy);
    }
}

void PeriodicSpectral::apply_state_filter(std::complex<double>* s) const {
  for (std::size_t c = 0; c < state_filter_.size(); ++c) s[c] *= state_filter_[c];
}

SpectralBatch::SpectralBatch(const PeriodicSpectral& grid, int count, int row_stride, std::size_t field_stride)
    : nx_(grid.nx()), ny_(grid.ny()), count_(count), row_stride_(row_stride), field_stride_(field_stride) {
  const int n[2] = {ny_, nx_}, embed[2] = {ny_, row_stride};
  const auto spectrum = static_cast<int>(grid.spectrum_size());
  std::vector<double> real(field_stride * count);
  std::vector<std::complex<double>> spectra(grid.spectrum_size() * count);
  auto* c = reinterpret_cast<fftw_complex*>(spectra.data());
  const auto stride = static_cast<int>(field_stride);
  forward_plan_ = fftw_plan_many_dft_r2c(2, n, count, real.data(), embed, 1, stride, c, nullptr, 1, spectrum,
                                         FFTW_ESTIMATE);
  backward_plan_ = fftw_plan_many_dft_c2r(2, n, count, c, nullptr, 1, spectrum, real.data(), embed, 1, stride,
                                          FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
}

SpectralBatch::~SpectralBatch() {
  fftw_destroy_plan(static_cast<fftw_plan>(forward_plan_));
  fftw_destroy_plan(static_cast<fftw_plan>(backward_plan_));
}

void SpectralBatch::forward(const double* fields, std::complex<double>* spectra) const {
  fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_plan_), const_cast<double*>(fields),
                       reinterpret_cast<fftw_complex*>(spectra));
}

void SpectralBatch::backward(std::complex<double>* spectra, double* fields) const {
  fftw_execute_dft_c2r(static_cast<fftw_plan>(backward_plan_), reinterpret_cast<fftw_complex*>(spectra), fields);
  const double norm = 1.0 / (static_cast<double>(nx_) * ny_);
  for (int m = 0; m < count_; ++m)
    for (int j = 0; j < ny_; ++j) {
      double* row = fields + m * field_stride_ + static_cast<std::size_t>(row_stride_) * j;
      for (int i = 0; i < nx_; ++i) row[i] *= norm;
    }
}

}  // namespace shockfield::dbm
