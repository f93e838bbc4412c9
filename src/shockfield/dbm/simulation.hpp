#pragma once
// The compressible BGK discrete Boltzmann model (Xu et al. 2015, §2.3.4):
//   ∂f_k/∂t + v_k·∇f_k = −(f_k − f_k^eq)/τ (+ an optional source, e.g. the GLS force term),
// f^eq = C⁻¹·M^eq (eqs. 20–26), convection by NND (or by FFT on a fully periodic lattice, as the
// FFT-GLS model of seed refs 34–35 does so that the ideal-gas pressure carried by v·∇f and the
// non-ideal force share one derivative operator), time by the third-order TVD Runge–Kutta
// scheme of Shu and Osher. The state is f only; ρ, u, T follow from eqs. 20–22.
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "shockfield/dbm/bgk_row.hpp"
#include "shockfield/dbm/boundary.hpp"
#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/spectral.hpp"
#include "shockfield/dbm/velocity_model.hpp"
#include "shockfield/parallel/halo_exchange.hpp"

namespace shockfield::dbm {

struct BgkSettings {
  double gamma = 1.4;                // specific-heat ratio γ = (b+2)/b
  double tau = 1e-3;                 // relaxation time
  double dt = 1e-4;                  // time step
  bool spectral_convection = false;  // v·∇f by FFT (needs periodic boundaries on all sides)
  /// The state filter (PeriodicSpectral::filtered) on f after every step; spectral convection only.
  bool filter_state = false;
  /// Largest accepted Courant number max|v|·Δt/Δx of the NND + RK3 scheme.
  static constexpr double max_courant = 1.0;
  /// Largest accepted Δt/τ: RK3 is stable on the negative real axis up to about 2.51.
  static constexpr double max_dt_over_tau = 2.5;
};

class Simulation {
 public:
  /// Adds to rhs (Q arrays of lattice.cells(), interior cells) the source term of a model
  /// beyond BGK, given f with its ghosts filled.
  using Source = std::function<void(const std::vector<double>& f, std::vector<double>& rhs)>;

  /// Validates the settings (InputError naming the value and its limit). The distributions are
  /// allocated now, or (`allocate` false) by allocate(): the run's plug-in defers them to the start
  /// of the run, so that `shockfield run --check` never allocates the lattice
  /// (docs/robustness.md).
  Simulation(VelocityModel model, const Lattice& lattice, const Boundaries& boundaries,
             const BgkSettings& settings, bool allocate = true);
  /// Sizes the distributions (and the spectral convection's arrays) to the lattice, unless they are.
  void allocate();
  /// The bytes allocate() takes (an estimate within the FFT library's own work arrays).
  static double bytes(const Lattice& lattice, const VelocityModel& model, bool spectral_convection);
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// f = f^eq of state(x, y) on every interior cell.
  void initialize(const std::function<Macro(double x, double y)>& state);
  /// One RK3 step of Δt.
  void step();
  /// RunError with the cell and values when ρ ≤ 0, T ≤ 0 or a value is not finite.
  void check_state() const;

  void set_source(Source source) { source_ = std::move(source); }
  /// A block of a decomposed lattice (dbm/decomposition.hpp): the ghosts on the sides `halo` has
  /// a neighbour on come from the neighbouring ranks, the others from the boundaries as before.
  void set_halo(const parallel::HaloExchange* halo) { halo_ = halo; }
  /// Sets the clock of a state restored from a checkpoint (f() restored by the caller).
  void restore_clock(double time, long long steps) { time_ = time, steps_ = steps; }
  double b() const { return b_; }
  double time() const { return time_; }
  long long steps() const { return steps_; }
  const VelocityModel& model() const { return model_; }
  const MomentInversion& inversion() const { return inversion_; }
  const Lattice& lattice() const { return lattice_; }
  const BgkSettings& settings() const { return settings_; }
  const std::vector<double>& f() const { return f_; }
  std::vector<double>& f() { return f_; }
  /// From now on step() copies the new f into f()'s storage instead of swapping buffers, so a
  /// view of f() (Method::state_arrays) keeps showing it.
  void keep_f_in_place() { f_in_place_ = true; }
  Macro macro(int i, int j) const;
  /// Total mass, x and y momentum and energy of the interior (eqs. 20–22), summed in a
  /// thread-count independent order.
  std::array<double, 4> totals() const;

 private:
  /// The ghosts of f: per axis, the halo's sides, then the boundaries' (the serial order).
  void fill_ghosts(std::vector<double>& f) const;
  /// Fills the ghosts of f and writes L(f) of the BGK model (without the source) to output.
  void stage(std::vector<double>& f, const RowOutput& output);
  /// v_k·∇f_k of every velocity by FFT into convection_ (interior cells, i + nx·j per k).
  void spectral_convection(const std::vector<double>& f);
  /// The state filter of PeriodicSpectral applied to every f_k (interior cells).
  void apply_state_filter();

  /// The velocities are transformed kVelocityBatch at a time (one FFTW call per batch, batches spread
  /// over the threads, so the numbers do not depend on the thread count).
  static constexpr int kVelocityBatch = 4;
  /// The plans of one batch: f_k's interior cells in the ghosted layout, and convection_'s layout.
  struct VelocityPlans {
    SpectralBatch ghosted, compact;
  };
  int velocity_batches() const { return (model_.size() + kVelocityBatch - 1) / kVelocityBatch; }
  /// Batch b's plans (the last batch may hold fewer velocities).
  const VelocityPlans& plans(int b) const;

  VelocityModel model_;
  MomentInversion inversion_;
  Lattice lattice_;
  BgkSettings settings_;
  double b_;
  GhostFiller ghosts_;
  const parallel::HaloExchange* halo_ = nullptr;
  Source source_;
  std::unique_ptr<PeriodicSpectral> spectral_;
  std::unique_ptr<VelocityPlans> full_batch_, last_batch_;  // last_batch_ only when Q % kVelocityBatch != 0
  std::vector<double> convection_;
  std::vector<double> f_, f1_, work_;  // work_: the second stage, or L(f) with a source
  bool f_in_place_ = false;
  double time_ = 0.0;
  long long steps_ = 0;
};

}  // namespace shockfield::dbm
