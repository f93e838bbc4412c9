#pragma once
// Explicit heat conduction of the material point method (Xu et al. 2015, §2.2.1: "optional heat
// conduction with the given k"), the standard MPM heat transfer (Tao et al.; Zhang, Chen & Liu,
// "The Material Point Method"), on the stencils of the step's Transfer:
//   C_i  = Σ_p m_p c_v,p N_ip                       nodal heat capacity (lumped)
//   T_i  = Σ_p m_p c_v,p T_p N_ip / C_i             nodal temperature
//   ∇T_p = Σ_i T_i ∇N_ip
//   Q_i  = −Σ_p V_p k_p ∇T_p·∇N_ip                  nodal heat rate (walls insulated)
//   ΔT_p = Δt Σ_i N_ip Q_i / C_i,   Δe_p = c_v,p ΔT_p
// Σ_i ∇N_ip = 0 (partition of unity) gives Σ_i Q_i = 0, so Σ_p m_p c_v,p ΔT_p = Δt Σ_i Q_i = 0:
// conduction moves internal energy between points and conserves the total. Stable while
//   Δt ≤ C·h² / (2·d·α_max),   α = k / (ρ c_v)                (explicit diffusion limit)
// Nodal sums go through Transfer::scatter_each, so results do not depend on the thread count.
#include <vector>

#include "shockfield/materials/solid_material.hpp"
#include "shockfield/mpm/particles.hpp"
#include "shockfield/mpm/transfer.hpp"

namespace shockfield::mpm {

class HeatConduction {
 public:
  /// One explicit step of length dt on `nodes` grid nodes; updates temperature and specific
  /// internal energy of every point. The transfer's stencils must be those of the particles'
  /// positions.
  void step(const Transfer& transfer, std::size_t nodes, Particles& p,
            const std::vector<materials::SolidMaterial>& materials, double dt);
  /// C·h² / (2·d·α_max) for the current densities; +∞ when every conductivity is 0.
  static double stable_time_step(const Particles& p,
                                 const std::vector<materials::SolidMaterial>& materials,
                                 double courant, double min_cell_size, int dim);

 private:
  std::vector<double> capacity_;     // C_i [J/K]
  std::vector<double> temperature_;  // Σ m c_v T N, then T_i [K]
  std::vector<double> rate_;         // Q_i [W]
};

}  // namespace shockfield::mpm
