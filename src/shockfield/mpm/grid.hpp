#pragma once
// The MPM background grid (Xu et al. 2015, §2.2.2): a regular mesh of cells in 2D plane strain (x, y;
// one node layer in z) or 3D, fixed in space (the "convective" step of the paper maps back to the
// original mesh every step). Each axis is either periodic (n nodes, index n wraps to 0) or
// bounded (n + 1 nodes) with a free, stick or slip rigid wall on each face.
#include <array>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/mpm/shape_functions.hpp"

namespace shockfield::mpm {

enum class Wall { Free, Stick, Slip };

struct GridSpec {
  int dim = 2;                               ///< 2 (plane strain) or 3
  Vec3 origin = Vec3::Zero();                ///< position of node (0, 0, 0) [m]
  Vec3 cell_size = Vec3::Constant(1e-6);     ///< h per axis [m]
  std::array<int, 3> cells{1, 1, 1};         ///< cells per axis (z unused in 2D)
  std::array<bool, 3> periodic{false, false, false};
  std::array<std::array<Wall, 2>, 3> walls{};  ///< [axis][0 = low face, 1 = high face]

  /// InputError naming the field when the grid is ill-formed.
  void validate() const;
  /// Extent of the grid along an axis [m].
  double length(int axis) const { return cells[static_cast<std::size_t>(axis)] * cell_size[axis]; }
};

class Grid {
 public:
  /// The nodal fields are allocated now, or (`allocate` false) by the first allocate(): a
  /// Simulation defers them to its first step, so that `shockfield run --check` never allocates
  /// the grid (docs/robustness.md).
  explicit Grid(const GridSpec& spec, bool allocate = true);
  /// Sizes mass, momentum and force to field_size() entries (zero) unless they are already, and
  /// with more than one layer the mass gradient too.
  void allocate();
  /// Multi-body contact (contact.hpp): the nodal fields hold `layers` copies, one per body, node i
  /// of body b at b·size() + i. Takes effect at the next allocate().
  void set_layers(int layers) { layers_ = layers; }
  int layers() const { return layers_; }
  std::size_t field_size() const { return size_ * static_cast<std::size_t>(layers_); }

  const GridSpec& spec() const { return spec_; }
  int dim() const { return spec_.dim; }
  /// Nodes along an axis.
  int nodes(int axis) const { return nodes_[static_cast<std::size_t>(axis)]; }
  std::size_t size() const { return size_; }
  std::size_t flat(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(nodes_[1]) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(nodes_[0]) + static_cast<std::size_t>(i);
  }
  std::array<int, 3> unflatten(std::size_t n) const;
  /// Node index along an axis after periodic wrapping, or −1 when outside a bounded axis.
  int wrap(int axis, int i) const;
  double min_cell_size() const;

  /// Wrap a position into the periodic extent; false when it lies outside a bounded axis.
  bool wrap_position(Vec3& x) const {
    for (int a = 0; a < spec_.dim; ++a) {
      const double len = spec_.length(a);
      double r = x[a] - spec_.origin[a];
      if (spec_.periodic[static_cast<std::size_t>(a)]) {
        if (!(r >= 0.0 && r < len)) r = wrap_periodic(r, len);
        x[a] = spec_.origin[a] + r;
      } else if (!(r >= 0.0 && r <= len)) {
        return false;
      }
    }
    return true;
  }
  /// Fit a 1D stencil into the grid: wrap along periodic axes; on bounded axes drop the weights
  /// of nodes beyond the edge (a GIMP particle box overhanging a wall) and shift the window in.
  /// False when the particle itself is outside.
  bool fit(int axis, Weights1D& w) const {
    const auto a = static_cast<std::size_t>(axis);
    const bool inside = spec_.periodic[a] ? w.base >= 0 && w.base < nodes_[a]  // already wrapped
                                          : w.base >= 0 && w.base + w.count <= nodes_[a];
    return inside || fit_edge(axis, w);
  }

  /// Impose the rigid walls on nodal momenta (every layer): stick zeroes all components, slip the
  /// normal one.
  void apply_walls(std::vector<Vec3>& momentum) const;

  // Nodal fields, field_size() entries (layer by layer).
  std::vector<double> mass;
  std::vector<Vec3> momentum;
  std::vector<Vec3> force;
  std::vector<Vec3> mass_gradient;  ///< Σ_p m_p ∇N_ip per layer; only with more than one layer (contact normals)

 private:
  bool fit_edge(int axis, Weights1D& w) const;  // fit() on a periodic axis or at a bounded edge
  static double wrap_periodic(double r, double len);  // r into [0, len)

  GridSpec spec_;
  std::array<int, 3> nodes_{};
  std::size_t size_ = 0;
  int layers_ = 1;
};

}  // namespace shockfield::mpm
