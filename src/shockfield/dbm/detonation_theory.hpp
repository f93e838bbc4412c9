#pragma once
// Chapman–Jouguet theory of a planar detonation in a polytropic gas (γ the same before and after
// the reaction, heat release Q per unit mass of reactant), the reference for the reactive DBM
// (docs/theory/dbm.md, "Detonation: CJ speed and von Neumann state"). In the frame of the fresh
// gas (state 0, at rest), with the detonation moving at D:
//   D_CJ = sqrt(c0² + (γ²−1)Q/2) + sqrt((γ²−1)Q/2),   c0² = γ p0/ρ0,
//   u_CJ = (ρ0 D² − γ p0)/((γ+1) ρ0 D),  p_CJ = p0 + ρ0 D u_CJ,  ρ_CJ = ρ0 D/(D − u_CJ),
// and the von Neumann state is the inert shock at D (Rankine–Hugoniot, Mach M = D/c0):
//   ρ_vN/ρ0 = (γ+1)M²/((γ−1)M² + 2),  p_vN/p0 = 1 + 2γ(M² − 1)/(γ+1),  u_vN = D(1 − ρ0/ρ_vN).
namespace shockfield::dbm {

struct GasState {
  double rho = 1.0, u = 0.0, p = 1.0;
};

struct ChapmanJouguet {
  double speed = 0.0;       ///< D_CJ in the lab frame (fresh gas moving at fresh.u)
  GasState cj, von_neumann;  ///< lab-frame states behind the reaction zone and behind the shock
};

/// CJ detonation running towards +x into `fresh`; InputError unless γ > 1, Q > 0 and the fresh
/// state is positive.
ChapmanJouguet chapman_jouguet(const GasState& fresh, double gamma, double Q);

}  // namespace shockfield::dbm
