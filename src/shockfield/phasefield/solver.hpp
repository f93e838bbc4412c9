#pragma once
// Time stepping of ∂ₜξ = −f′(ξ) + D∇²ξ + S(x, t) (model.hpp) on a grid (grid.hpp):
// - explicit: forward Euler with the (2·dim + 1)-point Laplacian, stable for dt ≤ dx²/(2 dim D)
//   (the constructor refuses a larger step); periodic axes or walls (neumann, dirichlet);
// - spectral: semi-implicit Fourier, ξ̂ⁿ⁺¹ = (ξ̂ⁿ − dt (f′(ξⁿ) − Sⁿ)^) / (1 + dt D |k|²): the
//   linear D∇² term implicit, the reaction explicit (FFTW r2c/c2r, single-threaded transforms);
//   periodic axes only (the constructor refuses walls).
// S is an optional source (none by default), evaluated at tⁿ: the manufactured-solution term of
// PFHub benchmark 7 (docs/phasefield.md) is one.
// Node loops are OpenMP-parallel; every node is computed on its own and every sum is taken in a
// fixed order, so results do not depend on the thread count.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/phasefield/grid.hpp"
#include "shockfield/phasefield/model.hpp"

namespace shockfield::phasefield {

enum class Scheme { explicit_euler, spectral };

/// Largest stable explicit step of the diffusion part, dx²/(2 Σ_d D_d) (dx²/(2 dim D) isotropic).
double explicit_step_limit(const Grid& grid, const Model& model);
Scheme scheme_from_name(const std::string& name);  ///< "explicit" or "spectral"
std::string scheme_name(Scheme scheme);

/// Sums over the grid (thread-independent).
/// Nodes on a wall count half a cell (a corner a quarter...): the trapezoidal rule.
struct FieldMeasures {
  double free_energy = 0.0;      ///< F = Σ [f(ξ) + D/2 |∇ξ|²] dV, forward differences (none out of a wall)
  double integral = 0.0;         ///< Σ ξ dV: the hcp volume of a sharp-front domain
  double fraction_above_half = 0.0;  ///< share of the volume with ξ > 1/2
};

/// A source term S(x, t) of the equation, x the node's position.
using Source = std::function<double(const std::array<double, 3>& x, double t)>;

class Solver {
 public:
  /// Throws std::invalid_argument when dt exceeds the explicit limit or D, dt are not positive.
  /// The field and work arrays (and the FFT plans) are allocated now, or (`allocate` false) by
  /// allocate(): the run's plug-in defers them to the start of the run, so that
  /// `shockfield run --check` never allocates the grid (docs/robustness.md).
  Solver(const Grid& grid, const Model& model, Scheme scheme, double dt, bool allocate = true);
  /// Sizes the field and work arrays to the grid (zero) and plans the FFTs, unless already done.
  void allocate();
  /// The bytes allocate() takes (without the FFT library's own plans).
  static double bytes(const Grid& grid, Scheme scheme);
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  void step();
  /// Sets the dirichlet wall nodes of the field to their fixed values (step() does it too).
  void hold_walls();
  /// Adds S to the right-hand side from the next step on.
  void set_source(Source source) { source_ = std::move(source); }
  /// A gradient coefficient varying in space, D_d(x) = D w_d s(x) (`scale` per node, all > 0; the
  /// pressure-dependent D of Xu et al. 2015 §4.4.3): ∇·(D∇ξ) with D averaged over the two nodes
  /// of each face (conservative; a zero-flux wall stays a mirror). Explicit scheme only, and the
  /// explicit limit shrinks by max s; std::invalid_argument otherwise, or for a wrong size.
  void set_diffusivity_scale(std::vector<double> scale);
  std::vector<double>& field() { return xi_; }
  /// From now on the explicit step copies its result into the field's storage instead of
  /// swapping buffers, so a view of field() (Method::state_arrays) keeps showing it.
  void keep_field_in_place() { field_in_place_ = true; }
  const std::vector<double>& field() const { return xi_; }
  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  void restore_clock(double time, std::int64_t steps) {
    time_ = time;
    steps_ = steps;
  }
  const Grid& grid() const { return grid_; }
  const Model& model() const { return model_; }
  double dt() const { return dt_; }
  Scheme scheme() const { return scheme_; }
  FieldMeasures measures() const;

 private:
  void step_explicit();
  /// The forward-Euler update, compiled once for a uniform D and once for set_diffusivity_scale's
  /// D(x), so the uniform stencil carries no per-face test.
  template <bool kVaryingD>
  void explicit_update();
  void step_spectral();
  /// work_[p] += dt S(x_p, tⁿ) on every node.
  void add_source();

  Grid grid_;
  Model model_;
  Scheme scheme_;
  double dt_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  std::vector<double> xi_, work_;
  bool field_in_place_ = false;
  std::vector<double> scale_;  ///< s(x) of set_diffusivity_scale; empty: uniform
  Source source_;
  struct Fourier;
  std::unique_ptr<Fourier> fourier_;
};

}  // namespace shockfield::phasefield
