#include "shockfield/macroparticle/case_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::macroparticle {
namespace {

constexpr double kDefaultCutoff = 0.5 * (1.0 + std::numbers::sqrt2);  // midway between the shells
constexpr double kDefaultStepFraction = 0.2;                        // of the stable step 2/ω_max

// The physical ranges of the atomic inputs (every metal lies well inside them); beyond them the
// derived stiffness and time step leave double range and the run would only blow up.
const Range kCohesiveEnergy = Range::closed(1e-3, 1e2);   // eV per atom
const Range kDensity = Range::closed(1.0, 1e5);            // kg/m³
const Range kAtomicMass = Range::closed(0.5, 500.0);       // u
const Range kLatticeConstant = Range::closed(1e-11, 1e-8); // m
const Range kExponent = {0.0, 100.0, true, false};
const Range kParticleRadius = Range::closed(1e-9, 1.0);       // m
const Range kAtomsPerParticle = Range::closed(1.0, 1e30);

// A value of the case, else (a cohesive energy always; the crystal's size and mass only when the
// case gives none of density, atomic_mass and lattice_constant) the material file's [atoms] value
// written by `shockfield bridge eam-to-macroparticle`, in the case key's unit and recorded in the
// resolved case as if given.
std::optional<double> case_or_atoms(const Config& m, const char* key, const Range& range, double scale,
                                    const materials::MaterialFile* file, std::string_view file_key) {
  if (m.has(key)) return m.get_double(key, range) * scale;
  const std::optional<double> v = file ? file->get(file_key) : std::nullopt;
  if (!v) return std::nullopt;
  return materials::file_default(m, key, *file, file_key, *v, range, scale) * scale;
}

std::optional<double> optional_in(const Config& t, const char* key, const Range& range, double scale = 1.0) {
  return case_or_atoms(t, key, range, scale, nullptr, {});
}

PairLawInput read_atoms(const Config& m, const Config& pair, std::vector<std::string>& notes) {
  const std::optional<materials::MaterialFile> file = materials::open_material_file(m);
  if (file) notes = file->summary_lines();
  const materials::MaterialFile* atoms = file ? &*file : nullptr;
  PairLawInput in;
  const auto e0 = case_or_atoms(m, "cohesive_energy", kCohesiveEnergy, units::si::eV, atoms, "atoms.cohesive_energy");
  in.cohesive_energy = e0 ? *e0 : m.get_double("cohesive_energy", kCohesiveEnergy);  // (the missing-key error)
  in.crystal = m.get_choice_or("crystal", {"fcc"}, "fcc");
  const bool sized = m.has("density") || m.has("atomic_mass") || m.has("lattice_constant");
  const materials::MaterialFile* sizes = sized ? nullptr : atoms;
  in.density = optional_in(m, "density", kDensity);
  in.atomic_mass = case_or_atoms(m, "atomic_mass", kAtomicMass, units::si::amu, sizes, "atoms.atomic_mass");
  in.lattice_constant = case_or_atoms(m, "lattice_constant", kLatticeConstant, 1.0, sizes, "atoms.lattice_constant");
  const int given = in.density.has_value() + in.atomic_mass.has_value() + in.lattice_constant.has_value();
  if (given != 2)
    m.fail(given < 2 ? "density" : "lattice_constant",
           "give two of density (kg/m³), atomic_mass (u) and lattice_constant (m): fcc ties the three by ρ = 4m/a0³");
  in.p = pair.get_double("p", kExponent);
  in.q = pair.get_double("q", kExponent);
  if (!(in.q > in.p))
    pair.fail("q", fmt::format("q = {} with p = {} gives no energy minimum: in φ = −G/(p r^p) + H/(q r^q) (eq 5, "
                               "Table 1) the repulsion exponent q must exceed the attraction exponent p", in.q, in.p));
  return in;
}

SpecimenSpec read_specimen(const Config& t, const Config& pair, PairLawInput& in) {
  SpecimenSpec s;
  s.shape = t.get_choice_or("shape", {"cylinder", "box"}, "cylinder") == "box" ? SpecimenSpec::Shape::box
                                                                             : SpecimenSpec::Shape::cylinder;
  if (s.shape == SpecimenSpec::Shape::cylinder) {
    s.diameter = t.get_double("diameter", Range::positive());
    s.n_phi = t.get_int("n_phi", Range::closed(1, 4096));
    if (s.n_phi < 2)
      t.fail("n_phi", "a rod of one cell across the diameter is too thin for its division (its particles form no "
                      "cross-section with an interior): expected n_phi >= 2");
    s.n_h = t.get_int("n_h", Range::closed(1, 1 << 20));
    for (const char* key : {"r0", "atoms_per_particle"})
      if (pair.has(key))
        pair.fail(key, "a cylinder's particle spacing follows from specimen.diameter and n_phi "
                       "(diameter = n_phi·√2·r0 + r0): remove this key");
    in.r0 = s.diameter / (std::numbers::sqrt2 * static_cast<double>(s.n_phi) + 1.0);
  } else {
    const auto cells = t.get_ints("cells", 3, Range::closed(1, 1 << 16));
    s.cells = {cells[0], cells[1], cells[2]};
    in.r0 = optional_in(pair, "r0", kParticleRadius);
    in.atoms_per_particle = optional_in(pair, "atoms_per_particle", kAtomsPerParticle);
    if (in.r0.has_value() == in.atoms_per_particle.has_value())
      pair.fail("r0", "a box needs its particle size: give exactly one of r0 (m) and atoms_per_particle");
  }
  // The specimen is cut from a packing of (n + 1)³ fcc cells of 4 sites (macroparticle/rod.cpp),
  // made whole before the cut, also under --check: bounded before anything is allocated.
  const std::array<long long, 3> cells =
      s.shape == SpecimenSpec::Shape::box ? s.cells : std::array<long long, 3>{s.n_phi, s.n_phi, s.n_h};
  const double sites = 4.0 * static_cast<double>(cells[0] + 1) * static_cast<double>(cells[1] + 1) *
                       static_cast<double>(cells[2] + 1);
  if (sites > kMaxParticles)
    t.fail(s.shape == SpecimenSpec::Shape::box ? "cells" : "n_phi",
           fmt::format("{} x {} x {} cells: the packing the specimen is cut from would hold {:.3g} particles; expected at "
                       "most {:.0e} (core/size_limits.hpp)", cells[0], cells[1], cells[2], sites, kMaxParticles));
  // An imperfection for instabilities a perfect packing under symmetric loading cannot start.
  s.perturbation = t.get_double_or("perturbation", 0.0, Range::closed(0.0, 0.05));
  s.perturbation_seed = static_cast<std::uint64_t>(t.get_int_or("perturbation_seed", 1, Range::closed(1, 9.0e15)));
  return s;
}

LoadingSpec read_loading(const std::optional<Config>& t) {
  LoadingSpec l;
  if (!t) return l;
  const std::string mode = t->get_choice_or("mode", {"none", "tension", "compression"}, "none");
  l.mode = mode == "tension" ? LoadingSpec::Mode::tension
           : mode == "compression" ? LoadingSpec::Mode::compression : LoadingSpec::Mode::none;
  if (l.mode == LoadingSpec::Mode::none) return l;
  l.strain_rate = t->get_double("strain_rate", Range::positive());
  l.final_strain = t->get_double("final_strain", {0.0, 0.5, true, false});
  l.clamped = t->get_choice_or("ends", {"sliding", "clamped"}, "sliding") == "clamped";
  return l;
}

LangevinSpec read_langevin(const Config& t, const PairLaw& law) {
  LangevinSpec s;
  s.temperature = t.get_double("temperature", Range::non_negative());
  s.eta_cg = t.get_double_or("eta_cg", 1.0, Range::positive());
  s.seed = static_cast<std::uint64_t>(t.get_int_or("seed", 1, Range::closed(1, 9.0e15)));
  if (t.has("friction")) {
    if (t.has("debye_temperature") || t.has("zeta_cg"))
      t.fail("friction", "give either friction (γ, kg/s) or debye_temperature with zeta_cg (eq 22), not both");
    s.friction = t.get_double("friction", Range::non_negative());
  } else if (t.has("debye_temperature")) {
    // Eq 22: α^macro = ζ_CG m (π/6) ω_D, ω_D = k_B θ_D/ħ.
    const double theta = t.get_double("debye_temperature", Range::positive());
    const double zeta = t.get_double_or("zeta_cg", 1.0, Range::positive());
    const double omega_d = units::si::boltz * theta / units::si::hbar;
    s.friction = zeta * law.atomic_mass * std::numbers::pi / 6.0 * omega_d;
  }
  s.pair_viscosity = t.get_double_or("pair_viscosity", 0.0, Range::non_negative());
  if (s.friction == 0 && s.pair_viscosity == 0)
    t.fail("friction", "the bath has no dissipation: give friction (eq 9), debye_temperature (eq 22) or "
                       "pair_viscosity (eq 8) > 0");
  return s;
}

PlasticRoute read_plasticity(const Config& t) {
  PlasticRoute r;
  r.yield_strain = t.get_double("yield_strain", {0.0, 0.2, true, false});
  r.compression_yield_strain = t.get_double_or("compression_yield_strain", r.yield_strain, {0.0, 0.5, true, false});
  // Any number of coefficients (get_doubles_or would demand the default's one).
  r.hardening = t.has("hardening") ? t.get_doubles("hardening", 0) : t.get_doubles_or("hardening", {0.0});
  if (r.hardening.empty() || r.hardening.size() > 8)
    t.fail("hardening", "expected 1 to 8 polynomial coefficients h_1 ... h_8");
  if (r.hardening[0] < 0 || r.hardening[0] >= 1)
    t.fail("hardening", fmt::format("h_1 = {} must be in [0, 1): the plastic route's slope as a fraction of the "
                                    "elastic stiffness k", r.hardening[0]));
  r.limit_strain = t.get_double_or("limit_strain", 0.3, {r.yield_strain, 1.0, true, false});
  if (t.has("saturation_strain"))
    r.saturation_strain = t.get_double("saturation_strain", {0.0, r.limit_strain - r.yield_strain, true, false});
  return r;
}

}  // namespace

