#include "shockfield/phasefield/solver.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace shockfield::phasefield {

Scheme scheme_from_name(const std::string& name) {
  if (name == "explicit") return Scheme::explicit_euler;
  if (name == "spectral") return Scheme::spectral;
  throw std::invalid_argument(fmt::format("unknown scheme '{}' (explicit or spectral)", name));
}

std::string scheme_name(Scheme scheme) { return scheme == Scheme::spectral ? "spectral" : "explicit"; }

// FFTW plans for the grid and the implicit factor 1/(1 + dt D |k|²) per complex mode.
struct Solver::Fourier {
  std::vector<std::complex<double>> spectrum;
  std::vector<double> factor;
  fftw_plan forward = nullptr, backward = nullptr;

  Fourier(const Grid& g, double D, double dt, std::vector<double>& real) {
    const int hx = g.n[0] / 2 + 1;
    spectrum.resize(static_cast<std::size_t>(hx) * g.n[1] * g.n[2]);
    factor.resize(spectrum.size());
    const auto wave = [&](int m, int d) {
      const int s = m <= g.n[d] / 2 ? m : m - g.n[d];
      return 2.0 * std::numbers::pi * s / g.length(d);
    };
    for (int k = 0; k < g.n[2]; ++k)
      for (int j = 0; j < g.n[1]; ++j)
        for (int i = 0; i < hx; ++i) {
          const double kx = 2.0 * std::numbers::pi * i / g.length(0), ky = wave(j, 1), kz = wave(k, 2);
          factor[i + static_cast<std::size_t>(hx) * (j + static_cast<std::size_t>(g.n[1]) * k)] =
              1.0 / (1.0 + dt * D * (kx * kx + ky * ky + kz * kz)) / static_cast<double>(g.size());
        }
    // FFTW's row-major dimension list: slowest first. FFTW_UNALIGNED: executed on other arrays.
    int dims[3];
    for (int d = 0; d < g.dim; ++d) dims[d] = g.n[g.dim - 1 - d];
    auto* c = reinterpret_cast<fftw_complex*>(spectrum.data());
    forward = fftw_plan_dft_r2c(g.dim, dims, real.data(), c, FFTW_ESTIMATE | FFTW_UNALIGNED);
    backward = fftw_plan_dft_c2r(g.dim, dims, c, real.data(), FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_DESTROY_INPUT);
  }
  ~Fourier() {
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
  }
};

Solver::Solver(const Grid& grid, const Model& model, Scheme scheme, double dt, bool allocate_now)
    : grid_(grid), model_(model), scheme_(scheme), dt_(dt) {
  if (!(model.D > 0.0)) throw std::invalid_argument(fmt::format("D = {} must be positive", model.D));
  if (!(dt > 0.0)) throw std::invalid_argument(fmt::format("dt = {} must be positive", dt));
  if (scheme == Scheme::explicit_euler && dt > grid.explicit_limit(model.D))
    throw std::invalid_argument(fmt::format("dt = {} exceeds the explicit stability limit dx^2/(2 dim D) = {}", dt,
                                            grid.explicit_limit(model.D)));
  // The explicit Laplacian needs 3 nodes per used dimension.
  for (int d = 0; d < grid.dim; ++d)
    if (grid.n[d] < 3) throw std::invalid_argument("every used dimension needs at least 3 nodes");
  if (allocate_now) allocate();
}

void Solver::allocate() {
  if (xi_.size() == grid_.size()) return;
  xi_.assign(grid_.size(), 0.0);
  work_.assign(grid_.size(), 0.0);
  if (scheme_ == Scheme::spectral) fourier_ = std::make_unique<Fourier>(grid_, model_.D, dt_, work_);
}

double Solver::bytes(const Grid& grid, Scheme scheme) {
  // ξ and its work array; spectral: the half spectrum (complex) and its factor per mode.
  const double n = static_cast<double>(grid.size());
  return 16.0 * n + (scheme == Scheme::spectral ? 24.0 * (n / grid.n[0]) * (grid.n[0] / 2 + 1) : 0.0);
}

Solver::~Solver() = default;

