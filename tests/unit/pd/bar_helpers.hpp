#pragma once
// A seed-004 1D impact bar with the correspondence model, for tests (Fig. 2 set-up).
#include <memory>

#include "shockfield/pd/bar_impact.hpp"
#include "shockfield/pd/correspondence.hpp"
#include "shockfield/pd/crystal_material.hpp"

namespace shockfield::pd::testing {

// The paper's §3.1 isotropic material: E = 77.11 GPa, ν = 0.334, Y = 270 MPa, ρ = 2703 kg/m³.
inline SmallStrainJ2 seed_aluminium(double yield = 270e6) {
  return SmallStrainJ2::from_young(2703.0, 77.11e9, 0.334, yield, 0.0, 0.0);
}

// The bar with any correspondence material (J2, crystal).
template <class Material>
struct MaterialBar {
  PointCloud cloud;
  Family family;
  CorrespondenceForce<Material>* force = nullptr;
  std::unique_ptr<Simulation> sim;

  MaterialBar(int points, double spacing, double m, double velocity, CorrespondenceOptions options,
              const Material& material)
      : cloud(bar_cloud(points, spacing)), family(build_family(cloud, m * spacing, VolumeCorrection::linear)) {
    auto model = std::make_unique<CorrespondenceForce<Material>>(cloud, family, std::vector<Material>(1, material),
                                                                 Influence(), options);
    force = model.get();
    sim = std::make_unique<Simulation>(cloud, family, std::move(model),
                                       std::vector{material.reference_density()});
    set_impact_velocity(*sim, velocity);
  }
  void run_until(double t, double dt) {
    while (sim->time() < t - 0.5 * dt) sim->step(dt);
  }
  std::vector<double> x() const {
    std::vector<double> out;
    for (const Vec3& p : cloud.x) out.push_back(p[0]);
    return out;
  }
  /// Axial stress σ_xx, positive in compression (as the paper plots it).
  std::vector<double> axial_compression() const {
    std::vector<double> out;
    for (std::size_t i = 0; i < cloud.size(); ++i) out.push_back(-force->stress(i)(0, 0));
    return out;
  }
  /// The plastic measure of every point (ε̄p for J2, mean γ_tot for a crystal).
  std::vector<double> plastic() const {
    std::vector<double> out;
    for (std::size_t i = 0; i < cloud.size(); ++i) out.push_back(plastic_measure(force->state(i)));
    return out;
  }
};

struct Bar : MaterialBar<SmallStrainJ2> {
  Bar(int points, double spacing, double m, double velocity, CorrespondenceOptions options,
      SmallStrainJ2 material = seed_aluminium())
      : MaterialBar(points, spacing, m, velocity, options, material) {}
};

}  // namespace shockfield::pd::testing
