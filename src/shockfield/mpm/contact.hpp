#pragma once
// Multi-body frictional contact of the material point method (Bardenhagen, Guilkey, Roessig,
// Brackbill, Witzel & Foster, "An improved contact algorithm for the material point method and
// application to stress propagation in granular material", CMES 2 (2001) 509–522; equations as
// implemented in docs/theory/mpm.md, "Contact between bodies").
//
// With contact on, every body (Particles::body) has its own layer of nodal mass, momentum, force
// and mass gradient (Grid::set_layers): its points see only their own body's grid velocity, so
// bodies pass through each other unless the layers are coupled here. At a node where two or more
// bodies have mass, with
//   v_cm = Σ_b p_b / Σ_b m_b                   centre-of-mass velocity of the node
//   n_b  = unit(∇m_b − Σ_{c≠b} ∇m_c)           outward normal of body b (n_a = −n_b for two bodies)
//   Δv   = p_b/m_b − v_cm,  Δv·n_b > 0         body b approaches the others: contact
// body b's velocity is corrected (Bardenhagen et al., the frictional contact law):
//   v_b ← v_b − (Δv·n_b)(n_b + μ' t_b),   t_b = unit(Δv − (Δv·n_b)n_b),
//   μ' = min(μ, |Δv − (Δv·n_b)n_b| / (Δv·n_b))
// i.e. the normal relative velocity is removed, the tangential one reduced by Coulomb friction
// μ·(Δv·n_b) and at most to zero (stick: v_b = v_cm). Bodies moving apart (Δv·n_b ≤ 0) are left
// alone: they separate. For two bodies the corrections are equal and opposite (momentum conserved
// to round-off); the normal is the same line for both, which is why it is built from both
// bodies' gradients rather than each body's own.
#include <cstddef>

#include "shockfield/mpm/grid.hpp"

namespace shockfield::mpm {

struct ContactOptions {
  bool enabled = false;   ///< one grid field per body, coupled by the contact law; off: bodies share one field
  double friction = 0.0;  ///< Coulomb coefficient μ ≥ 0 (0 frictionless; large: stick)

  void validate() const;
};

/// What a contact pass did.
struct ContactStats {
  std::size_t nodes = 0;  ///< nodes where at least one body was corrected
  double force = 0.0;     ///< ½ Σ_nodes Σ_b |Δp_b| / Δt [N, N/m in 2D]: the force between bodies in contact
};

/// The contact law on the layered nodal momenta of `grid` (after the momentum update, or after the
/// MUSL remap): nodes lighter than `mass_floor` in a layer do not count as that body's. Each node
/// is corrected independently, so the result does not depend on the thread count.
ContactStats apply_contact(Grid& grid, double friction, double mass_floor, double dt);

}  // namespace shockfield::mpm
