#pragma once
// The elastic macroparticle pair law as a pair style of the MD engine, in the engine's reduced
// units (reduced_units.hpp: r0 = D = 1):
//   φ(r) = [p r^-q − q r^-p]/(q − p)        (eq 5 with G = f r0^p, H = f r0^q, f = D pq/(q − p))
//   −φ'(r)/r = pq/(q − p)·(r^-q − r^-p)/r²  (fpair: force on i = (x_i − x_j)·fpair)
// for r below the cutoff, which lies between the first (r0) and second (√2 r0) neighbour shells of
// the fcc packing, so that each particle has the 12 bonds eq 10 shares its energy among. The
// energy is not shifted: a bulk particle has φ = −6D = −P_atom exactly (eq 10). Table 1's
// exponents take compile-time multiplication chains (inverse_powers.hpp; per pair cheaper than
// lj/cut's, bench/RESULTS.md), other integers a loop, the rest std::pow. With a plastic route
// (plastic_bonds.hpp) every pair outside the elastic band follows its bond state instead.
#include <memory>
#include <optional>
#include <string>

#include "shockfield/macroparticle/plastic_bonds.hpp"

#include "shockfield/md/potential.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"

namespace shockfield::macroparticle {

class MacroparticlePotential final : public md::Potential {
 public:
  /// Exponents p < q, cutoff in units of r0 (1 < cutoff < √2).
  MacroparticlePotential(double p, double q, double cutoff);
  /// The plastic pair law of eq 16 with its bond states in `table`.
  void set_plasticity(const PlasticRoute& route, std::shared_ptr<BondTable> table);

  std::string style() const override { return "macroparticle"; }
  double cutoff() const override { return cutoff_; }
  void check_types(const md::Atoms& atoms) const override;
  void compute(md::Atoms& atoms, const geometry::NeighborList& list, md::ForceResult& out) override;

  double p() const { return p_; }
  double q() const { return q_; }

 private:
  void compute_plastic(md::Atoms& atoms, const geometry::NeighborList& list, md::ForceResult& out);

  double p_, q_, cutoff_;
  std::optional<PlasticBondLaw> plastic_;
  std::shared_ptr<BondTable> bonds_;
  md::potentials::ThreadScratch scratch_;
};

}  // namespace shockfield::macroparticle
