#pragma once
// Non-ordinary state-based (correspondence) peridynamics, Liu et al. (2025) eqs. 1-8, with the Riemann
// correction of eqs. 9-17 and a zero-energy-mode penalty.
//
//   K_i = Σ_j ω β V_j ξ⊗ξ                                  (eq. 7)
//   F_i = [Σ_j ω β V_j Y⊗ξ] K_i⁻¹                          (eq. 8)
//   T_i⟨ξ⟩ = ω P_i K_i⁻¹ ξ                                  (eq. 6)
//   L_i = Σ_j β V_j (T_i⟨ξ⟩ − T_j⟨−ξ⟩) = Σ_j β V_j T̂        (eqs. 2, 9, 11)
// Riemann correction (eqs. 12-17): with A = det(F)F⁻ᵀ (I for small strain) and P = A·σ,
//   T̂ = ω[(P_i − σ_m,i A_i)K_i⁻¹ + (P_j − σ_m,j A_j)K_j⁻¹]ξ     (deviatoric part, eq. 13)
//     + ω σ*[A_i K_i⁻¹ + A_j K_j⁻¹]ξ                              (spherical part with σ* = −p*, eq. 16)
// where p* is the Dukowicz two-shock interface pressure (riemann.hpp) between p_L = −σ_m,i and
// p_R = −σ_m,j, with the point velocities projected on the current bond direction.
// Zero-energy modes: the bond-wise penalty of Silling (J. Elasticity 127, 2017), which is
// Peridigm's "hourglass" force made dimension-free:
//   T_i^hg⟨ξ⟩ = C·(M / m_i)·ω·(Y − F_i ξ),  m_i = Σ ω β V |ξ|²,  M = ρ0 c_L²,
// C the case file's coefficient (0 turns it off).
// In 1D and 2D the unused directions are held: K and F are the identity there (uniaxial or plane
// strain), which is the paper's laterally constrained bar (Fig. 2).
#include <vector>

#include "shockfield/pd/constitutive.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/force_model.hpp"
#include "shockfield/pd/model_state.hpp"
#include "shockfield/pd/influence.hpp"

namespace shockfield::pd {

struct CorrespondenceOptions {
  bool riemann = true;    ///< eqs. 12-17 on/off (off: plain eq. 11)
  double hourglass = 0.0; ///< C of the zero-energy-mode penalty
};

template <CorrespondenceMaterial Material>
class CorrespondenceForce final : public ForceModel {
 public:
  /// Per-point materials (a polycrystal has one per grain); size 1 means the same everywhere.
  /// InputError when a point's shape tensor is singular (too few or collinear neighbours).
  CorrespondenceForce(const PointCloud& cloud, const Family& family, std::vector<Material> materials,
                      Influence influence, CorrespondenceOptions options);

  void compute(const Kinematics& k, std::vector<Vec3>& force_density) override;
  double stable_step(const std::vector<double>& density) const override;
  std::vector<double> damage() const override { return std::vector<double>(cloud_.size(), 0.0); }
  std::string name() const override { return "correspondence"; }

  const Mat3& deformation_gradient(std::size_t i) const { return f_[i]; }
  const Mat3& stress(std::size_t i) const { return sigma_[i]; }  ///< Cauchy σ
  const typename Material::State& state(std::size_t i) const { return state_[i]; }
  const Material& material(std::size_t i) const { return materials_[materials_.size() == 1 ? 0 : i]; }
  /// Everything a later step reads of the past (F and the material state of every point), for
  /// checkpoints; restore_state() takes it back bitwise (InputError on a size mismatch).
  /// `deformation_gradient` (9 per point, row-major) and one array per field of the material's
  /// state_layout() (per point, or per point and grain).
  ModelState saved_state() const;
  void restore_state(const ModelState& state);

 private:
  const PointCloud& cloud_;
  const Family& family_;
  std::vector<Material> materials_;
  CorrespondenceOptions options_;
  Mat3 unused_;                       // identity on the directions beyond cloud.dim
  std::vector<double> omega_;         // per bond
  std::vector<Mat3> k_inv_;           // K⁻¹ per point
  std::vector<double> weighted_volume_;
  std::vector<Mat3> f_, sigma_, pk_, ak_;  // F, σ, P K⁻¹, A K⁻¹
  std::vector<double> sigma_m_, rho_;
  std::vector<typename Material::State> state_;
};

}  // namespace shockfield::pd
