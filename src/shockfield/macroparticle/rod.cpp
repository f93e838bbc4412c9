#include "shockfield/macroparticle/rod.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"
#include "shockfield/macroparticle/loaded_layers.hpp"
#include "shockfield/macroparticle/pair_dissipation.hpp"
#include "shockfield/macroparticle/pair_potential.hpp"
#include "shockfield/md/fixes/langevin.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/lattice.hpp"
#include "shockfield/md/region.hpp"

namespace shockfield::macroparticle {
namespace {

constexpr double kCell = std::numbers::sqrt2;  // cubic cell of the packing, r0 = 1
constexpr double kSkin = 0.15;                 // cutoff + skin stays inside the second shell (√2)

struct Packing {
  geometry::Box box;
  md::Atoms atoms;
  std::array<long long, 3> cells{};
};

// The fcc sites with centres in [0, n·a] along each axis (both faces included), cut to the
// cylinder of radius n_phi·a/2 about the centre of the cross-section for a rod.
Packing build_packing(const SpecimenSpec& s) {
  Packing p;
  p.cells = s.shape == SpecimenSpec::Shape::box ? s.cells : std::array<long long, 3>{s.n_phi, s.n_phi, s.n_h};
  md::LatticeSpec spec;
  spec.a0 = kCell;
  const md::Lattice lattice(spec);
  const auto shrink = geometry::Boundary::shrink;
  p.box = lattice.box({static_cast<int>(p.cells[0] + 1), static_cast<int>(p.cells[1] + 1),
                       static_cast<int>(p.cells[2] + 1)}, {shrink, shrink, shrink});
  p.atoms.mass = {1.0};
  p.atoms.type_names = {""};
  lattice.create_atoms(p.box, p.atoms);
  const double tol = 1e-6;
  md::Region keep;
  keep.side_in = false;
  if (s.shape == SpecimenSpec::Shape::box) {
    keep.shape = md::Region::Shape::block;
    for (int d = 0; d < 3; ++d) {
      keep.lo[d] = -tol;
      keep.hi[d] = static_cast<double>(p.cells[d]) * kCell + tol;
    }
  } else {
    keep.shape = md::Region::Shape::cylinder;
    keep.axis = 2;
    keep.center = Vec3(0.5 * kCell * static_cast<double>(s.n_phi), 0.5 * kCell * static_cast<double>(s.n_phi), 0.0);
    keep.radius = 0.5 * kCell * static_cast<double>(s.n_phi) + tol;
    keep.axial_lo = -tol;
    keep.axial_hi = static_cast<double>(s.n_h) * kCell + tol;
  }
  md::delete_atoms(keep, p.atoms);
  return p;
}

ReducedUnits reduced_units(const PairLaw& law) { return {law.r0, law.bond_energy, law.particle_mass}; }

}  // namespace

Rod::Rod(const MacroparticleCase& c)
    : units_(reduced_units(c.law)),
      sim_(geometry::Box{}, md::Atoms{}, std::make_unique<MacroparticlePotential>(c.law.p, c.law.q, c.cutoff),
           c.dt / units_.time(), kSkin) {
  Packing p = build_packing(c.specimen);
  const double top_z = static_cast<double>(p.cells[2]) * kCell;
  length0_ = top_z;
  volume0_ = static_cast<double>(p.atoms.nlocal) / std::numbers::sqrt2;
  const bool loaded = c.loading.mode != LoadingSpec::Mode::none;
  // Strain rate in engine units (per engine ps); compression pulls the ends together.
  const double rate = (c.loading.mode == LoadingSpec::Mode::compression ? -1.0 : 1.0) * c.loading.strain_rate *
                      units_.time();
  const double layer = 0.25 * kCell;  // half the (001) layer spacing a/2
  double xc = 0, yc = 0;
  std::size_t middle = 0;
  md::Atoms& a = p.atoms;
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    const double z = a.x[i].z();
    if (loaded && z < layer) a.mask[i] |= kBottomBit;
    else if (loaded && z > top_z - layer) a.mask[i] |= kTopBit;
    else a.mask[i] |= kFreeBit;
    // The imperfection of [specimen] perturbation: Gaussian, keyed on (seed, particle id).
    if ((a.mask[i] & kFreeBit) && c.specimen.perturbation > 0)
      for (int d = 0; d < 3; ++d)
        a.x[i][d] += c.specimen.perturbation *
                     rng::normal(c.specimen.perturbation_seed, static_cast<std::uint64_t>(a.id[i]), static_cast<std::uint64_t>(d));
    if (z >= 0.25 * top_z - 1e-9 && z <= 0.75 * top_z + 1e-9) {
      a.mask[i] |= kMiddleBit;
      xc += a.x[i].x();
      yc += a.x[i].y();
      ++middle;
    }
    // The homogeneous velocity field of the strain rate, so the ends send no step wave.
    if (loaded) a.v[i].z() = rate * (z - 0.5 * top_z);
  }
  if (loaded && (p.atoms.nlocal < 3 || middle == 0))
    throw InputError(fmt::format("specimen: {} particles leave no free middle between the loaded layers", a.nlocal));
  xc /= static_cast<double>(middle);
  yc /= static_cast<double>(middle);
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & kMiddleBit) radius0_sq_ += std::pow(a.x[i].x() - xc, 2) + std::pow(a.x[i].y() - yc, 2);
  radius0_sq_ /= static_cast<double>(middle);

  sim_.box = p.box;
  sim_.atoms = std::move(p.atoms);
  // Eq 21's η_CG scales the random forces, i.e. the bath temperature by η_CG²; γ and μ in engine
  // units are γτ/M and μτ/M.
  const double bath = c.langevin ? c.langevin->temperature * std::pow(c.langevin->eta_cg, 2) / units_.temperature() : 0.0;
  const double per_engine_friction = units_.time() / units_.mass;
  if (c.langevin && c.langevin->friction > 0) {
    const double damping = 1.0 / (c.langevin->friction * per_engine_friction);  // fix langevin's M/γ
    sim_.fixes.push_back(std::make_unique<md::FixLangevin>(bath, damping, c.langevin->seed, kFreeBit));
  } else {
    sim_.fixes.push_back(std::make_unique<md::FixNve>(kFreeBit));
  }
  if (c.langevin && c.langevin->pair_viscosity > 0)
    sim_.fixes.push_back(std::make_unique<FixPairDissipation>(c.langevin->pair_viscosity * per_engine_friction, bath,
                                                              c.langevin->seed, c.cutoff));
  if (c.plasticity) {
    bonds_ = std::make_shared<BondTable>();
    static_cast<MacroparticlePotential&>(*sim_.potential).set_plasticity(*c.plasticity, bonds_);
    sim_.fixes.push_back(std::make_unique<FixBondHistory>(bonds_));
  }
  if (loaded)
    sim_.fixes.push_back(std::make_unique<FixLoadedLayers>(kBottomBit, kTopBit, 0.5 * rate * length0_, c.loading.clamped));
  sim_.setup(false);
}

