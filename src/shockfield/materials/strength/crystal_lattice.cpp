#include "shockfield/materials/strength/crystal_lattice.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"

namespace shockfield::materials {

std::vector<SlipSystem> fcc_slip_systems() {
  // Each {111} plane holds the three ⟨110⟩ directions perpendicular to it.
  const Vec3 normals[4] = {{1, 1, 1}, {-1, 1, 1}, {1, -1, 1}, {1, 1, -1}};
  const Vec3 directions[6] = {{0, 1, -1}, {1, 0, -1}, {1, -1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 0}};
  std::vector<SlipSystem> systems;
  for (const Vec3& n : normals)
    for (const Vec3& d : directions)
      if (d.dot(n) == 0.0) systems.push_back({d.normalized(), n.normalized()});
  return systems;
}

std::vector<SlipSystem> slip_systems(const std::string& name) {
  if (name == "fcc") return fcc_slip_systems();
  throw InputError(fmt::format("unknown slip system set '{}' (expected fcc)", name));
}

Mat3 bunge_rotation(double phi1, double Phi, double phi2) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  auto check = [](const char* name, double v, double hi, bool closed) {
    if (!(v >= 0.0 && (closed ? v <= hi : v < hi)))
      throw InputError(fmt::format("Bunge Euler angle {} = {} rad is out of range (expected {} ≤ {} {} {:.6g})", name, v,
                                   0, name, closed ? "≤" : "<", hi));
  };
  check("φ1", phi1, two_pi, false);
  check("Φ", Phi, std::numbers::pi, true);
  check("φ2", phi2, two_pi, false);
  using Eigen::AngleAxisd;
  return (AngleAxisd(phi1, Vec3::UnitZ()) * AngleAxisd(Phi, Vec3::UnitX()) * AngleAxisd(phi2, Vec3::UnitZ()))
      .toRotationMatrix();
}

Vec3 random_bunge_angles(std::uint64_t seed, std::uint64_t k) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  // Uniform (Haar) measure: φ1, φ2 uniform, cos Φ uniform.
  return {two_pi * rng::uniform(seed, k, 0), std::acos(2.0 * rng::uniform(seed, k, 1) - 1.0),
          two_pi * rng::uniform(seed, k, 2)};
}

Mat3 rotation_loading_along(const Vec3& axis) {
  // g maps crystal → sample with g·axiŝ = x̂ (the shortest such rotation).
  return Eigen::Quaterniond::FromTwoVectors(axis.normalized(), Vec3::UnitX()).toRotationMatrix();
}

}  // namespace shockfield::materials
