#pragma once
// Small numeric aliases shared by every module (Eigen fixed-size types).
#include <Eigen/Core>
#include <cstdint>

namespace shockfield {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Index = std::int64_t;

/// Symmetric tensor in Voigt order xx, yy, zz, xy, xz, yz (the LAMMPS order).
using Voigt6 = Eigen::Matrix<double, 6, 1>;

}  // namespace shockfield
