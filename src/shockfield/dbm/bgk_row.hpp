#pragma once
// The BGK right-hand side L(f) = −v_k·∇f_k − (f_k − f_k^eq)/τ of a block of lattice rows,
// organised so that every inner loop runs along x over contiguous cells with the discrete
// velocity fixed (and so vectorises), in chunks of cells small enough for the workspace to stay
// in the L1 cache: per row, the macroscopic state of the chunk (eqs. 20–22) and f^eq = C⁻¹·M^eq
// (eqs. 20–26), then per velocity the NND convection (or a precomputed spectral derivative) and
// the collision. A block walks down its rows so that the NND face values in y of one row are
// reused by the next (each face serves two cells). The result either is stored or directly
// completes a Runge–Kutta stage, which saves a pass over memory. One thread owns one BgkRow
// workspace.
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

/// out[i] = runge_kutta_stage(a, base[i], f[i], dt, L[i]) for i < n (out may be f), compiled
/// like the fused stages of BgkRow (same SIMD clone), so the stored-L path gives the same bits.
void runge_kutta_row(double a, const double* base, const double* f, double dt, const double* L,
                     int n, double* out);

class BgkRow {
 public:
  BgkRow(const VelocityModel& model, const MomentInversion& inversion, const Lattice& lattice,
         double b, double tau);

  static constexpr int chunk = 64, block_rows = 16;
  /// Number of chunks of a row and of blocks of rows: blocks × chunks is the parallel work (so
  /// 1D runs use all threads).
  static int chunks(int nx) { return (nx + chunk - 1) / chunk; }
  static int blocks(int ny) { return (ny + block_rows - 1) / block_rows; }

  /// L(f) on chunk chunk_index of the interior rows of block block_index (f with ghosts
  /// filled). With `convection` (Q arrays of nx·ny, index i + nx·j) v_k·∇f_k is taken from it
  /// instead of NND.
  void rhs(const double* f, int block_index, int chunk_index, const double* convection,
           const RowOutput& output);

 private:
  /// Prefetches into the cache what velocity k of row j will read first.
  void prefetch_next_row(const double* f, int k, int j, int i0, int n,
                         const RowOutput& output) const;
  /// ρ, u, T and f^eq of the n cells of the chunk starting at storage index c0.
  void equilibrium_chunk(const double* f, std::size_t c0, int n);
  /// L(f) of the n cells of row j from i0 on; face_y_ holds the y face values of row j − 1 (see
  /// downwind_face) on entry and those of row j on return.
  void rhs_row(const double* f, int j, int i0, int n, const double* convection,
               const RowOutput& output);

  const VelocityModel& model_;
  const MomentInversion& inversion_;
  Lattice lattice_;
  double b_, inv_tau_;
  // Chunk workspace: ρ, u_x, u_y, T; moments and modes of C⁻¹ = R·S (generic models); the Q
  // equilibria; the x face values of one velocity; the y face values of every velocity.
  std::vector<double> rho_, ux_, uy_, T_, work_, eq_, face_x_, face_y_;
};

}  // namespace shockfield::dbm
