#pragma once
// Initial velocities (LAMMPS `velocity create T seed dist gaussian mom yes`): Gaussian
// components of variance k_B T/m, drawn per atom id (so the result does not depend on atom order
// or threads), total momentum removed, then scaled to exactly T with 3N−3 degrees of freedom.
#include <cstdint>

#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

void create_velocities(Atoms& atoms, double temperature, std::uint64_t seed, std::uint32_t group_bit = 1u);
/// Adds a constant velocity (Å/ps) to a group (flyer plates, bulk motion).
void add_velocity(Atoms& atoms, const Vec3& velocity, std::uint32_t group_bit);
/// Σ m v² over a group in eV (twice its kinetic energy) and the group's atom count.
double group_twice_kinetic(const Atoms& atoms, std::uint32_t group_bit, std::size_t& count);
/// Σ m v_d² per component d over a group in eV (LAMMPS compute temp's vector, diagonal).
Vec3 group_twice_kinetic_components(const Atoms& atoms, std::uint32_t group_bit);
/// Kinetic temperature of a group with 3N−3 degrees of freedom, K.
double group_temperature(const Atoms& atoms, std::uint32_t group_bit);

}  // namespace shockfield::md
