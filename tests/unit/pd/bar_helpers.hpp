#pragma once
// A seed-004 1D impact bar with the correspondence model, for tests (Fig. 2 set-up).
#include <memory>

#include "shockfield/pd/bar_impact.hpp"
#include "shockfield/pd/correspondence.hpp"

namespace shockfield::pd::testing {

// The seed's §3.1 isotropic material: E = 77.11 GPa, ν = 0.334, Y = 270 MPa, ρ = 2703 kg/m³.
inline SmallStrainJ2 seed_aluminium(double yield = 270e6) {
  return SmallStrainJ2::from_young(2703.0, 77.11e9, 0.334, yield, 0.0, 0.0);
}

struct Bar {
  PointCloud cloud;
  Family family;
  CorrespondenceForce<SmallStrainJ2>* force = nullptr;
  std::unique_ptr<Simulation> sim;

  Bar(int points, double spacing, double m, double velocity, CorrespondenceOptions options,
      SmallStrainJ2 material = seed_aluminium())
      : cloud(bar_cloud(points, spacing)), family(build_family(cloud, m * spacing, VolumeCorrection::linear)) {
    auto model = std::make_unique<CorrespondenceForce<SmallStrainJ2>>(cloud, family, std::vector{material},
                                                                      Influence(), options);
    force = model.get();
    sim = std::make_unique<Simulation>(cloud, family, std::move(model), std::vector{material.density});
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
  /// Axial stress σ_xx, positive in compression (as the seed plots it).
  std::vector<double> axial_compression() const {
    std::vector<double> out;
    for (std::size_t i = 0; i < cloud.size(); ++i) out.push_back(-force->stress(i)(0, 0));
    return out;
  }
};

}  // namespace shockfield::pd::testing
