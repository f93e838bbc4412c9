#pragma once
// Spatial derivatives of periodic 2D fields by FFT (FFTW3), as the paper's refs 34–35 use for the
// GLS force term: a field is transformed once, and any derivative ∂x^a ∂y^b of it is (ik_x)^a
// (ik_y)^b in Fourier space, transformed back, with an exponential filter on the highest modes
// (none on the Nyquist mode). The derivative filter alone leaves the modes it removes in the state,
// seen by no derivative and so damped by nothing: filtered() is the state filter that removes them
// (docs/theory/dbm.md, "The undamped band of the filtered derivatives"). Plans are made once per
// grid (FFTW plan creation is not thread-safe); each transform runs single-threaded (callers may
// run several at once), so results do not depend on the OpenMP thread count. Plans assume 16-byte
// aligned arrays (what std::vector's allocator gives; FFTW's SIMD codelets need it): the aligned
// transforms take about half the time of FFTW_UNALIGNED ones (bench/RESULTS.md). SpectralBatch
// transforms several fields of one strided array in one FFTW call (the distributions f_k).
#include <complex>
#include <vector>

namespace shockfield::dbm {

class PeriodicSpectral {
 public:
  using Spectrum = std::vector<std::complex<double>>;

  /// The derivative filter exp(−36(η_x⁸ + η_y⁸)), η = |k|/k_Nyquist per axis.
  static double derivative_filter(double eta_x, double eta_y);
  /// The state filter exp(−36(η_x¹⁶ + η_y¹⁶)): 1 − 3e-4 at η = 0.6, 0.36 at 0.8, 2e-16 at 1.
  static double state_filter(double eta_x, double eta_y);

  /// nx × ny cells of size dx × dy; fields are stored x fastest (i + nx·j).
  PeriodicSpectral(int nx, int ny, double dx, double dy);
  ~PeriodicSpectral();
  PeriodicSpectral(const PeriodicSpectral&) = delete;
  PeriodicSpectral& operator=(const PeriodicSpectral&) = delete;

  std::size_t size() const { return static_cast<std::size_t>(nx_) * ny_; }
  std::size_t spectrum_size() const { return static_cast<std::size_t>(hx_) * ny_; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  Spectrum forward(const std::vector<double>& field) const;
  /// ∂x^ax ∂y^ay of the field whose spectrum is s (ax, ay ≤ 2).
  std::vector<double> derivative(const Spectrum& s, int ax, int ay) const;
  /// ∂x of sx plus ∂y of sy (a divergence), one inverse transform.
  std::vector<double> divergence(const Spectrum& sx, const Spectrum& sy) const;
  /// ∇² of the field whose spectrum is s.
  std::vector<double> laplacian(const Spectrum& s) const;
  /// The same four into caller-owned arrays (resized), `work` a spectrum of scratch: kept between
  /// calls they cost no fresh pages (allocated per call, their page faults took ~12% of a GLS step).
  void forward(const std::vector<double>& field, Spectrum& out) const;
  void derivative(const Spectrum& s, int ax, int ay, Spectrum& work, std::vector<double>& out) const;
  void divergence(const Spectrum& sx, const Spectrum& sy, Spectrum& work, std::vector<double>& out) const;
  void laplacian(const Spectrum& s, Spectrum& work, std::vector<double>& out) const;
  /// s ← (v_x ∂x + v_y ∂y) of the field whose spectrum is s (filtered like derivative()).
  void convect(std::complex<double>* s, double vx, double vy) const;
  /// s ← s times the state filter (the mean, k = 0, kept exactly).
  void apply_state_filter(std::complex<double>* s) const;

 private:
  std::complex<double> factor(int ix, int iy, int ax, int ay) const;
  /// The normalised field of s into out (s is overwritten).
  void backward(Spectrum& s, std::vector<double>& out) const;

  int nx_, ny_, hx_;
  std::vector<double> kx_, ky_, filter_, state_filter_;
  void* forward_plan_;   // fftw_plan, kept opaque so this header does not need fftw3.h
  void* backward_plan_;
};

/// FFTW's advanced interface for `count` fields of one real array at once: field m's cell (i, j) at
/// m·field_stride + i + row_stride·j (interior cells of a ghosted lattice: row_stride = nx + 4), its
/// spectrum at m·spectrum_size() of a contiguous array. The first field must be 16-byte aligned,
/// and row_stride and field_stride even, so that every field is. Single-threaded, like PeriodicSpectral.
class SpectralBatch {
 public:
  SpectralBatch(const PeriodicSpectral& grid, int count, int row_stride, std::size_t field_stride);
  ~SpectralBatch();
  SpectralBatch(const SpectralBatch&) = delete;
  SpectralBatch& operator=(const SpectralBatch&) = delete;

  int count() const { return count_; }
  void forward(const double* fields, std::complex<double>* spectra) const;
  /// The fields of the spectra (overwritten), normalised: backward(forward(f)) = f.
  void backward(std::complex<double>* spectra, double* fields) const;

 private:
  int nx_, ny_, count_, row_stride_;
  std::size_t field_stride_;
  void* forward_plan_;  // fftw_plan
  void* backward_plan_;
};

}  // namespace shockfield::dbm
