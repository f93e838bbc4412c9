#pragma once
// Potentials by name, from the [potential] table of a case file:
//
//   [potential]                       # EAM: one LAMMPS potential file
//   style = "eam/alloy"               # "eam" (funcfl), "eam/alloy" (setfl), "eam/fs", "adp",
//                                     # "lj/cut", "table"
//   file = "CuNi.eam.alloy"           # relative to the case file's folder, then
//                                     # $LAMMPS_POTENTIALS, /usr/share/lammps/potentials
//   elements = ["Cu", "Ni"]           # eam/alloy, eam/fs, adp: element of atom types 1..n
//                                     # (LAMMPS `pair_coeff * * CuNi.eam.alloy Cu Ni`)
//
//   [potential]                       # Lennard-Jones
//   style = "lj/cut"
//   cutoff = 8.5                      # Å, global (pair_style lj/cut 8.5)
//   epsilon = 0.0104                  # eV, all pairs (pair_coeff * * ε σ); optional when every
//   sigma = 3.4                       # Å   like pair is given below
//   shift = true                      # pair_modify shift yes (default false)
//   [[potential.pair]]                # per type pair (pair_coeff i j ε σ [cutoff]);
//   types = [1, 2]                    # unset unlike pairs mix geometrically
//   epsilon = 0.02
//   sigma = 3.0
//   cutoff = 7.0                      # optional, default the global cutoff
//
//   [potential]                       # tabulated pair potential (LAMMPS pair_style table)
//   style = "table"
//   interpolation = "linear"          # or "spline" (pair_style table linear 1000)
//   points = 1000                     # N of the inner table, >= 2
//   file = "pair.table"               # default file of every pair; relative as for EAM files
//   keyword = "LJ"                    # optional: every pair (pair_coeff * * pair.table LJ)
//   cutoff = 8.0                      # optional, Å; default the section's last distance
//   [[potential.pair]]                # pair_coeff i j [file] keyword [cutoff]; no mixing:
//   types = [1, 2]                    # every type pair needs a table
//   keyword = "LJ12"
//
// Every value is read through Config, so a mistake names the case file, the key and its line.
// The MD driver calls
//   auto potential = make_potential(root.table("potential"), case_file.parent_path(), ntypes);
// The styles are listed explicitly in registry.cpp (no static registration).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::md::potentials {

/// The folder searched for potential files after the case file's folder (Debian `lammps`).
inline const std::filesystem::path lammps_potential_dir = "/usr/share/lammps/potentials";

/// Builds the potential described by `table` for atoms of `ntypes` types (1..ntypes in files).
std::unique_ptr<Potential> make_potential(const Config& table, const std::filesystem::path& case_dir,
                                          int ntypes);

/// The style names make_potential() accepts.
std::vector<std::string> potential_styles();

/// The mass the potential file gives atom type t (0-based), if the potential has masses (EAM, ADP).
std::optional<double> potential_type_mass(const Potential& potential, int t);
/// The element the potential file names for atom type t (0-based): eam/alloy, eam/fs, adp files.
std::optional<std::string> potential_type_element(const Potential& potential, int t);

/// The file named by string `key` of `table`: as given if absolute, else case_dir/name; else, as
/// LAMMPS does (utils::get_potential_file_path), in the folder of the environment variable
/// LAMMPS_POTENTIALS when it is set; else in lammps_potential_dir. (LAMMPS looks there for the
/// file's name without its folders, also for an absolute name; here a relative name is looked up
/// as given.) Fails on `key` listing the places it looked when none exists. Read through Config::get_input_file, so the file
/// reaches the run's provenance.
std::filesystem::path find_potential_file(const Config& table, std::string_view key,
                                          const std::filesystem::path& case_dir);

}  // namespace shockfield::md::potentials