void Rod::advance(bool per_atom) {
  sim_.advance([per_atom](std::int64_t) { return per_atom; });
}

RodMeasures Rod::measure() const {
  const md::Atoms& a = sim_.atoms;
  double zb = 0, zt = 0, xc = 0, yc = 0;
  std::size_t nb = 0, nt = 0, nm = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (a.mask[i] & kBottomBit) zb += a.x[i].z(), ++nb;
    if (a.mask[i] & kTopBit) zt += a.x[i].z(), ++nt;
    if (a.mask[i] & kMiddleBit) xc += a.x[i].x(), yc += a.x[i].y(), ++nm;
  }
  RodMeasures m;
  m.time = sim_.time * units_.time();
  if (nb > 0 && nt > 0) m.strain = (zt / static_cast<double>(nt) - zb / static_cast<double>(nb)) / length0_ - 1.0;
  xc /= static_cast<double>(nm);
  yc /= static_cast<double>(nm);
  double r2 = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i)
    if (a.mask[i] & kMiddleBit) r2 += std::pow(a.x[i].x() - xc, 2) + std::pow(a.x[i].y() - yc, 2);
  m.lateral_strain = std::sqrt(r2 / static_cast<double>(nm) / radius0_sq_) - 1.0;
  m.stress = -sim_.forces.virial[2] / volume0_ * units_.stress();
  const md::ThermoState t = sim_.thermo();
  m.kinetic = t.kinetic * units_.energy;
  m.potential = t.potential * units_.energy;
  m.temperature = t.temperature * units_.temperature();
  return m;
}

std::vector<double> Rod::particle_stress() const {
  std::vector<double> out(sim_.atoms.nlocal, 0.0);
  if (!sim_.forces.per_atom) return out;
  const double cell = 1.0 / std::numbers::sqrt2;
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = -sim_.forces.virial_atom[i][2] / cell * units_.stress();
  return out;
}

}  // namespace shockfield::macroparticle
