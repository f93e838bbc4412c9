#pragma once
// The discrete Boltzmann case file (method = "dbm"): the compressible BGK model on a D2V16
// lattice, started from a Riemann problem along x or a uniform state, or ([model] kind = "gls")
// the GLS liquid–vapour model started from a quench (gls_case.hpp). Read and validated
// completely before anything runs; every failure names the file and the key (docs/dbm.md).
// Units are those of the model (ρ, u, T dimensionless, p = ρT).
#include <optional>

#include "shockfield/core/config.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/dbm/boundary.hpp"
#include "shockfield/dbm/detonation.hpp"
#include "shockfield/dbm/gls_case.hpp"
#include "shockfield/dbm/lattice.hpp"
#include "shockfield/dbm/riemann_exact.hpp"
#include "shockfield/dbm/simulation.hpp"
#include "shockfield/dbm/velocity_model.hpp"

namespace shockfield::dbm {

struct InitialSpec {
  Macro left, right;  ///< equal for a uniform start
  double split = 0.0; ///< x of the jump: cells with x < split take `left`
  bool riemann = false;
};

/// Intervals in model time; profiles are profiles/profile_<k>.csv, fields fields/*.vti + grid.pvd.
struct DbmOutputSpec : OutputIntervals {
  int profile_row = 0;  ///< j of the line profile along x
};

struct DbmCase {
  Lattice lattice;
  VelocityModel model;
  BgkSettings bgk;           ///< dt already adjusted so that a whole number of steps hits end_time
  long long steps = 0;       ///< steps to end_time
  Boundaries boundaries;
  InitialSpec initial;
  double end_time = 0.0;
  DbmOutputSpec output;
  /// Exact star-region p and u of the Riemann problem (u_y = 0, no vacuum), for [derived].
  std::optional<RiemannStar> exact_star;
  /// The one-step reactive DBM of [reaction] (reaction_case.hpp), when present.
  std::optional<ReactionSpec> reaction;
  /// [model] kind = "gls": the liquid–vapour force, the quench and the L(t) threshold.
  std::optional<GlsCaseSpec> gls;
};

/// Reads [grid], [model], [initial], [boundary], [run], [output] and [reaction].
DbmCase read_dbm_case(const Config& root);

}  // namespace shockfield::dbm
