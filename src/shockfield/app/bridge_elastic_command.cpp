// `shockfield bridge elastic`: the zero-temperature cubic elastic constants of an EAM crystal
// (md/elastic_constants.hpp, the LAMMPS ELASTIC strain–stress procedure) → a material file with
// the cubic C11, C12, C44 for the crystal law of peridynamics (Liu et al. 2025, eqs. 31–32) and
// the isotropic K, G of a Voigt, Reuss or Hill average for MPM (Hill 1952), with the density of
// the same relaxed crystal and the classical (Dulong–Petit) heat capacity 3k_B/m that the MD
// crystal has. Or the constants come from a file of an earlier run (--constants).
#include <fmt/format.h>

#include <cstdio>

#include "shockfield/app/bridge_md_crystal.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::app {
namespace {

namespace fs = std::filesystem;
namespace mu = units::metal;

struct ElasticOptions {
  CrystalOptions crystal;
  std::optional<fs::path> constants;
  std::string average = "hill";
  BridgeOutput out;
};

MeasuredCrystal from_constants(const ElasticOptions& o) {
  const Config t = Config::load(*o.constants);
  MeasuredCrystal m;
  m.source = fs::absolute(*o.constants);
  // Bounds a crystal can have (and the products below stay finite): lattice constants of 0.5-50 Å
  // (the elements' are 2.5-6.5 Å), elastic constants within 10 TPa (diamond's C11 is 1.08 TPa).
  m.c.a0 = t.get_double("a0_A", Range::closed(0.5, 50.0));
  m.c.c11 = t.get_double("c11_GPa", {0.0, 1e4, true, false});
  m.c.c12 = t.get_double("c12_GPa", Range::closed(-1e4, 1e4));
  m.c.c44 = t.get_double("c44_GPa", {0.0, 1e4, true, false});
  if (t.has("cohesive_energy_eV")) m.c.cohesive_energy = t.get_double("cohesive_energy_eV");
  if (t.has("strain")) t.get_double("strain", Range::positive());
  t.check_unknown_keys();
  if (!o.crystal.mass)
    throw InputError(fmt::format("bridge elastic --constants {}: give --mass (amu) for the density", m.source.string()));
  m.mass = *o.crystal.mass;
  m.details = toml::table{{"procedure", "read from the constants file"}};
  return m;
}

void run(const ElasticOptions& o, const std::vector<std::string>& command_line) {
  if (o.crystal.potential.has_value() == o.constants.has_value())
    throw InputError("bridge elastic: give either --potential (run the MD elastic constants) or --constants (read them)");
  const MeasuredCrystal m = o.crystal.potential ? measure_crystal(o.crystal, "bridge elastic") : from_constants(o);
  const double c11 = m.c.c11 * 1e9, c12 = m.c.c12 * 1e9, c44 = m.c.c44 * 1e9;
  if (!(c11 > std::abs(c12)) || !(c11 + 2.0 * c12 > 0.0) || !(c44 > 0.0))
    throw InputError(fmt::format("{}: C11 = {} GPa, C12 = {} GPa, C44 = {} GPa is not a stable cubic crystal",
                                 m.source.string(), m.c.c11, m.c.c12, m.c.c44));
  const double density = crystal_density(o.crystal, m);
  const double heat_capacity = 3.0 * mu::boltz * mu::eV_to_J / (m.mass * mu::amu_to_kg);  // Dulong–Petit
  const materials::IsotropicModuli iso = materials::cubic_average(c11, c12, c44, o.average);
  const std::map<std::string, double> values{
      {"elasticity.density", density}, {"elasticity.temperature", 0.0}, {"elasticity.c11", c11},
      {"elasticity.c12", c12},         {"elasticity.c44", c44},         {"elasticity.bulk", iso.bulk},
      {"elasticity.shear", iso.shear}, {"thermal.heat_capacity", heat_capacity}};
  toml::table entry = crystal_provenance_entry(m, command_line);
  toml::table fit = m.details;
  fit.insert("lattice", o.crystal.lattice);
  fit.insert("a0_A", m.c.a0);
  fit.insert("mass_amu", m.mass);
  for (const char* avg : {"voigt", "reuss", "hill"}) {
    const materials::IsotropicModuli a = materials::cubic_average(c11, c12, c44, avg);
    fit.insert(fmt::format("shear_{}_Pa", avg), a.shear);
  }
  fit.insert("zener_anisotropy", 2.0 * c44 / (c11 - c12));
  entry.insert("fit", fit);
  const std::map<std::string, std::string> notes{
      {"elasticity.note", fmt::format("zero-temperature MD constants of {} ({}, a0 = {} A); bulk and shear by the {} "
                                      "average", m.source.filename().string(), o.crystal.lattice, m.c.a0, o.average)},
      {"elasticity.average", o.average},
      {"thermal.note", "heat_capacity = 3 k_B / m: the classical (Dulong-Petit) value of the MD crystal"}};
  materials::write_bridged_material(o.out.file, o.out.update, o.out.name, "elastic", values, notes, entry);
  std::printf("%s, a0 = %.6f A, rho = %.1f kg/m^3\n  C11 = %.2f  C12 = %.2f  C44 = %.2f GPa (Zener A = %.3f)\n"
              "  %s: K = %.2f GPa, G = %.2f GPa\n  c_v = %.1f J/(kg K) (3 k_B/m)\n-> %s\n",
              m.source.string().c_str(), m.c.a0, density, m.c.c11, m.c.c12, m.c.c44, 2.0 * c44 / (c11 - c12),
              o.average.c_str(), iso.bulk * 1e-9, iso.shear * 1e-9, heat_capacity, o.out.file.string().c_str());
}

}  // namespace

void add_bridge_elastic_command(CLI::App& bridge, const std::vector<std::string>& command_line) {
  auto o = std::make_shared<ElasticOptions>();
  CLI::App* cmd = bridge.add_subcommand(
      "elastic",
      "MD elastic constants -> cubic elasticity (PD crystal law) and isotropic K, G (MPM). With\n"
      "--potential, relaxes the crystal to zero pressure and strains it (the LAMMPS ELASTIC\n"
      "procedure at 0 K, md/elastic_constants.hpp); with --constants, reads a0_A, c11_GPa, c12_GPa,\n"
      "c44_GPa from a TOML file. Writes [elasticity] density (of the relaxed crystal), temperature\n"
      "(0 K), c11, c12, c44, bulk, shear (--average voigt|reuss|hill) and [thermal] heat_capacity =\n"
      "3 k_B/m, with the potential's SHA-256 in [provenance.elastic].\n"
      "Example: shockfield bridge elastic --potential Cu_u3.eam --a0 3.615 -o cu_md.toml --update");
  add_crystal_options(*cmd, o->crystal);
  cmd->add_option("--constants", o->constants, "TOML with a0_A, c11_GPa, c12_GPa, c44_GPa instead of running MD")
      ->check(CLI::ExistingFile);
  cmd->add_option("--average", o->average, "Isotropic average for K, G")
      ->check(CLI::IsMember({"voigt", "reuss", "hill"}))
      ->capture_default_str();
  add_bridge_output_options(*cmd, o->out, "[elasticity] and [thermal]");
  cmd->callback([o, command_line] { run(*o, command_line); });
}

}  // namespace shockfield::app