MacroparticleCase read_macroparticle_case(const Config& root) {
  MacroparticleCase c;
  const Config pair = root.table("pair");
  PairLawInput in = read_atoms(root.table("material"), pair, c.material_notes);
  c.specimen = read_specimen(root.table("specimen"), pair, in);
  c.cutoff = pair.get_double_or("cutoff", kDefaultCutoff, {1.0, std::numbers::sqrt2, true, true});
  try {
    c.law = derive_pair_law(in);
  } catch (const InputError& e) {
    pair.fail("p", e.what());
  }
  const PairLaw& law = c.law;
  c.loading = read_loading(root.optional_table("loading"));
  if (const auto t = root.optional_table("langevin")) c.langevin = read_langevin(*t, law);
  if (const auto t = root.optional_table("plasticity")) c.plasticity = read_plasticity(*t);

  const Config run = root.table("run");
  const double stable = law.stable_time_step();
  c.dt = run.get_double_or("dt", kDefaultStepFraction * stable, Range::positive());
  if (c.dt > stable)
    run.fail("dt", fmt::format("{} s is beyond the stable time step 2/ω_max = {:.4g} s of this packing "
                               "(ω_max = √(8k/M), k = {:.4g} N/m, M = {:.4g} kg)", c.dt, stable, law.stiffness,
                               law.particle_mass));
  if (c.langevin && c.langevin->friction * c.dt / law.particle_mass > 0.5)
    root.table("langevin").fail(c.langevin->friction > 0 ? "friction" : "zeta_cg",
                                fmt::format("the friction γ = {:.4g} kg/s damps a particle (M = {:.4g} kg) within "
                                            "{:.3g} time steps; expected γΔt/M <= 0.5", c.langevin->friction,
                                            law.particle_mass, law.particle_mass / (c.langevin->friction * c.dt)));
  // Eq 8 over 12 bonds acts like a friction of up to 12μ (a particle against its neighbours).
  if (c.langevin && 12.0 * c.langevin->pair_viscosity * c.dt / law.particle_mass > 0.5)
    root.table("langevin").fail("pair_viscosity", fmt::format("μ = {:.4g} kg/s over 12 bonds damps a particle (M = {:.4g} kg) "
                                                              "within {:.3g} time steps; expected 12μΔt/M <= 0.5",
                                                              c.langevin->pair_viscosity, law.particle_mass,
                                                              law.particle_mass / (12.0 * c.langevin->pair_viscosity * c.dt)));
  if (c.loading.mode == LoadingSpec::Mode::none) {
    c.steps = run.get_int("steps", Range::closed(0, 1e12));
  } else {
    if (run.has("steps"))
      run.fail("steps", "a loaded run's steps follow from loading.final_strain / (strain_rate · dt): remove run.steps");
    c.steps = static_cast<long long>(std::ceil(c.loading.final_strain / (c.loading.strain_rate * c.dt) - 1e-9));
    if (c.steps > 1e12) root.table("loading").fail("final_strain", fmt::format("needs {} steps", c.steps));
  }

  const auto out = root.optional_table("output");
  if (out) {
    c.output.thermo_every = out->get_int_or("thermo_every", 0, Range::closed(0, 1e12));
    c.output.dump_every = out->get_int_or("dump_every", 0, Range::closed(0, 1e12));
    c.output.dump_pad = static_cast<int>(std::to_string(c.steps).size());  // dump.<step> sorts in time order
    c.output.vtk_every = out->get_int_or("vtk_every", 0, Range::closed(0, 1e12));
    c.output.vtk_pieces = static_cast<int>(out->get_int_or("vtk_pieces", 1, Range::closed(1, 4096)));
    c.output.checkpoint_every = out->get_int_or("checkpoint_every", 0, Range::closed(0, 1e12));
  }

  root.derive("r0", law.r0);
  root.derive("atoms_per_particle", law.atoms_per_particle);
  root.derive("particle_energy", law.particle_energy);
  root.derive("bond_energy", law.bond_energy);
  root.derive("f", law.f);
  root.derive("G", law.G);
  root.derive("H", law.H);
  root.derive("particle_mass", law.particle_mass);
  root.derive("stiffness", law.stiffness);
  root.derive("youngs_eq15", law.youngs_eq15());
  root.derive("youngs_lattice_001", law.youngs_lattice_001());
  root.derive("poisson_lattice_001", law.poisson_lattice_001());
  root.derive("stable_dt", stable);
  root.derive("dt", c.dt);
  root.derive("steps", c.steps);
  if (c.langevin) root.derive("langevin_friction", c.langevin->friction);
  return c;
}

}  // namespace shockfield::macroparticle
