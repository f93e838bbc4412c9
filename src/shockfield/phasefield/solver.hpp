#pragma once
// Time stepping of ∂ₜξ = −f′(ξ) + D∇²ξ (model.hpp) on a periodic grid (grid.hpp):
// - explicit: forward Euler with the (2·dim + 1)-point Laplacian, stable for dt ≤ dx²/(2 dim D)
//   (the constructor refuses a larger step);
// - spectral: semi-implicit Fourier, ξ̂ⁿ⁺¹ = (ξ̂ⁿ − dt (f′(ξⁿ))^) / (1 + dt D |k|²): the linear
//   D∇² term implicit, the reaction explicit (FFTW r2c/c2r, single-threaded transforms).
// Node loops are OpenMP-parallel; every node is computed on its own and every sum is taken in a
// fixed order, so results do not depend on the thread count.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/phasefield/grid.hpp"
#include "shockfield/phasefield/model.hpp"

namespace shockfield::phasefield {

enum class Scheme { explicit_euler, spectral };
Scheme scheme_from_name(const std::string& name);  ///< "explicit" or "spectral"
std::string scheme_name(Scheme scheme);

/// Sums over the grid (thread-independent).
struct FieldMeasures {
  double free_energy = 0.0;      ///< F = Σ [f(ξ) + D/2 |∇ξ|²] dV, forward differences
  double integral = 0.0;         ///< Σ ξ dV: the hcp volume of a sharp-front domain
  double fraction_above_half = 0.0;  ///< share of nodes with ξ > 1/2
};

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
  std::vector<double>& field() { return xi_; }
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
  void step_spectral();

  Grid grid_;
  Model model_;
  Scheme scheme_;
  double dt_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  std::vector<double> xi_, work_;
  struct Fourier;
  std::unique_ptr<Fourier> fourier_;
};

}  // namespace shockfield::phasefield
