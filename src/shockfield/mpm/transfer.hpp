#pragma once
// Particle ↔ grid transfers of the material point method (Xu et al. 2015, §2.2.2):
//   m_i = Σ_p m_p N_i(x_p),   m_i v_i = Σ_p m_p v_p N_i(x_p),
//   f_i^int = −Σ_p V_p σ_p·∇N_i(x_p)   (V_p = m_p/ρ_p)                       (eq. 12)
//   v̄_p = Σ_i N_i(x_p) v_i,   L_p = Σ_i v_i ⊗ ∇N_i(x_p)                      (grid → particles)
//
// `build` evaluates every particle's stencil (first node and 1D weights per axis) once per step;
// all transfers of the step reuse it. The kernels are compiled per dimension and stencil width
// (2 nodes per axis for the linear hat, 3 for GIMP), so the node loops unroll; in 2D (plane
// strain) only the x and y components are transferred, z components of nodal fields stay zero.
//
// Thread-count independence of the particle-to-grid sums: particles are binned by the first node
// of their stencil and the bins cut into slabs of two node layers along the outermost axis. A
// slab's particles touch at most four consecutive layers, so slabs two apart never share a node:
// all even slabs scatter concurrently, then all odd slabs (slabs whose stencil wraps round a
// periodic outermost axis go last, one at a time). Each nodal sum is therefore formed in one
// fixed order — slab pass, then bin, then particle index — whatever the number of OpenMP threads,
// with no atomics and no per-thread copies of the grid.
#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/particles.hpp"
#include "shockfield/mpm/shape_functions.hpp"

namespace shockfield::mpm {

/// Linear hats (eq. 9); GIMP with particle boxes that follow the deformation (cpGIMP: half-width
/// l_a = l_a0·|F_aa| along each axis, Bardenhagen & Kober 2004, §4.2); uniform GIMP with the boxes of
/// the undeformed lattice (uGIMP, the same paper's eq. 39).
enum class ShapeKind { Linear, Gimp, UniformGimp };

/// The cpGIMP half-width along one axis: the initial half-width l0 stretched by the diagonal
/// coefficient F_aa of the deformation gradient, so that the boxes of a uniformly strained lattice
/// keep tiling the body. Bounded to [l0/10, max(l0, 0.49·h)]: GIMP needs l < h/2 (three nodes per
/// axis), and under large rotations F_aa alone no longer measures the box (docs/theory/mpm.md).
inline double contiguous_half_width(double l0, double f_aa, double h) {
  return std::clamp(l0 * std::abs(f_aa), 0.1 * l0, std::max(l0, 0.49 * h));
}

/// One particle's stencil: first node along each axis (wrapped) and the 1D weights N and dN/dx of
/// the nodes base, base+1, ... (unused trailing entries are zero). With contact (contact.hpp) base[0]
/// also selects the body's layer: it is b·(nodes along x + support) + the node, an index into the
/// layered table of x offsets (so the stencil does not grow by a layer field).
template <int Dim>
struct Stencil {
  std::array<int, Dim> base{};
  std::array<std::array<double, 3>, Dim> w{};
  std::array<std::array<double, 3>, Dim> dw{};
};

class Transfer {
 public:
  /// Evaluate every particle's stencil for the current positions and bin the particles.
  /// RunError when a particle has left the grid.
  void build(const Grid& grid, const Particles& p, ShapeKind shape);
  /// Nodal mass, momentum and internal force from the particles (eq. 12), each point into its
  /// body's layer, and with several layers the mass gradient Σ_p m_p ∇N_ip; overwrites them.
  /// A non-empty `mean_stress_correction` adds c_p·I (in-plane in 2D) to V_p σ_p in the force: the
  /// B-bar force of the smoothed dilatation (simulation.cpp, smoothed_mean_stress_correction).
  void to_grid(Grid& grid, const Particles& p, const std::vector<double>& mean_stress_correction = {}) const;

