#pragma once
// Velocity-Verlet NVE integration of a group (LAMMPS `fix nve`):
//   v ← v + ½Δt f/m ;  x ← x + Δt v   (initial_integrate)
//   v ← v + ½Δt f/m                   (final_integrate)
#include <cstdint>

#include "shockfield/md/fix.hpp"

namespace shockfield::md {

class FixNve : public Fix {
 public:
  explicit FixNve(std::uint32_t group_bit = 1u) : group_bit_(group_bit) {}
  std::string name() const override { return "nve"; }
  void initial_integrate(Simulation& sim) override;
  void final_integrate(Simulation& sim) override;

 protected:
  /// v ← v + ½Δt f/m for the group, then x ← x + Δt v if `drift`.
  void half_kick(Simulation& sim, bool drift) const;
  std::uint32_t group_bit_;
};

}  // namespace shockfield::md
