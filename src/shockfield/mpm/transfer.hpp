#pragma once
// Particle ↔ grid transfers of the material point method (seed 000, §2.2.2):
//   m_i = Σ_p m_p N_i(x_p),   m_i v_i = Σ_p m_p v_p N_i(x_p),
//   f_i^int = −Σ_p V_p σ_p·∇N_i(x_p)   (V_p = m_p/ρ_p)                       (eq. 12)
// The particle-to-grid sums are gathers: each node visits the particles binned by the first node
// of their stencil, bins in a fixed order and particles in index order, so every nodal sum is
// formed in the same order whatever the number of OpenMP threads (no atomics, no colouring).
#include <array>
#include <cstddef>
#include <vector>

#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/particles.hpp"
#include "shockfield/mpm/shape_functions.hpp"

namespace shockfield::mpm {

enum class ShapeKind { Linear, Gimp };

class Transfer {
 public:
  /// Evaluate every particle's stencil for the current positions and bin the particles.
  /// RunError when a particle has left the grid.
  void build(const Grid& grid, const Particles& p, ShapeKind shape);
  /// Nodal mass, momentum and (with `with_force`) internal force from the particles.
  void to_grid(Grid& grid, const Particles& p, bool with_force);

  /// Call f(node, N_i(x_p), ∇N_i(x_p)) for each node of particle p's stencil.
  template <class F>
  void visit(const Grid& grid, std::size_t p, F&& f) const {
    const auto& s = stencils_[p];
    for (int c = 0; c < s[2].count; ++c) {
      const int k = grid.wrap(2, s[2].base + c);
      for (int b = 0; b < s[1].count; ++b) {
        const int j = grid.wrap(1, s[1].base + b);
        for (int a = 0; a < s[0].count; ++a) {
          const int i = grid.wrap(0, s[0].base + a);
          const auto [w, grad] = weight(s, a, b, c);
          f(grid.flat(i, j, k), w, grad);
        }
      }
    }
  }

 private:
  using Stencil = std::array<Weights1D, 3>;
  struct Weight {
    double w;
    Vec3 grad;
  };
  static Weight weight(const Stencil& s, int a, int b, int c) {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b), uc = static_cast<std::size_t>(c);
    const double wx = s[0].w[ua], wy = s[1].w[ub], wz = s[2].w[uc];
    return {wx * wy * wz, Vec3(s[0].dw[ua] * wy * wz, wx * s[1].dw[ub] * wz, wx * wy * s[2].dw[uc])};
  }
  template <ShapeFunction S>
  void evaluate(const Grid& grid, const Particles& p);

  std::vector<Stencil> stencils_;
  std::vector<std::size_t> bin_start_;
  std::vector<std::size_t> binned_;
  std::vector<Vec3> momentum_;   // m_p v_p
  std::vector<Mat3> volume_stress_;  // V_p σ_p
};

}  // namespace shockfield::mpm
