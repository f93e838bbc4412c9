#pragma once
// The MD crystal the atom-to-continuum bridges measure (`bridge elastic`, `bridge
// eam-to-macroparticle`): an EAM potential file, the crystal, its starting lattice constant; the
// crystal relaxed to zero pressure at 0 K and strained (md/elastic_constants.hpp, the LAMMPS
// ELASTIC procedure) gives a0, the cohesive energy and C11, C12, C44.
#include <CLI/CLI.hpp>
#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/md/elastic_constants.hpp"

namespace shockfield::app {

struct CrystalOptions {
  std::optional<std::filesystem::path> potential;
  std::string style = "eam", element = "Cu", lattice = "fcc";
  std::optional<double> a0, mass;
  int repeat = 4;
};

/// --potential, --style, --element, --lattice, --a0, --mass, --repeat.
void add_crystal_options(CLI::App& cmd, CrystalOptions& o);

struct MeasuredCrystal {
  md::CubicElasticConstants c;      ///< GPa, Å, eV/atom
  double mass = 0;                  ///< amu
  std::filesystem::path source;     ///< the potential (or constants) file
  toml::table details;              ///< how they were obtained, for [provenance]
};

/// Relaxes and strains the crystal of `o` (needs --potential and --a0; the mass from the potential
/// file unless --mass). `command` names the bridge in messages.
MeasuredCrystal measure_crystal(const CrystalOptions& o, const std::string& command);

/// Density of the relaxed crystal, kg/m³.
double crystal_density(const CrystalOptions& o, const MeasuredCrystal& m);

/// The bridge's [provenance] entry (command, date, version) with the crystal's source file and its
/// SHA-256 as `inputs`; the caller adds its `fit` (starting from `m.details`).
toml::table crystal_provenance_entry(const MeasuredCrystal& m, const std::vector<std::string>& command_line);

}  // namespace shockfield::app
