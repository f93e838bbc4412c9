#include "shockfield/phasefield/solver.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace shockfield::phasefield {

double explicit_step_limit(const Grid& grid, const Model& model) {
  double sum = 0.0;
  for (int d = 0; d < grid.dim; ++d) sum += model.D_along(d);
  return grid.dx * grid.dx / (2.0 * sum);
}

Scheme scheme_from_name(const std::string& name) {
  if (name == "explicit") return Scheme::explicit_euler;
  if (name == "spectral") return Scheme::spectral;
  throw std::invalid_argument(fmt::format("unknown scheme '{}' (explicit or spectral)", name));
}

std::string scheme_name(Scheme scheme) { return scheme == Scheme::spectral ? "spectral" : "explicit"; }

// FFTW plans for the grid and the implicit factor 1/(1 + dt Σ_d D_d k_d²) per complex mode.
struct Solver::Fourier {
  std::vector<std::complex<double>> spectrum;
  std::vector<double> factor;
  fftw_plan forward = nullptr, backward = nullptr;

  Fourier(const Grid& g, const Model& model, double dt, std::vector<double>& real) {
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
              1.0 / (1.0 + dt * (model.D_along(0) * kx * kx + model.D_along(1) * ky * ky + model.D_along(2) * kz * kz)) /
              static_cast<double>(g.size());
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
  for (int d = 0; d < 3; ++d)
    if (!(model.anisotropy[d] > 0.0))
      throw std::invalid_argument(fmt::format("anisotropy {} = {} must be positive", d, model.anisotropy[d]));
  if (!(dt > 0.0)) throw std::invalid_argument(fmt::format("dt = {} must be positive", dt));
  if (scheme == Scheme::spectral && !grid.all_periodic())
    throw std::invalid_argument("the spectral scheme needs periodic boundaries on every axis; use the explicit scheme "
                                "with walls");
  if (scheme == Scheme::explicit_euler && dt > explicit_step_limit(grid, model))
    throw std::invalid_argument(fmt::format("dt = {} exceeds the explicit stability limit dx^2/(2 sum D_d) = {}", dt,
                                            explicit_step_limit(grid, model)));
  // The explicit Laplacian needs 3 nodes per used dimension.
  for (int d = 0; d < grid.dim; ++d)
    if (grid.n[d] < 3) throw std::invalid_argument("every used dimension needs at least 3 nodes");
  if (allocate_now) allocate();
}

void Solver::allocate() {
  if (xi_.size() == grid_.size()) return;
  xi_.assign(grid_.size(), 0.0);
  work_.assign(grid_.size(), 0.0);
  if (scheme_ == Scheme::spectral) fourier_ = std::make_unique<Fourier>(grid_, model_, dt_, work_);
}

double Solver::bytes(const Grid& grid, Scheme scheme) {
  // ξ and its work array; spectral: the half spectrum (complex) and its factor per mode.
  const double n = static_cast<double>(grid.size());
  return 16.0 * n + (scheme == Scheme::spectral ? 24.0 * (n / grid.n[0]) * (grid.n[0] / 2 + 1) : 0.0);
}

Solver::~Solver() = default;

void Solver::step() {
  hold_walls();
  if (scheme_ == Scheme::spectral)
    step_spectral();
  else
    step_explicit();
  hold_walls();
  ++steps_;
  time_ = static_cast<double>(steps_) * dt_;
}

void Solver::hold_walls() {
  for (int d = 0; d < grid_.dim; ++d) {
    if (grid_.boundary[d] != Boundary::dirichlet) continue;
    for (int side = 0; side < 2; ++side) {
      const int wall = side == 0 ? 0 : grid_.n[d] - 1;
      std::array<int, 3> lo{0, 0, 0}, hi = grid_.n;
      lo[d] = wall, hi[d] = wall + 1;
      for (int k = lo[2]; k < hi[2]; ++k)
        for (int j = lo[1]; j < hi[1]; ++j)
          for (int i = lo[0]; i < hi[0]; ++i) xi_[grid_.index(i, j, k)] = grid_.fixed[d][side];
    }
  }
}

void Solver::set_diffusivity_scale(std::vector<double> scale) {
  if (scheme_ != Scheme::explicit_euler)
    throw std::invalid_argument("a gradient coefficient varying in space needs the explicit scheme");
  if (scale.size() != grid_.size())
    throw std::invalid_argument(fmt::format("{} scale values for {} nodes", scale.size(), grid_.size()));
  double largest = 0.0;
  for (std::size_t p = 0; p < scale.size(); ++p) {
    if (!(scale[p] > 0.0 && std::isfinite(scale[p])))
      throw std::invalid_argument(fmt::format("the gradient coefficient's scale is {} at node {} (x fastest); it must "
                                              "be positive", scale[p], p));
    largest = std::max(largest, scale[p]);
  }
  const double limit = explicit_step_limit(grid_, model_) / largest;
  if (dt_ > limit)
    throw std::invalid_argument(fmt::format("dt = {} exceeds the explicit stability limit dx^2/(2 sum D_d max s) = {} "
                                            "(largest scale {})", dt_, limit, largest));
  scale_ = std::move(scale);
}

void Solver::add_source() {
  if (!source_) return;
  const auto [nx, ny, nz] = grid_.n;
  const double dx = grid_.dx, t = time_, dt = dt_;
#pragma omp parallel for collapse(2) schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) work_[grid_.index(i, j, k)] += dt * source_({i * dx, j * dx, k * dx}, t);
}

void Solver::step_explicit() {
  if (scale_.empty())
    explicit_update<false>();
  else
    explicit_update<true>();
  add_source();
  if (field_in_place_)
    std::copy(work_.begin(), work_.end(), xi_.begin());
  else
    xi_.swap(work_);
}

template <bool kVaryingD>
void Solver::explicit_update() {
  const auto [nx, ny, nz] = grid_.n;
  const int dim = grid_.dim;
  const double inv_dx2 = 1.0 / (grid_.dx * grid_.dx), dt = dt_;
  const double rx = model_.D_along(0) * inv_dx2, ry = model_.D_along(1) * inv_dx2, rz = model_.D_along(2) * inv_dx2;
  const double* x = xi_.data();
  const double* s = scale_.data();
  double* out = work_.data();
  const std::size_t sy = nx, sz = static_cast<std::size_t>(nx) * ny;
  const Grid& g = grid_;
  // The flux through the face between nodes p and q: (ξ_q − ξ_p) times D on the face, the mean of
  // the two nodes' scales when D varies in space.
  const auto flux = [x, s](std::size_t p, std::size_t q) {
    const double difference = x[q] - x[p];
    if constexpr (kVaryingD) return 0.5 * (s[p] + s[q]) * difference;
    return difference;
  };
#pragma omp parallel for collapse(2) schedule(static)
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      const int jm = g.neighbour(1, j, -1), jp = g.neighbour(1, j, 1);
      const int km = g.neighbour(2, k, -1), kp = g.neighbour(2, k, 1);
      const std::size_t row = sy * j + sz * k;
      for (int i = 0; i < nx; ++i) {
        const int im = g.neighbour(0, i, -1), ip = g.neighbour(0, i, 1);
        const std::size_t p = row + i;
        const double c = x[p];
        double div = rx * (flux(p, row + im) + flux(p, row + ip));  // ∇·(D∇ξ), D_d per axis
        if (dim > 1) div += ry * (flux(p, sy * jm + sz * k + i) + flux(p, sy * jp + sz * k + i));
        if (dim > 2) div += rz * (flux(p, sy * j + sz * km + i) + flux(p, sy * j + sz * kp + i));
        out[p] = c + dt * (div - model_.df(c));
      }
    }
}

