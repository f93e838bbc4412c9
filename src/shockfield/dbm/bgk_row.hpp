#pragma once
// The BGK right-hand side L(f) = −v_k·∇f_k − (f_k − f_k^eq)/τ of one lattice row, organised so
// that every inner loop runs along x over contiguous cells with the discrete velocity fixed (and
// so vectorises), in chunks of cells small enough for the workspace to stay in the L1 cache: the
// macroscopic state of the chunk (eqs. 20–22), f^eq = C⁻¹·M^eq (eqs. 20–26), then per velocity
// the NND convection (or a precomputed spectral derivative) and the collision. The result either
// is stored or directly completes a Runge–Kutta stage, which saves a pass over memory. One thread
// owns one BgkRow workspace.
#include <cstddef>
#include <vector>

#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

/// Where the L(f) of a row goes: out = L(f) when base is null, else the Runge–Kutta stage
/// out = a·base + (1 − a)·(f + Δt·L(f)). Arrays are Q × lattice.cells().
struct RowOutput {
  double* out = nullptr;
  const double* base = nullptr;
  double a = 0.0, dt = 0.0;
};

/// One value of a third-order TVD Runge–Kutta stage: a·base + (1 − a)·(f + Δt·L).
inline double runge_kutta_stage(double a, double base, double f, double dt, double L) {
  return a * base + (1.0 - a) * (f + dt * L);
}

class BgkRow {
 public:
  BgkRow(const VelocityModel& model, const MomentInversion& inversion, const Lattice& lattice,
         double b, double tau);

  static constexpr int chunk = 64;
  /// Number of chunks of a row: rows × chunks is the parallel work (so 1D runs use all threads).
  static int chunks(int nx) { return (nx + chunk - 1) / chunk; }

  /// L(f) on chunk chunk_index of interior row j (f with ghosts filled). With `convection` (Q arrays of
  /// nx·ny, index i + nx·j) v_k·∇f_k is taken from it instead of NND.
  void rhs(const double* f, int j, int chunk_index, const double* convection,
           const RowOutput& output);

 private:
  /// ρ, u, T and f^eq of the n cells of the chunk starting at storage index c0.
  void equilibrium_chunk(const double* f, std::size_t c0, int n);

  const VelocityModel& model_;
  const MomentInversion& inversion_;
  Lattice lattice_;
  double b_, inv_tau_;
  // Chunk workspace: ρ, u_x, u_y, T; moments and modes of C⁻¹ = R·S; the Q equilibria; L(f);
  // the limited x slopes of one velocity.
  std::vector<double> rho_, ux_, uy_, T_, work_, eq_, rhs_, slope_x_;
};

}  // namespace shockfield::dbm
