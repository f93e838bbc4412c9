#pragma once
// EAM tables on one common grid with LAMMPS's cubic splines, exactly as LAMMPS 29 Sep 2021 builds
// them (src/MANYBODY/pair_eam.cpp, pair_eam_alloy.cpp, pair_eam_fs.cpp):
//   file2array()   funcfl: every file's F(rho), rho(r), Z(r) is resampled onto the common grid
//                  (largest dr and drho of the files, nr = rmax/dr + 0.5, nrho likewise) by
//                  4-point Lagrange interpolation, even for a single file, and the pair term is
//                  r*phi_ij = 27.2*0.529 * Z_i(r) Z_j(r) (Hartree·Bohr → eV·Å);
//                  setfl/fs: the file's tables are copied as they are.
//   array2spline() each table becomes 7 coefficients per grid point (interpolate()): with
//                  p in [0,1] the fraction of the interval, value = ((c3 p + c4) p + c5) p + c6
//                  and derivative = (c0 p + c1) p + c2 (already divided by the grid step).
// Table indices follow LAMMPS: m is the 1-based grid index LAMMPS computes, entry m-1 here.
#include <algorithm>
#include <array>
#include <vector>

#include "shockfield/md/potentials/eam_file.hpp"

namespace shockfield::md::potentials {

using Spline7 = std::array<double, 7>;
using SplineTable = std::vector<Spline7>;

/// LAMMPS PairEAM::interpolate(): spline coefficients of the n values f on a grid of step delta.
SplineTable spline_coefficients(const std::vector<double>& f, double delta);

struct EamTables {
  int nrho = 0, nr = 0;
  double drho = 0, dr = 0;
  double rhomax = 0;  ///< largest tabulated density; F is extended linearly beyond it
  double cut = 0;     ///< cutoff, Å

  std::vector<SplineTable> frho;  ///< F(rho) per table
  std::vector<SplineTable> rhor;  ///< rho(r) per table
  std::vector<SplineTable> z2r;   ///< r*phi(r) per table

  int ntypes = 0;
  std::vector<int> type2frho;  ///< [type]
  /// [i * ntypes + j]: the table of the density an atom of type j receives from a neighbour of
  /// type i (LAMMPS type2rhor[i][j]; rho_i += rhor[type2rhor[j][i]](r_ij)).
  std::vector<int> type2rhor;
  std::vector<int> type2z2r;   ///< [i * ntypes + j], symmetric
  std::vector<double> type_mass;  ///< [type], amu, from the file

  int rhor_index(int i, int j) const { return type2rhor[static_cast<std::size_t>(i * ntypes + j)]; }
  int z2r_index(int i, int j) const { return type2z2r[static_cast<std::size_t>(i * ntypes + j)]; }
};

// ---- Look-ups with LAMMPS's arithmetic (PairEAM::compute(), the same in PairADP::compute()) ----

/// LAMMPS's m = max(1, min(int(p), last)) with p clamped before the cast, so that a huge or NaN
/// p (a NaN position, a tiny grid step) gives a valid row instead of an overflowing cast.
inline int table_interval(double p, int last) {
  if (!(p >= 1.0)) return 1;
  return p < last ? static_cast<int>(p) : last;
}

/// A table position: 0-based row (LAMMPS's 1-based interval m, minus 1) and fraction p in [0, 1].
struct TablePoint {
  std::size_t row;
  double p;
};
/// p = x/dx + 1, m = table_interval(p, n - 1), p -= m, p <= 1 (x = r with 1/dr, or ρ with 1/dρ).
inline TablePoint table_point(double x, double inverse_step, int n) {
  double p = x * inverse_step + 1.0;
  const int m = table_interval(p, n - 1);
  p -= m;
  p = std::min(p, 1.0);
  return {static_cast<std::size_t>(m - 1), p};
}

/// Spline value ((c3 p + c4) p + c5) p + c6 from c = &coefficient 3, and derivative
/// (c0 p + c1) p + c2 from c = &coefficient 0.
inline double spline_value(const double* c, double p) { return ((c[0] * p + c[1]) * p + c[2]) * p + c[3]; }
inline double spline_slope(const double* c, double p) { return (c[0] * p + c[1]) * p + c[2]; }

/// F(ρ) and F'(ρ) of atom type `type`; beyond the table (ρ > rhomax) the energy is extended
/// linearly, F = F(ρmax⁻ spline) + F'·(ρ − ρmax), as LAMMPS 29 Sep 2021 does for eam* and adp.
struct Embedding {
  double energy;  ///< F, eV
  double slope;   ///< F', eV per density unit
};
inline Embedding embedding(const EamTables& t, int type, double rho) {
  const auto [row, p] = table_point(rho, 1.0 / t.drho, t.nrho);
  const auto& c = t.frho[static_cast<std::size_t>(t.type2frho[static_cast<std::size_t>(type)])][row];
  const double slope = spline_slope(c.data(), p);
  double energy = spline_value(c.data() + 3, p);
  if (rho > t.rhomax) energy += slope * (rho - t.rhomax);
  return {energy, slope};
}

/// pair_style eam: `type_file[t]` is the index into `files` of atom type t (0-based).
EamTables tabulate_funcfl(const std::vector<FuncflFile>& files, const std::vector<int>& type_file);
/// pair_style eam/alloy and eam/fs: `type_element[t]` is the file element of atom type t.
EamTables tabulate_setfl(const SetflFile& file, const std::vector<int>& type_element);

/// pair_style adp: the setfl tables plus splines of u(r) and w(r) on the r grid (the same
/// interpolate() as rho(r) and r*phi(r)), indexed per type pair by z2r_index().
struct AdpTables {
  EamTables eam;
  std::vector<SplineTable> u2r;  ///< dipole function u(r), eV/Å
  std::vector<SplineTable> w2r;  ///< quadrupole function w(r), eV/Å²
};
AdpTables tabulate_adp(const AdpFile& file, const std::vector<int>& type_element);

}  // namespace shockfield::md::potentials
