#pragma once
// Discrete velocity models of the compressible DBM (seed 000 §2.3.4). A model is a set of Q
// velocities v_ki with an extra internal-energy variable η_ki per velocity (for an adjustable
// specific-heat ratio γ = (b+2)/b, b = 2 + I extra degrees of freedom). f^eq is obtained from the
// seven kinetic moment relations (eqs. 20–26) as f^eq = C⁻¹·M^eq; the model is usable only when
// the 16×16 moment matrix C is invertible, which the constructor of MomentInversion checks.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace shockfield::dbm {

/// Number of independent moment components fixed by eqs. 20–26 in 2D:
/// M0 (1) + M1 (2) + M2,0 (1) + M2 (3) + M3 (4) + M3,1 (2) + M4,2 (3).
inline constexpr int kMoments = 16;

/// Hydrodynamic state of one cell.
struct Macro {
  double rho = 1.0, ux = 0.0, uy = 0.0, T = 1.0;
};

struct VelocityModel {
  std::string name;
  std::vector<double> vx, vy, eta;  // one entry per discrete velocity
  int size() const { return static_cast<int>(vx.size()); }
  double max_speed() const;
  /// Index of the velocity mirrored in x (−vx, vy, η) or y (vx, −vy, η); InputError if the model
  /// has none (reflecting walls need it).
  std::vector<int> mirror(int axis) const;
};

/// D2V16 (Gan, Xu et al.): four groups of four velocities of speeds v[0..3]; groups 0 and 2 along
/// the axes, groups 1 and 3 along the diagonals; η = eta0 on group 0, zero elsewhere.
VelocityModel d2v16(const std::array<double, 4>& speeds, double eta0);

/// The row of the moment matrix for one discrete velocity (the 16 weights of f_ki in the moments
/// of eqs. 20–26, in the order of equilibrium_moments()).
Eigen::Matrix<double, kMoments, 1> moment_row(double vx, double vy, double eta);

/// M^eq of eqs. 20–26 for b = 2/(γ−1) degrees of freedom (eq. 22: E = ρ(bT + u²)/2, eq. 25:
/// ρu((b+2)T + u²)/2, eq. 26: ρ[((b+2)T + u²)T I + ((b+4)T + u²) uu]/2; b = 2 gives the seed's
/// forms exactly).
Eigen::Matrix<double, kMoments, 1> equilibrium_moments(double rho, double ux, double uy, double T,
                                                       double b);

/// ρ, u, T of one cell from f (eqs. 20–22 with f for f^eq; f_k at f[k·stride]).
Macro macro_of(const VelocityModel& model, const double* f, std::size_t stride, double b);

/// C⁻¹ of a velocity model, checked: InputError when the model has Q ≠ 16 velocities or C is
/// singular / too ill-conditioned to satisfy the moment relations.
class MomentInversion {
 public:
  explicit MomentInversion(const VelocityModel& model);
  /// f^eq_k for k = 0..Q−1 into out (stride 1).
  void equilibrium(double rho, double ux, double uy, double T, double b, double* out) const;
  /// The distribution with the given moments (in the order of equilibrium_moments()): C⁻¹·m.
  void distribution(const Eigen::Matrix<double, kMoments, 1>& moments, double* out) const;
  double condition_number() const { return condition_; }

 private:
  Eigen::Matrix<double, kMoments, kMoments, Eigen::RowMajor> inverse_;
  double condition_ = 0.0;
};

}  // namespace shockfield::dbm
