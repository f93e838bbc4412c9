#pragma once
// Readers for the three DYNAMO/LAMMPS EAM potential file formats, with the record semantics of
// LAMMPS 29 Sep 2021 (PotentialFileReader: text after '#' on a data line is ignored; a header
// record is one line holding at least the needed words; a table of n values may span lines and
// the rest of its last line is dropped). Values are kept as tabulated, 0-based (LAMMPS keeps
// them 1-based); tabulation onto the common grid and splines are in eam_tables.hpp.
//
//   funcfl (pair_style eam, *.eam), pair_eam.cpp read_file():
//     line 1 comment; line 2 "Z mass ..."; line 3 "Nrho drho Nr dr cutoff";
//     F(rho) [Nrho values], Z(r) [Nr], rho(r) [Nr]        (Z in units of the electron charge)
//   setfl (pair_style eam/alloy, *.eam.alloy), pair_eam_alloy.cpp read_file():
//     lines 1-3 comments; line 4 "N el_1 ... el_N"; line 5 "Nrho drho Nr dr cutoff";
//     per element: "Z mass a lattice", F(rho) [Nrho], rho(r) [Nr];
//     then r*phi(r) [Nr] for every element pair i >= j, in the order (0,0) (1,0) (1,1) (2,0) ...
//   Finnis-Sinclair (pair_style eam/fs, *.eam.fs), pair_eam_fs.cpp read_file(): as setfl but each
//     element block holds N density functions rho_{i,j}(r), j = 0..N-1 (density at an atom of
//     element j due to a neighbour of element i).
//   ADP (pair_style adp, *.adp; LAMMPS doc page pair_adp, "extended DYNAMO setfl format"): a setfl
//     file followed by the dipole functions u_ij(r) [Nr] and then the quadrupole functions
//     w_ij(r) [Nr], each for every element pair i >= j in the order of r*phi; u and w are
//     tabulated as they are (not multiplied by r).
//
// Numbers may use Fortran exponents ("1.0D-3", "2.5d+01"): LAMMPS 2021 rejects them
// (utils::is_double); we accept them because DYNAMO tools write them. Every malformed or
// truncated file is an InputError "file:line: expected ...".
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::md::potentials {

/// The radial grids shared by every table of one file: rho_k = k·drho, r_k = k·dr (k from 0).
struct EamGrid {
  int nrho = 0;
  double drho = 0;
  int nr = 0;
  double dr = 0;
  double cut = 0;  ///< cutoff, Å
};

/// One single-element funcfl file.
struct FuncflFile {
  std::string path;
  double mass = 0;             ///< amu
  EamGrid grid;
  std::vector<double> frho;    ///< F(rho), eV, nrho values
  std::vector<double> zr;      ///< effective charge Z(r), nr values
  std::vector<double> rhor;    ///< rho(r), nr values
};

/// One multi-element setfl or Finnis-Sinclair file.
struct SetflFile {
  std::string path;
  bool finnis_sinclair = false;
  std::vector<std::string> elements;
  std::vector<double> mass;                ///< per element, amu
  EamGrid grid;
  std::vector<std::vector<double>> frho;   ///< [element] F(rho), eV
  /// setfl: [element] rho(r); fs: [i * N + j] rho_{i,j}(r) as stored in the file.
  std::vector<std::vector<double>> rhor;
  std::vector<std::vector<double>> z2r;    ///< [i*(i+1)/2 + j], i >= j: r*phi_{ij}(r), eV·Å

  int element_index(const std::string& name) const;  ///< -1 when absent
};

/// One ADP file: its setfl part and the angular tables, indexed like SetflFile::z2r.
struct AdpFile {
  SetflFile setfl;
  std::vector<std::vector<double>> u2r;  ///< [i*(i+1)/2 + j], i >= j: u_ij(r), eV/Å
  std::vector<std::vector<double>> w2r;  ///< [i*(i+1)/2 + j], i >= j: w_ij(r), eV/Å²
};

FuncflFile read_funcfl(const std::filesystem::path& file);
SetflFile read_setfl(const std::filesystem::path& file, bool finnis_sinclair);
AdpFile read_adp(const std::filesystem::path& file);

}  // namespace shockfield::md::potentials