void Solver::step_spectral() {
  Fourier& F = *fourier_;
  const std::size_t n = xi_.size();
  const double dt = dt_;
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < n; ++p) work_[p] = xi_[p] - dt * model_.df(xi_[p]);
  add_source();
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
  const Grid& g = grid_;
  // Trapezoidal weight of node i along axis d: 1/2 on a wall; the forward difference from node i
  // along d: none from the last node before a wall.
  const auto weight = [&](int d, int i) { return g.periodic(d) || (i > 0 && i < g.n[d] - 1) ? 1.0 : 0.5; };
  const auto forward = [&](int d, int i) { return g.periodic(d) || i + 1 < g.n[d]; };
  std::vector<double> energy(rows), integral(rows), above(rows);
#pragma omp parallel for schedule(static)
  for (std::size_t row = 0; row < rows; ++row) {
    const int j = static_cast<int>(row % ny), k = static_cast<int>(row / ny);
    const int jp = g.neighbour(1, j, 1), kp = g.neighbour(2, k, 1);
    const double row_weight = (dim > 1 ? weight(1, j) : 1.0) * (dim > 2 ? weight(2, k) : 1.0);
    double e = 0.0, s = 0.0, h = 0.0;
    for (int i = 0; i < nx; ++i) {
      const std::size_t p = grid_.index(i, j, k);
      const double c = xi_[p], w = row_weight * weight(0, i);
      // D_d |∂_d ξ|² on the forward face (D averaged over its two nodes when it varies).
      const auto face = [&](int d, std::size_t q) {
        return model_.D_along(d) * (scale_.empty() ? 1.0 : 0.5 * (scale_[p] + scale_[q])) * std::pow(xi_[q] - c, 2);
      };
      double g2 = forward(0, i) ? face(0, grid_.index(g.neighbour(0, i, 1), j, k)) : 0.0;
      if (dim > 1 && forward(1, j)) g2 += face(1, grid_.index(i, jp, k));
      if (dim > 2 && forward(2, k)) g2 += face(2, grid_.index(i, j, kp));
      e += w * (model_.f(c) + 0.5 * g2 * inv_dx2);
      s += w * c;
      h += c > 0.5 ? w : 0.0;
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
  double volume = 1.0;  // in cells: n per periodic axis, n − 1 between walls
  for (int d = 0; d < dim; ++d) volume *= g.periodic(d) ? g.n[d] : g.n[d] - 1;
  m.fraction_above_half /= volume;
  return m;
}

}  // namespace shockfield::phasefield
