#include "shockfield/macroparticle/pair_potential.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/macroparticle/inverse_powers.hpp"

namespace shockfield::macroparticle {

namespace {

// The elastic pair law of eq 5 over the half list; powers(r², r^-p, r^-q) returns 1/r².
template <class Powers>
void elastic_forces(md::Atoms& atoms, const geometry::NeighborList& list, md::ForceResult& out,
                    md::potentials::ThreadScratch& scratch, double p, double q, double cutoff, Powers powers) {
  const double cutsq = cutoff * cutoff;
  const double scale = p * q / (q - p);
  const double ep = q / (q - p), eq = p / (q - p);
  auto kernel = [=](int, int, double rsq, double& fpair, double& energy) {
    if (rsq >= cutsq) return false;
    double rp, rq;
    const double r2inv = powers(rsq, rp, rq);
    fpair = scale * (rq - rp) * r2inv;
    energy = eq * rq - ep * rp;
    return true;
  };
  md::potentials::accumulate_pair_forces(atoms, list, kernel, out, scratch);
}

// Runs `run` with the compile-time powers of (P, Q) when the exponents are those.
template <int P, int Q, class Run>
bool run_fixed(int ip, int iq, const Run& run) {
  if (ip != P || iq != Q) return false;
  run([](double s2, double& sp, double& sq) { return inverse_powers<P, Q>(s2, sp, sq); });
  return true;
}

}  // namespace

MacroparticlePotential::MacroparticlePotential(double p, double q, double cutoff) : p_(p), q_(q), cutoff_(cutoff) {
  if (!(p > 0) || !(q > p))
    throw InputError(fmt::format("pair style macroparticle: exponents p = {}, q = {} have no minimum (expected q > p > 0)", p, q));
  if (!(cutoff > 1.0 && cutoff < std::sqrt(2.0)))
    throw InputError(fmt::format("pair style macroparticle: cutoff {} r0 must lie between the first (r0) and second "
                                 "(√2 r0) neighbour shells", cutoff));
}

void MacroparticlePotential::check_types(const md::Atoms& atoms) const {
  if (atoms.ntypes() != 1)
    throw InputError(fmt::format("pair style macroparticle: one particle type, the system has {}", atoms.ntypes()));
}

void MacroparticlePotential::set_plasticity(const PlasticRoute& route, std::shared_ptr<BondTable> table) {
  plastic_.emplace(p_, q_, route);
  bonds_ = std::move(table);
}

void MacroparticlePotential::compute_plastic(md::Atoms& atoms, const geometry::NeighborList& list,
                                             md::ForceResult& out) {
  const double cutsq = cutoff_ * cutoff_;
  const PlasticBondLaw* law = &*plastic_;
  const BondTable* table = bonds_.get();
  auto* pending = bonds_->pending(omp_get_max_threads()).data();
  const std::int64_t* id = atoms.id.data();
  const int* owner = atoms.ghost_owner.data();
  const auto nlocal = static_cast<int>(atoms.nlocal);
  auto kernel = [=](int i, int j, double rsq, double& fpair, double& energy) {
    if (rsq >= cutsq) return false;
    const double r = std::sqrt(rsq);
    const std::int64_t idj = j < nlocal ? id[j] : id[owner[j - nlocal]];
    const std::uint64_t key = BondTable::key(id[i], idj);
    const BondState* known = table->find(key);
    double tension;
    if (!known && law->elastic_band(r)) {
      tension = law->elastic_tension(r);
      energy = law->elastic_energy(r);
    } else {
      BondState s = known ? *known : law->initial();
      if (law->evaluate(r, s, tension, energy)) pending[omp_get_thread_num()].emplace_back(key, s);
    }
    fpair = -tension / r;  // force on i = −T (x_i − x_j)/r
    return true;
  };
  md::potentials::accumulate_pair_forces(atoms, list, kernel, out, scratch_);
  bonds_->apply_pending();
}

void MacroparticlePotential::compute(md::Atoms& atoms, const geometry::NeighborList& list, md::ForceResult& out) {
  if (plastic_) {
    compute_plastic(atoms, list, out);
    return;
  }
  const auto run = [&](auto powers) { elastic_forces(atoms, list, out, scratch_, p_, q_, cutoff_, powers); };
  // The (p, q) of Table 1 as unrolled chains; other integers by a loop; the rest by std::pow.
  const InversePowers powers(p_, q_);
  const int ip = powers.ip(), iq = powers.iq();
  if (run_fixed<3, 9>(ip, iq, run) || run_fixed<4, 8>(ip, iq, run) || run_fixed<4, 9>(ip, iq, run) ||
      run_fixed<4, 10>(ip, iq, run) || run_fixed<5, 9>(ip, iq, run) || run_fixed<5, 10>(ip, iq, run) ||
      run_fixed<6, 12>(ip, iq, run))
    return;
  run([powers](double s2, double& sp, double& sq) {
    powers(std::sqrt(s2), sp, sq);
    return 1.0 / s2;
  });
}

}  // namespace shockfield::macroparticle
