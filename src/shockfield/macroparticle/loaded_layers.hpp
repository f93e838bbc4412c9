#pragma once
// Loading of a rod by prescribed velocities (Saitoh et al., §2.6: "velocity of particles in
// uppermost and lowermost layers is constrained so as to produce constant strain rate"): the
// particles of the bottom and top groups move along z at −v and +v (v = ε̇L₀/2; negative ε̇ for
// compression). With `clamped` their x and y are held too; otherwise x and y follow the forces by
// velocity Verlet, like md's fix nve (free lateral contraction of the ends).
#include <cstdint>

#include "shockfield/md/fix.hpp"

namespace shockfield::macroparticle {

class FixLoadedLayers final : public md::Fix {
 public:
  FixLoadedLayers(std::uint32_t bottom_bit, std::uint32_t top_bit, double end_speed, bool clamped)
      : bottom_(bottom_bit), top_(top_bit), speed_(end_speed), clamped_(clamped) {}
  std::string name() const override { return "loaded_layers"; }
  void initial_integrate(md::Simulation& sim) override;
  void final_integrate(md::Simulation& sim) override;

 private:
  std::uint32_t bottom_, top_;
  double speed_;
  bool clamped_;
};

}  // namespace shockfield::macroparticle