  /// For each particle p (in parallel): f(p, Σ_i N_i a_i, Σ_i N_i b_i) for nodal vectors a, b.
  template <class F>
  void interpolate(const std::vector<Vec3>& a, const std::vector<Vec3>& b, F&& f) const;
  /// The same, fused with the MUSL remap: right after f has updated particle p's velocity, its
  /// momentum m_p v_p is scattered to the nodal momenta (zeroed first). The nodal mass stays that
  /// of `to_grid`, the stencils being unchanged within a step.
  template <class F>
  void interpolate_and_remap(Grid& grid, const Particles& p, const std::vector<Vec3>& a, const std::vector<Vec3>& b,
                             F&& f) const;
  /// For each particle p (in parallel): out[p] = Σ_i a_i ⊗ ∇N_i(x_p) for a nodal vector field a,
  /// then f(p). The gradients of a block of particles are stored before f runs on them, so f
  /// reads out[p] long after it was written (read back at once, a 3×3 matrix stored element by
  /// element and loaded as 16-byte packets stalls store-to-load forwarding).
  template <class F>
  void gradient(const std::vector<Vec3>& a, std::vector<Mat3>& out, F&& f) const;
  /// out_i = Σ_p m_p N_ip u_p for a value u_p per particle, into each point's body layer (with
  /// `mass` from to_grid, out_i / m_i is the mass-weighted nodal average of u). Zeroes `out` first;
  /// each nodal sum is formed in the slab-pass order, so it does not depend on the thread count.
  void mass_weighted_to_grid(const Particles& p, const std::vector<Vec3>& u, std::vector<Vec3>& out) const;
  /// Generic transfers for other nodal fields (heat conduction): f(q, each) for every particle q,
  /// where each(g) calls g(i, N_i(x_q), ∇N_i(x_q)) for the nodes i of q's stencil (∇N as
  /// std::array<double, 3>, z component 0 in 2D). `scatter_each` visits the particles in the
  /// slab-pass order of the particle-to-grid sums, so f may add to nodal fields and each nodal
  /// sum is formed in one fixed order whatever the thread count; `gather_each` runs in parallel
  /// over the particles and must only read nodal fields. Both visit the grid's nodes, not the
  /// bodies' layers (conduction is across bodies in contact) unless `Layered`.
  template <bool Layered = false, class F>
  void scatter_each(F&& f) const;
  template <class F>
  void gather_each(F&& f) const;

 private:
  template <int D, int S>
  using Kernel = std::pair<std::integral_constant<int, D>, std::integral_constant<int, S>>;
  /// Call k(Kernel<dim, support>{}) for the current dimension and stencil width.
  template <class K>
  void dispatch(K&& k) const;
  /// In parallel over the particles q (static schedule): f(Kernel<dim, support>{}, q, stencil of q).
  template <class F>
  void each_particle(F&& f) const;
  template <int Dim, class Shape, bool Contiguous>
  void evaluate(const Grid& grid, const Particles& p);
  void bin(const Grid& grid);
  /// Particle-to-grid sums, slab pass by slab pass (see the top of this file). Per particle q,
  /// `before(q, stencil, nodes)` runs first; then w m_p v_p (and with Force, w m_p and −V_p σ_p·∇N)
  /// is added to each node of its stencil.
  template <int Dim, int S, bool Force, class Before>
  void scatter(Grid& grid, const Particles& p, Before&& before, const std::vector<double>& correction = {}) const;
  /// The slab passes alone: body(first, last) for each slab, whose particles are
  /// binned_[first..last) in bin order.
  template <class Body>
  void slab_passes(Body&& body) const;
  /// g(i, N_i, ∇N_i) for the nodes i of a stencil (flat indices `node` from nodes()).
  template <int Dim, int S, std::size_t N, class G>
  static void each_node(const Stencil<Dim>& s, const std::array<std::size_t, N>& node, G&& g);
  template <int Dim>
  const std::vector<Stencil<Dim>>& stencils() const {
    if constexpr (Dim == 2) return stencils2_;
    else return stencils3_;
  }
  /// Σ_i N_i a_i and Σ_i N_i b_i over a stencil.
  template <int Dim, int S, std::size_t N>
  static void gather(const Stencil<Dim>& s, const std::array<std::size_t, N>& node, const std::vector<Vec3>& a,
                     const std::vector<Vec3>& b, Vec3& sa, Vec3& sb);
  /// Flat indices of the S^Dim nodes of a stencil, x fastest, in its body's layer (Layered) or in
  /// the first (the grid's nodes themselves).
  template <int Dim, int S, bool Layered = true>
  [[gnu::always_inline]] std::array<std::size_t, S * S * (Dim == 3 ? S : 1)> nodes(const Stencil<Dim>& s) const;

