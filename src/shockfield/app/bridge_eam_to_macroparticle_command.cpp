// `shockfield bridge eam-to-macroparticle`: the atoms' numbers of the macroscopic particle model
// (Saitoh et al., eqs 10–15) from an EAM potential. The MD crystal relaxed to zero pressure at
// 0 K (app/bridge_md_crystal.hpp) gives the cohesive energy e0 and the lattice constant a0 that
// eqs 10–11 take; they are written as the [atoms] table of a material file that a macroparticle
// case reads with `[material] file = ...`. The same crystal's elastic constants are set beside
// the moduli the pair law gives the packing (docs/theory/macroparticle.md): eq 15, the perfect
// packing's [001] modulus (2√2/3)k/r0, and the exponent product pq that would make that modulus
// the EAM crystal's [001] modulus (E ∝ pq at fixed e0, a0).
#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "shockfield/app/bridge_md_crystal.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/macroparticle/parameters.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::app {
namespace {

struct Options {
  CrystalOptions crystal;
  double p = 4, q = 9;
  BridgeOutput out;
};

// Young's modulus for uniaxial stress along [001] of a cubic crystal: (C11 − C12)(C11 + 2C12)/(C11 + C12).
double youngs_001(double c11, double c12) { return (c11 - c12) * (c11 + 2.0 * c12) / (c11 + c12); }

void run(const Options& o, const std::vector<std::string>& command_line) {
  if (!o.crystal.potential) throw InputError("bridge eam-to-macroparticle: give --potential (an EAM file)");
  if (o.crystal.lattice != "fcc")
    throw InputError(fmt::format("bridge eam-to-macroparticle: --lattice {}: the macroscopic particle model (eqs 10-15) "
                                 "is written for fcc atoms", o.crystal.lattice));
  if (!(o.q > o.p) || !(o.p > 0))
    throw InputError(fmt::format("bridge eam-to-macroparticle: --p {} --q {}: the pair law needs q > p > 0 (eq 5)", o.p, o.q));
  const MeasuredCrystal m = measure_crystal(o.crystal, "bridge eam-to-macroparticle");
  const double e0_eV = -m.c.cohesive_energy;
  if (!(e0_eV > 0))
    throw RunError(fmt::format("{}: the relaxed crystal is not bound (E/N = {} eV)", m.source.string(), m.c.cohesive_energy));
  const double e0 = e0_eV * units::si::eV, a0 = m.c.a0 * 1e-10, mass = m.mass * units::si::amu;

  macroparticle::PairLawInput in;
  in.cohesive_energy = e0;
  in.lattice_constant = a0;
  in.atomic_mass = mass;
  in.r0 = 1e-3;  // any particle size: the moduli of eqs 14-15 do not depend on it
  in.p = o.p;
  in.q = o.q;
  const macroparticle::PairLaw law = macroparticle::derive_pair_law(in);
  const double c11 = m.c.c11 * 1e9, c12 = m.c.c12 * 1e9, c44 = m.c.c44 * 1e9;
  const materials::IsotropicModuli hill = materials::cubic_average(c11, c12, c44, "hill");
  const double e_hill = 9.0 * hill.bulk * hill.shear / (3.0 * hill.bulk + hill.shear);
  const double e_md_001 = youngs_001(c11, c12);
  const double pq_match = o.p * o.q * e_md_001 / law.youngs_lattice_001();

  const std::map<std::string, double> values{
      {"atoms.cohesive_energy", e0}, {"atoms.lattice_constant", a0}, {"atoms.atomic_mass", mass}};
  toml::table entry = crystal_provenance_entry(m, command_line);
  toml::table fit = m.details;
  fit.insert_or_assign("cohesive_energy_eV", e0_eV);  // the binding energy, > 0 (the MD's E/N is −e0)
  fit.insert("a0_A", m.c.a0);
  fit.insert("mass_amu", m.mass);
  fit.insert("c11_GPa", m.c.c11);
  fit.insert("c12_GPa", m.c.c12);
  fit.insert("c44_GPa", m.c.c44);
  fit.insert("md_youngs_001_Pa", e_md_001);
  fit.insert("md_youngs_hill_Pa", e_hill);
  fit.insert("p", o.p);
  fit.insert("q", o.q);
  fit.insert("pair_law_youngs_eq15_Pa", law.youngs_eq15());
  fit.insert("pair_law_youngs_001_Pa", law.youngs_lattice_001());
  fit.insert("pq_matching_md_youngs_001", pq_match);
  entry.insert("fit", fit);
  const std::map<std::string, std::string> notes{
      {"atoms.crystal", "fcc"},
      {"atoms.note", fmt::format("zero-temperature MD crystal of {} (fcc, relaxed to zero pressure): e0 = {:.6f} eV, "
                                 "a0 = {:.6f} A, m = {} u", m.source.filename().string(), e0_eV, m.c.a0, m.mass)}};
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "eam_to_macroparticle", values, notes, entry);
  std::printf(
      "%s: fcc a0 = %.6f A, e0 = %.6f eV/atom, m = %g u\n"
      "  MD crystal:  C11 = %.2f  C12 = %.2f  C44 = %.2f GPa; E[001] = %.2f GPa, E (Hill) = %.2f GPa\n"
      "  pair law p = %g, q = %g: E eq 15 = %.2f GPa, perfect packing E[001] = %.2f GPa\n"
      "  pq = %.2f would give the packing the MD crystal's E[001]\n-> %s\n",
      m.source.string().c_str(), m.c.a0, e0_eV, m.mass, m.c.c11, m.c.c12, m.c.c44, e_md_001 * 1e-9, e_hill * 1e-9, o.p,
      o.q, law.youngs_eq15() * 1e-9, law.youngs_lattice_001() * 1e-9, pq_match, o.out.file.string().c_str());
}

}  // namespace

void add_bridge_eam_to_macroparticle_command(CLI::App& bridge, const std::vector<std::string>& command_line) {
  auto o = std::make_shared<Options>();
  CLI::App* cmd = bridge.add_subcommand(
      "eam-to-macroparticle",
      "EAM atoms -> the macroscopic particle model (Saitoh et al., eqs 10-15). Relaxes the fcc\n"
      "crystal of the potential to zero pressure at 0 K and writes [atoms] cohesive_energy (J),\n"
      "lattice_constant (m), atomic_mass (kg), which a macroparticle case takes with\n"
      "[material] file = ... (its own keys win). Prints the crystal's C11, C12, C44, its [001]\n"
      "and Hill Young's moduli beside the pair law's (eq 15 and the perfect packing's [001] modulus\n"
      "for --p, --q) and the exponent product pq that would match the [001] modulus; all are in\n"
      "[provenance.eam_to_macroparticle.fit].\n"
      "Example: shockfield bridge eam-to-macroparticle --potential Cu_u3.eam --a0 3.615 -o cu_atoms.toml");
  add_crystal_options(*cmd, o->crystal);
  cmd->add_option("--p", o->p, "Attraction exponent of the pair law (eq 5), for the moduli printed")->capture_default_str();
  cmd->add_option("--q", o->q, "Repulsion exponent (q > p)")->capture_default_str();
  add_bridge_output_options(*cmd, o->out, "[atoms]");
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
