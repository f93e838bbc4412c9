#include "shockfield/app/bridge_md_crystal.hpp"

#include <fmt/format.h>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/sha256.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/materials/material_file.hpp"
#include "shockfield/md/lattice.hpp"
#include "shockfield/md/potentials/registry.hpp"

namespace shockfield::app {

namespace fs = std::filesystem;

void add_crystal_options(CLI::App& cmd, CrystalOptions& o) {
  cmd.add_option("--potential", o.potential, "EAM potential file (then the case folder, /usr/share/lammps/potentials)");
  cmd.add_option("--style", o.style, "Potential style")->check(CLI::IsMember({"eam", "eam/alloy", "eam/fs"}))->capture_default_str();
  cmd.add_option("--element", o.element, "Element (eam/alloy, eam/fs)")->capture_default_str();
  cmd.add_option("--lattice", o.lattice, "Cubic lattice")->check(CLI::IsMember({"sc", "bcc", "fcc", "diamond"}))->capture_default_str();
  cmd.add_option("--a0", o.a0, "Starting lattice constant, A (relaxed to zero pressure)")->check(CLI::PositiveNumber);
  cmd.add_option("--mass", o.mass, "Atomic mass, amu (default: the potential file's)")->check(CLI::Range(1e-3, 1e4));
  cmd.add_option("--repeat", o.repeat, "Periodic repeats of the cell along each axis")->check(CLI::Range(2, 20))->capture_default_str();
}

MeasuredCrystal measure_crystal(const CrystalOptions& o, const std::string& command) {
  if (!o.a0) throw InputError(fmt::format("{} --potential: give --a0, the starting lattice constant (Å)", command));
  const std::string elements = o.style == "eam" ? "" : fmt::format("elements = [\"{}\"]\n", o.element);
  const Config table = Config::parse(fmt::format("style = \"{}\"\nfile = \"{}\"\n{}", o.style, o.potential->string(), elements),
                                     "--potential");
  const md::PotentialFactory make = [&] { return md::potentials::make_potential(table, fs::current_path(), 1); };
  MeasuredCrystal m;
  const std::unique_ptr<md::Potential> first = make();
  m.source = table.input_files().front();
  const std::optional<double> file_mass = md::potentials::potential_type_mass(*first, 0);
  if (!o.mass && !file_mass) throw InputError(fmt::format("{}: the potential gives no mass: give --mass (amu)", m.source.string()));
  m.mass = o.mass.value_or(file_mass.value_or(0.0));
  md::CubicCrystal crystal;
  crystal.lattice.style = md::parse_lattice_style(o.lattice, "--lattice");
  crystal.lattice.a0 = *o.a0;
  crystal.mass = {m.mass};
  crystal.type_names = {o.element};
  md::ElasticSettings settings;
  settings.repeat = {o.repeat, o.repeat, o.repeat};
  m.c = md::cubic_elastic_constants(crystal, make, settings);
  m.details = toml::table{{"procedure", "zero-temperature strain-stress central differences (LAMMPS ELASTIC); "
                                        "checked against LAMMPS to 1e-8 (tests/validation/test_md_elastic.cpp)"},
                          {"strain", settings.strain},
                          {"repeat", o.repeat},
                          {"relaxation_iterations", m.c.relaxation.iterations},
                          {"cohesive_energy_eV", m.c.cohesive_energy}};
  return m;
}

double crystal_density(const CrystalOptions& o, const MeasuredCrystal& m) {
  md::LatticeSpec spec;
  spec.style = md::parse_lattice_style(o.lattice, "--lattice");
  spec.a0 = m.c.a0;
  const md::Lattice lattice(spec);
  return lattice.basis_size() * m.mass * units::metal::amu_per_A3_to_g_per_cc / (m.c.a0 * m.c.a0 * m.c.a0) * 1e3;
}

toml::table crystal_provenance_entry(const MeasuredCrystal& m, const std::vector<std::string>& command_line) {
  toml::table entry = materials::bridge_provenance_entry(command_line);
  toml::array inputs;
  inputs.push_back(toml::table{{"file", m.source.string()}, {"sha256", sha256_file_hex(m.source)}});
  entry.insert("inputs", inputs);
  return entry;
}

}  // namespace shockfield::app
