#pragma once
// Crystal geometry for the crystal viscoplastic law (Liu et al. 2025, §2.3): slip systems by name and
// orientations as Bunge Euler angles.
//
// Bunge (z-x-z) convention: the rotation g = R_z(φ1)·R_x(Φ)·R_z(φ2) takes crystal axes to sample
// axes (a crystal vector v_c is v_s = g·v_c in the sample frame), φ1, φ2 ∈ [0, 2π), Φ ∈ [0, π].
#include <cstdint>
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"

namespace shockfield::materials {

struct SlipSystem {
  Vec3 direction;  ///< m0, unit slip direction (crystal frame)
  Vec3 normal;     ///< n0, unit slip-plane normal (crystal frame)
};

/// The 12 {111}⟨110⟩ systems of FCC crystals.
std::vector<SlipSystem> fcc_slip_systems();
/// Slip systems by name ("fcc"); InputError naming the known sets otherwise.
std::vector<SlipSystem> slip_systems(const std::string& name);

/// Crystal → sample rotation of Bunge angles in radians; InputError when out of range.
Mat3 bunge_rotation(double phi1, double Phi, double phi2);
/// Bunge angles (radians) of a rotation drawn uniformly over SO(3): number k of stream `seed`.
Vec3 random_bunge_angles(std::uint64_t seed, std::uint64_t k);
/// Rotation taking the crystal direction `axis` (e.g. [1 1 1]) onto the sample x axis.
Mat3 rotation_loading_along(const Vec3& axis);

}  // namespace shockfield::materials
