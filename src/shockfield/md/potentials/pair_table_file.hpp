#pragma once
// Reader for one section of a LAMMPS `pair_style table` file (LAMMPS 29 Sep 2021,
// pair_table.cpp read_table() and param_extract()):
//
//   # comments and blank lines anywhere
//   KEYWORD                                   first word of the section's first line
//   N n [R rlo rhi | RSQ rlo rhi] [FPRIME fplo fphi]
//                                             (a blank line)
//   1 r_1 e_1 f_1                             n lines "index r energy force", r in Å, energy in eV,
//   ...                                       force −dE/dr in eV/Å
//
// With `R` the distances are recomputed as r_i = rlo + (rhi − rlo)·i/(n − 1), with `RSQ` as
// r_i = √(rlo² + (rhi² − rlo²)·i/(n − 1)) (i from 0), whatever the file's second column says
// (LAMMPS warns when they differ by more than 1e-6; so do we not, the column is read and
// ignored). `FPRIME` gives the derivative of the force at the first and last point for the spline
// of the force; without it the spline uses one-sided differences. `BITMAP` tables are refused.
// Stricter than LAMMPS, which warns and goes on: an incomplete or non-numeric data line, a
// non-finite value, distances not strictly increasing or not positive are errors, each an
// InputError "file:line: expected ...".
#include <filesystem>
#include <string>
#include <vector>

namespace shockfield::md::potentials {

struct PairTableSection {
  enum class Spacing { file, r, rsq };  ///< distances as given, or recomputed (`R`, `RSQ`)
  std::string path;
  std::string keyword;
  Spacing spacing = Spacing::file;
  double rlo = 0, rhi = 0;              ///< `R`/`RSQ` bounds, Å
  bool has_fprime = false;
  double fplo = 0, fphi = 0;            ///< `FPRIME`: dF/dr at the first and last point, eV/Å²
  std::vector<double> r, e, f;          ///< n distances (Å), energies (eV), forces (eV/Å)

  double first_r() const { return spacing == Spacing::file ? r.front() : rlo; }
  double last_r() const { return spacing == Spacing::file ? r.back() : rhi; }
};

/// Reads the section `keyword` of `file`; InputError naming the file and line on any defect, and
/// the sections present when `keyword` is not one of them.
PairTableSection read_pair_table(const std::filesystem::path& file, const std::string& keyword);

}  // namespace shockfield::md::potentials