  int dim_ = 2;
  int support_ = 2;
  std::array<int, 3> node_count_{};
  std::array<std::size_t, 3> stride_{};
  std::array<std::vector<std::size_t>, 3> offset_;  // [axis][base + k]: flat offset of node base + k, wrapped
  std::size_t row_ = 0;  // entries of offset_[0] per body layer: nodes along x + support
  std::vector<Stencil<2>> stencils2_;
  std::vector<Stencil<3>> stencils3_;
  std::vector<std::size_t> bin_of_;  // per particle: flat index of its stencil's first node
  std::vector<std::size_t> bin_start_;
  std::vector<std::size_t> binned_;
  std::size_t slab_bins_ = 0;                     // bins per slab (two outermost layers)
  std::vector<std::vector<std::size_t>> passes_;  // slabs scattered concurrently, pass by pass
};

template <class K>
void Transfer::dispatch(K&& k) const {
  if (dim_ == 2) {
    if (support_ == 2) k(Kernel<2, 2>{});
    else k(Kernel<2, 3>{});
  } else {
    if (support_ == 2) k(Kernel<3, 2>{});
    else k(Kernel<3, 3>{});
  }
}

template <int Dim, int S, bool Layered>
inline std::array<std::size_t, S * S * (Dim == 3 ? S : 1)> Transfer::nodes(const Stencil<Dim>& s) const {
  // offset_[0] holds one block of row_ x offsets per body layer (the first block: the grid's nodes).
  const std::size_t* ox = offset_[0].data() + (Layered ? static_cast<std::size_t>(s.base[0])
                                                        : static_cast<std::size_t>(s.base[0]) % row_);
  const std::size_t* oy = offset_[1].data() + s.base[1];
  const std::size_t* oz = Dim == 3 ? offset_[2].data() + s.base[Dim - 1] : nullptr;
  std::array<std::size_t, S * S * (Dim == 3 ? S : 1)> out{};
  std::size_t e = 0;
  for (int c = 0; c < (Dim == 3 ? S : 1); ++c)
    for (int b = 0; b < S; ++b)
      for (int a = 0; a < S; ++a) out[e++] = ox[a] + oy[b] + (Dim == 3 ? oz[c] : 0);
  return out;
}

template <int Dim, int S, std::size_t N>
inline void Transfer::gather(const Stencil<Dim>& s, const std::array<std::size_t, N>& node, const std::vector<Vec3>& va,
                             const std::vector<Vec3>& vb, Vec3& sa, Vec3& sb) {
  sa.setZero();
  sb.setZero();
  std::size_t e = 0;
  for (int c = 0; c < (Dim == 3 ? S : 1); ++c) {
    const double wz = Dim == 3 ? s.w[Dim - 1][static_cast<std::size_t>(c)] : 1.0;
    for (int b = 0; b < S; ++b) {
      const double wy = s.w[1][static_cast<std::size_t>(b)];
      for (int a = 0; a < S; ++a, ++e) {
        const double w = s.w[0][static_cast<std::size_t>(a)] * wy * wz;
        const Vec3& na = va[node[e]];
        const Vec3& nb = vb[node[e]];
        for (int r = 0; r < Dim; ++r) {
          sa[r] += w * na[r];
          sb[r] += w * nb[r];
        }
      }
    }
  }
}

template <class F>
void Transfer::each_particle(F&& f) const {
  dispatch([&](auto kernel) {
    constexpr int D = decltype(kernel.first)::value;
    const auto& all = stencils<D>();
    const auto n = static_cast<std::ptrdiff_t>(all.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t q = 0; q < n; ++q) f(kernel, static_cast<std::size_t>(q), all[static_cast<std::size_t>(q)]);
  });
}

template <class F>
void Transfer::interpolate(const std::vector<Vec3>& va, const std::vector<Vec3>& vb, F&& f) const {
  each_particle([&](auto kernel, std::size_t q, const auto& s) {
    constexpr int D = decltype(kernel.first)::value, S = decltype(kernel.second)::value;
    Vec3 sa, sb;
    gather<D, S>(s, nodes<D, S>(s), va, vb, sa, sb);
    f(q, sa, sb);
  });
}

template <class F>
void Transfer::interpolate_and_remap(Grid& grid, const Particles& p, const std::vector<Vec3>& va,
                                     const std::vector<Vec3>& vb, F&& f) const {
  const auto nn = static_cast<std::ptrdiff_t>(grid.field_size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < nn; ++i) grid.momentum[static_cast<std::size_t>(i)].setZero();
  dispatch([&](auto kernel) {
    constexpr int D = decltype(kernel.first)::value, S = decltype(kernel.second)::value;
    scatter<D, S, false>(grid, p, [&](std::size_t q, const Stencil<D>& s, const auto& node) {
      Vec3 sa, sb;
      gather<D, S>(s, node, va, vb, sa, sb);
      f(q, sa, sb);
    });
  });
}

template <class Body>
void Transfer::slab_passes(Body&& body) const {
  const std::size_t bins = bin_start_.size() - 1;
  for (const auto& pass : passes_) {
    const auto count = static_cast<std::ptrdiff_t>(pass.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const std::size_t slab = pass[static_cast<std::size_t>(k)];
      const std::size_t first = bin_start_[std::min(bins, slab * slab_bins_)];
      const std::size_t last = bin_start_[std::min(bins, (slab + 1) * slab_bins_)];
      body(first, last);
    }
  }
}

template <int Dim, int S, bool Force, class Before>
void Transfer::scatter(Grid& grid, const Particles& p, Before&& before, const std::vector<double>& correction) const {
  const auto& all = stencils<Dim>();
  const bool gradient = Force && !grid.mass_gradient.empty();  // contact normals (contact.hpp)
  const bool corrected = Force && !correction.empty();
  slab_passes([&](std::size_t first, std::size_t last) {
    for (std::size_t e = first; e < last; ++e) {
      const std::size_t q = binned_[e];
      const auto& s = all[q];
      const auto node = nodes<Dim, S>(s);
      before(q, s, node);
      const double m = p.mass[q];
      const Vec3 mv = m * p.v[q];
      Mat3 vs;  // V_p σ_p
      if constexpr (Force) {
        vs = p.volume(q) * p.state[q].stress();
        if (corrected)
          for (int r = 0; r < Dim; ++r) vs(r, r) += correction[q];
      }
      each_node<Dim, S>(s, node, [&](std::size_t i, double w, const std::array<double, 3>& g) {
        Vec3& gm = grid.momentum[i];
        for (int r = 0; r < Dim; ++r) gm[r] += w * mv[r];
        if constexpr (Force) {
          grid.mass[i] += w * m;
          if (gradient)
            for (int r = 0; r < Dim; ++r) grid.mass_gradient[i][r] += m * g[static_cast<std::size_t>(r)];
          Vec3& f = grid.force[i];
          for (int r = 0; r < Dim; ++r) {
            double t = vs(r, 0) * g[0];
            for (int k2 = 1; k2 < Dim; ++k2) t += vs(r, k2) * g[static_cast<std::size_t>(k2)];
            f[r] -= t;  // eq. 12, σ symmetric
          }
        }
      });
    }
  });
}

template <int Dim, int S, std::size_t N, class G>
inline void Transfer::each_node(const Stencil<Dim>& s, const std::array<std::size_t, N>& node, G&& g) {
  std::size_t n = 0;
  for (int c = 0; c < (Dim == 3 ? S : 1); ++c) {
    const auto uc = static_cast<std::size_t>(c);
    const double wz = Dim == 3 ? s.w[Dim - 1][uc] : 1.0, dwz = Dim == 3 ? s.dw[Dim - 1][uc] : 0.0;
    for (int b = 0; b < S; ++b) {
      const auto ub = static_cast<std::size_t>(b);
      const double wy = s.w[1][ub], dwy = s.dw[1][ub];
      for (int a = 0; a < S; ++a, ++n) {
        const auto ua = static_cast<std::size_t>(a);
        const double wx = s.w[0][ua], dwx = s.dw[0][ua];
        g(node[n], wx * wy * wz, std::array<double, 3>{dwx * wy * wz, wx * dwy * wz, wx * wy * dwz});
      }
    }
  }
}

template <bool Layered, class F>
void Transfer::scatter_each(F&& f) const {
  dispatch([&](auto kernel) {
    constexpr int D = decltype(kernel.first)::value, S = decltype(kernel.second)::value;
    const auto& all = stencils<D>();
    slab_passes([&](std::size_t first, std::size_t last) {
      for (std::size_t e = first; e < last; ++e) {
        const std::size_t q = binned_[e];
        f(q, [&](auto&& g) { each_node<D, S>(all[q], nodes<D, S, Layered>(all[q]), g); });
      }
    });
  });
}

template <class F>
void Transfer::gather_each(F&& f) const {
  each_particle([&](auto kernel, std::size_t q, const auto& s) {
    constexpr int D = decltype(kernel.first)::value, S = decltype(kernel.second)::value;
    f(q, [&](auto&& g) { each_node<D, S>(s, nodes<D, S, false>(s), g); });
  });
}

template <class F>
void Transfer::gradient(const std::vector<Vec3>& va, std::vector<Mat3>& out, F&& f) const {
  constexpr std::size_t block = 32;  // particles whose gradients are stored before f runs on them
  dispatch([&](auto kernel) {
    constexpr int D = decltype(kernel.first)::value, S = decltype(kernel.second)::value;
    const auto& all = stencils<D>();
    const auto blocks = static_cast<std::ptrdiff_t>((all.size() + block - 1) / block);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t b = 0; b < blocks; ++b) {
      const std::size_t first = static_cast<std::size_t>(b) * block, last = std::min(first + block, all.size());
      for (std::size_t q = first; q < last; ++q) {
        Mat3 l = Mat3::Zero();
        each_node<D, S>(all[q], nodes<D, S>(all[q]), [&](std::size_t node, double, const std::array<double, 3>& g) {
          const Vec3& v = va[node];
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) l(r, k) += v[r] * g[static_cast<std::size_t>(k)];
        });
        out[q] = l;
      }
      for (std::size_t q = first; q < last; ++q) f(q);
    }
  });
}

}  // namespace shockfield::mpm
