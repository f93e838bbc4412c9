#pragma once
// Discrete velocity models of the compressible DBM (Xu et al. 2015, §2.3.4). A model is a set of Q
// velocities v_ki with an extra internal-energy variable η_ki per velocity (for an adjustable
// specific-heat ratio γ = (b+2)/b, b = 2 + I extra degrees of freedom). f^eq is obtained from the
// seven kinetic moment relations (eqs. 20–26) as f^eq = C⁻¹·M^eq; the model is usable only when
// the 16×16 moment matrix C is invertible, which the constructor of MomentInversion checks.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace shockfield::dbm {

/// Number of independent moment components fixed by eqs. 20–26 in 2D:
/// M0 (1) + M1 (2) + M2,0 (1) + M2 (3) + M3 (4) + M3,1 (2) + M4,2 (3).
inline constexpr int kMoments = 16;

using Matrix16 = Eigen::Matrix<double, kMoments, kMoments>;

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
/// ρu((b+2)T + u²)/2, eq. 26: ρ[((b+2)T + u²)T I + ((b+4)T + u²) uu]/2; b = 2 gives the paper's
/// forms exactly), handed to put(m, value) for m = 0..15 in the order of moment_row(). Real is
/// double, or std::complex<double> for the complex-step derivatives of linear_stability.cpp.
template <class Real, class Put>
inline void put_equilibrium_moments(Real rho, Real ux, Real uy, Real T, double b, Put&& put) {
  const Real u2 = ux * ux + uy * uy;
  const Real h = 0.5 * ((b + 2.0) * T + u2);  // M3,1 / (ρu)
  const Real g = 0.5 * ((b + 4.0) * T + u2);  // uu coefficient of M4,2 / ρ
  put(0, rho);                                  // eq. 20
  put(1, rho * ux), put(2, rho * uy);           // eq. 21
  put(3, 0.5 * rho * (b * T + u2));             // eq. 22
  put(4, rho * (T + ux * ux)), put(5, rho * ux * uy), put(6, rho * (T + uy * uy));   // eq. 23
  put(7, rho * (3.0 * T * ux + ux * ux * ux)), put(8, rho * (T * uy + ux * ux * uy));  // eq. 24
  put(9, rho * (T * ux + ux * uy * uy)), put(10, rho * (3.0 * T * uy + uy * uy * uy));
  put(11, rho * ux * h), put(12, rho * uy * h);                      // eq. 25
  put(13, rho * (h * T + g * ux * ux)), put(14, rho * g * ux * uy);  // eq. 26
  put(15, rho * (h * T + g * uy * uy));
}

Eigen::Matrix<double, kMoments, 1> equilibrium_moments(double rho, double ux, double uy, double T,
                                                       double b);

/// ρ, u, T from the sums Σf, Σf v_x, Σf v_y and Σf (v² + η²)/2 of one cell (eqs. 20–22); one
/// division per cell (1/b is loop-invariant in a loop over cells).
inline Macro macro_from_sums(double rho, double jx, double jy, double e, double b) {
  const double inv_rho = 1.0 / rho;
  Macro m;
  m.rho = rho;
  m.ux = jx * inv_rho;
  m.uy = jy * inv_rho;
  m.T = (2.0 * e * inv_rho - m.ux * m.ux - m.uy * m.uy) * (1.0 / b);
  return m;
}

/// ρ, u, T of one cell from f (eqs. 20–22 with f for f^eq; f_k at f[k·stride]).
Macro macro_of(const VelocityModel& model, const double* f, std::size_t stride, double b);

/// C⁻¹ of a velocity model, checked: InputError when the model has Q ≠ 16 velocities or C is
/// singular / too ill-conditioned to satisfy the moment relations.
///
/// C⁻¹ is applied in factored form C⁻¹ = R·S. When the velocities come in groups of four related
/// by 90° rotations (D2V16), f within a group is a discrete Fourier series f_r = a + b·ê_r +
/// (−1)^r d (ê_r the unit vector of velocity r, R holds these weights) and S maps the moments to
/// the modes a, b, d of each group; by symmetry each mode depends on a few moments only, so
/// S·M costs 61 multiply-adds instead of 256. Other models use R = I, S = C⁻¹.
///
/// The same symmetry fixes the pattern of S: a_g takes M0, M3, M4 + M6 and M13 + M15; b_g takes
/// (M1, M7, M9, M11) for x and, with the same weights, (M2, M10, M8, M12) for y; d_g takes
/// M4 − M6, M13 − M15, M5 and M14. equilibria() applies C⁻¹ in this form, checked against C⁻¹ on
/// construction, with every intermediate of a cell in registers (4 × 16 weights).
class MomentInversion {
 public:
  explicit MomentInversion(const VelocityModel& model);
  /// f^eq_k for k = 0..Q−1 into out (stride 1).
  void equilibrium(double rho, double ux, double uy, double T, double b, double* out) const;
  /// f^eq of n cells: out[k·n + i] from rho[i], ux[i], uy[i], T[i]; work holds 2·16·n doubles.
  /// Loops run over the cells, so they vectorise.
  void equilibria(const double* rho, const double* ux, const double* uy, const double* T, int n,
                  double b, double* out, double* work) const;
  /// The distribution with the given moments (in the order of equilibrium_moments()): C⁻¹·m.
  void distribution(const Eigen::Matrix<double, kMoments, 1>& moments, double* out) const;
  double condition_number() const { return condition_; }

 private:
  struct Term {
    int row, column;
    double weight;
  };
  /// out_row[i] = Σ weight·in_column[i] over terms sorted by row (arrays of n, row-major).
  static void apply(const std::vector<Term>& terms, const double* in, int n, double* out);

  /// Weights of the modes of one rotation group (see above) and ê of its first velocity.
  struct GroupWeights {
    double a[4], b[4], d[4], ex, ey;
  };
  /// The GroupWeights of a rotation-group model, or none when R·S in that form is not C⁻¹.
  static std::vector<GroupWeights> group_weights(const Matrix16& R, const Matrix16& S,
                                                 const Matrix16& inverse);

  std::vector<Term> modes_;    // nonzeros of S (moment → group mode)
  std::vector<Term> rebuild_;  // nonzeros of R (group mode → f_k)
  std::vector<GroupWeights> groups_;
  double condition_ = 0.0;
};

}  // namespace shockfield::dbm
