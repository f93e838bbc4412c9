#include "shockfield/dbm/reaction_case.hpp"

#include <fmt/format.h>

namespace shockfield::dbm {
namespace {

RateLaw read_law(const Config& t) {
  RateLaw law;
  law.kind = t.get_choice("kind", {"arrhenius", "cochran"}) == "arrhenius" ? RateKind::arrhenius : RateKind::cochran;
  law.heat_release = t.get_double("heat_release", Range::positive());
  law.ignition_temperature = t.get_double_or("ignition_temperature", 0.0, Range::non_negative());
  if (law.kind == RateKind::arrhenius) {
    law.rate = t.get_double("rate", Range::positive());
    law.activation = t.get_double_or("activation", 0.0, Range::non_negative());
    return law;
  }
  law.omega1 = t.get_double_or("omega1", 0.0, Range::non_negative());
  law.omega2 = t.get_double_or("omega2", 0.0, Range::non_negative());
  law.m = t.get_double_or("m", 1.0);
  law.n = t.get_double_or("n", 1.0);
  if (law.omega1 == 0.0 && law.omega2 == 0.0)
    t.fail("omega1", "the Cochran rate needs omega1 > 0 or omega2 > 0 (both are 0, nothing would react)");
  return law;
}

}  // namespace

std::optional<ReactionSpec> read_reaction(const Config& root, const DbmCase& c) {
  const std::optional<Config> t = root.optional_table("reaction");
  if (!t) return std::nullopt;
  if (c.gls) t->fail("kind", "[reaction] needs model.kind = \"bgk\": the GLS liquid-vapour model has no reaction");
  if (c.bgk.spectral_convection)
    t->fail("kind", "the reactive DBM carries the reactant on the NND face fluxes: set model.convection = \"nnd\"");
  ReactionSpec s;
  s.law = read_law(*t);
  const double length = c.lattice.nx * c.lattice.dx;
  s.ignition.x = t->get_double_or("ignition_x", 0.0, Range::closed(0.0, length));
  s.ignition.width = t->get_double_or("ignition_width", 0.0, Range::closed(0.0, length - s.ignition.x));
  s.inflow_lambda = t->get_double_or("inflow_lambda", 1.0, Range::closed(0.0, 1.0));
  const Macro& fresh = c.initial.right;
  if (fresh.uy != 0.0)
    t->fail("kind", "the detonation runs along +x: the fresh gas ([initial] right or uniform state) needs v = 0");
  s.fresh = {fresh.rho, fresh.ux, fresh.rho * fresh.T};
  s.theory = chapman_jouguet(s.fresh, c.bgk.gamma, s.law.heat_release);
  return s;
}

void derive_reaction(const Config& root, const ReactionSpec& s) {
  root.derive("cj_speed", s.theory.speed);
  root.derive("cj_rho", s.theory.cj.rho);
  root.derive("cj_u", s.theory.cj.u);
  root.derive("cj_p", s.theory.cj.p);
  root.derive("von_neumann_rho", s.theory.von_neumann.rho);
  root.derive("von_neumann_u", s.theory.von_neumann.u);
  root.derive("von_neumann_p", s.theory.von_neumann.p);
  root.derive("front_pressure", s.front_pressure());
}

}  // namespace shockfield::dbm
