#pragma once
// Discrete Fourier transforms of real grid fields (FFTW3), shared by the spectral statistics and
// the Gaussian random field generator. Layout: FFTW's r2c half-spectrum, x fastest with
// n[0]/2 + 1 entries, then y, then z.
#include <array>
#include <complex>
#include <vector>

namespace shockfield::analysis::fft {

struct Layout {
  std::array<std::size_t, 3> n{1, 1, 1};  ///< real cells per axis (n[2] = 1 in 2D)
  std::array<double, 3> spacing{1, 1, 1};
  int dimension = 2;

  std::size_t real_size() const { return n[0] * n[1] * n[2]; }
  std::size_t half_x() const { return n[0] / 2 + 1; }
  std::size_t complex_size() const { return half_x() * n[1] * n[2]; }
  /// Wave-vector component along axis a for FFT index i (negative frequencies above n/2).
  double wavenumber(int a, std::size_t i) const;
  /// |k|² and the multiplicity of half-spectrum entry c (2 for entries standing for ±k, else 1).
  double k_squared(std::size_t c, double* kx_squared = nullptr) const;
  double multiplicity(std::size_t c) const;
};

/// Forward transform (unnormalised) of `real` (real_size() values).
std::vector<std::complex<double>> forward(const Layout& layout, const std::vector<double>& real);
/// Backward transform (unnormalised: forward then backward multiplies by real_size()).
std::vector<double> backward(const Layout& layout, std::vector<std::complex<double>> spectrum);

}  // namespace shockfield::analysis::fft