void Solver::step() {
  if (scheme_ == Scheme::spectral)
    step_spectral();
  else
    step_explicit();
  ++steps_;
  time_ = static_cast<double>(steps_) * dt_;
}

void Solver::step_explicit() {
  const auto [nx, ny, nz] = grid_.n;
  const int dim = grid_.dim;
  const double r = model_.D / (grid_.dx * grid_.dx), dt = dt_;
  const double* x = xi_.data();
  double* out = work_.data();
  const std::size_t sy = nx, sz = static_cast<std::size_t>(nx) * ny;
#pragma omp parallel for collapse(2) schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      const int jm = j == 0 ? ny - 1 : j - 1, jp = j == ny - 1 ? 0 : j + 1;
      const int km = k == 0 ? nz - 1 : k - 1, kp = k == nz - 1 ? 0 : k + 1;
      const std::size_t row = sy * j + sz * k;
      for (int i = 0; i < nx; ++i) {
        const int im = i == 0 ? nx - 1 : i - 1, ip = i == nx - 1 ? 0 : i + 1;
        const double c = x[row + i];
        double lap = x[row + im] + x[row + ip] - 2.0 * c;
        if (dim > 1) lap += x[sy * jm + sz * k + i] + x[sy * jp + sz * k + i] - 2.0 * c;
        if (dim > 2) lap += x[sy * j + sz * km + i] + x[sy * j + sz * kp + i] - 2.0 * c;
        out[row + i] = c + dt * (r * lap - model_.df(c));
      }
    }
  xi_.swap(work_);
}

void Solver::step_spectral() {
  Fourier& F = *fourier_;
  const std::size_t n = xi_.size();
  const double dt = dt_;
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < n; ++p) work_[p] = xi_[p] - dt * model_.df(xi_[p]);
  fftw_execute_dft_r2c(F.forward, work_.data(), reinterpret_cast<fftw_complex*>(F.spectrum.data()));
  const std::size_t m = F.spectrum.size();
#pragma omp parallel for schedule(static)
  for (std::size_t c = 0; c < m; ++c) F.spectrum[c] *= F.factor[c];
  fftw_execute_dft_c2r(F.backward, reinterpret_cast<fftw_complex*>(F.spectrum.data()), xi_.data());
}

FieldMeasures Solver::measures() const {
  const auto [nx, ny, nz] = grid_.n;
  const int dim = grid_.dim;
  const double inv_dx2 = 1.0 / (grid_.dx * grid_.dx);
  const std::size_t rows = static_cast<std::size_t>(ny) * nz;
  std::vector<double> energy(rows), integral(rows), above(rows);
#pragma omp parallel for schedule(static)
  for (std::size_t row = 0; row < rows; ++row) {
    const int j = static_cast<int>(row % ny), k = static_cast<int>(row / ny);
    const int jp = j == ny - 1 ? 0 : j + 1, kp = k == nz - 1 ? 0 : k + 1;
    double e = 0.0, s = 0.0, h = 0.0;
    for (int i = 0; i < nx; ++i) {
      const int ip = i == nx - 1 ? 0 : i + 1;
      const double c = xi_[grid_.index(i, j, k)];
      double g2 = std::pow(xi_[grid_.index(ip, j, k)] - c, 2);
      if (dim > 1) g2 += std::pow(xi_[grid_.index(i, jp, k)] - c, 2);
      if (dim > 2) g2 += std::pow(xi_[grid_.index(i, j, kp)] - c, 2);
      e += model_.f(c) + 0.5 * model_.D * g2 * inv_dx2;
      s += c;
      h += c > 0.5 ? 1.0 : 0.0;
    }
    energy[row] = e;
    integral[row] = s;
    above[row] = h;
  }
  FieldMeasures m;
  for (std::size_t row = 0; row < rows; ++row) {
    m.free_energy += energy[row];
    m.integral += integral[row];
    m.fraction_above_half += above[row];
  }
  m.free_energy *= grid_.cell_volume();
  m.integral *= grid_.cell_volume();
  m.fraction_above_half /= static_cast<double>(grid_.size());
  return m;
}

}  // namespace shockfield::phasefield
