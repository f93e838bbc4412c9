#pragma once
// The largest systems a case may ask for, checked where the counts are read and before anything
// is sized by them: a count trusted too far ends in std::bad_alloc (exit 1) or swaps the machine,
// instead of an input error naming the key.
#include <fmt/format.h>

#include <string>

namespace shockfield {

/// Grid cells or nodes (DBM lattice, MPM grid, phase-field grid) and lattice atoms (MD): 10^9.
/// A DBM cell holds 16 distribution values in three copies (~400 bytes), an MPM or phase-field
/// node ~100 bytes and an atom ~300 with its neighbours, so 10^9 of them is 0.1-0.4 TB: beyond
/// the machines this code runs on, and 10^3 times the largest example.
inline constexpr double kMaxGridPoints = 1e9;

/// Particles and points that carry a material state (MPM particles, PD points): 10^8. An MPM
/// particle holds ~500 bytes (position, velocity, volumes, deformation and velocity gradients,
/// stress and history), a PD point ~1 kB with its bonds, so 10^8 of them is 60-100 GB. Counted
/// from the case (lattice points of a body) before any is made.
inline constexpr double kMaxParticles = 1e8;

/// PD bonds (all points' families together): 2·10^9. The family's CSR offsets are `int`, which
/// holds at most 2^31 − 1 ≈ 2.1·10^9 bonds, and a bond costs ~40 bytes in the run (neighbour,
/// length, volume scale, influence weight, damage flag), so 2·10^9 bonds are ~80 GB: beyond the
/// machines this code runs on (the examples have at most ~10^7). Bonds per point grow as m³
/// (4/3·π·m³ inside a 3D body for δ = m·ΔX), so a large horizon_factor reaches it long before the
/// point bound; counted from the lattice before the body is built (pd/lattice_bonds.hpp).
inline constexpr double kMaxBonds = 2e9;

/// "3.2 GB", "450 MB": the memory a run's arrays will take, as `shockfield run --check` prints it
/// (an estimate of the large arrays, in decimal units).
inline std::string memory_text(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.3g} GB", bytes / 1e9);
  return fmt::format("{:.3g} MB", bytes / 1e6);
}

}  // namespace shockfield
