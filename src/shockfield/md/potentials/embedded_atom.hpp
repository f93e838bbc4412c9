#pragma once
// What the embedded-atom family (eam, eam/alloy, eam/fs, adp) shares beyond the force loop: the
// tables read from one potential file, the element each atom type is mapped to, and the masses
// the file gives (LAMMPS: these potentials set the masses; run_prepare.cpp applies them).
#include <string>
#include <vector>

#include "shockfield/md/potential.hpp"
#include "shockfield/md/potentials/eam_tables.hpp"

namespace shockfield::md::potentials {

/// Spline rows packed per ordered type pair (ti, tj) and grid interval m, `stride` doubles each,
/// so that one pair's look-ups read one or two cache lines (like LAMMPS's OPT package).
struct PackedPairRows {
  std::vector<double> data;
  std::size_t stride = 0;
  int nr = 0, ntypes = 0;

  PackedPairRows() = default;
  /// fill(ti, tj, m, row) writes the `stride` doubles of row m of type pair (ti, tj).
  template <class Fill>
  PackedPairRows(const EamTables& t, std::size_t row_stride, Fill fill)
      : data(static_cast<std::size_t>(t.ntypes * t.ntypes * t.nr) * row_stride, 0.0),
        stride(row_stride), nr(t.nr), ntypes(t.ntypes) {
    for (int ti = 0; ti < ntypes; ++ti)
      for (int tj = 0; tj < ntypes; ++tj)
        for (int m = 0; m < nr; ++m) fill(ti, tj, static_cast<std::size_t>(m), row(ti, tj, static_cast<std::size_t>(m)));
  }
  double* row(int ti, int tj, std::size_t m) {
    return data.data() + (static_cast<std::size_t>(ti * ntypes + tj) * static_cast<std::size_t>(nr) + m) * stride;
  }
};

/// The packed row a pair kernel reads for atoms i, j at distance r (LAMMPS's table position).
struct PairRowLookup {
  const double* rows;
  const int* type;
  double rdr;
  int nr, ntypes;
  std::size_t stride;
  PairRowLookup(const PackedPairRows& packed, const int* atom_type, const EamTables& t)
      : rows(packed.data.data()), type(atom_type), rdr(1.0 / t.dr), nr(t.nr), ntypes(t.ntypes),
        stride(packed.stride) {}
  /// The row of pair (i, j) at r, and the fraction p within its interval.
  const double* at(int i, int j, double r, double& p) const {
    const auto point = table_point(r, rdr, nr);
    p = point.p;
    const auto pair = static_cast<std::size_t>(type[i] * ntypes + type[j]);
    return rows + (pair * static_cast<std::size_t>(nr) + point.row) * stride;
  }
};

/// The EAM part of a packed row. Density row (8 doubles): [ρ_{j→i} c3..c6, ρ_{i→j} c3..c6];
/// force row (13 doubles): [ρ'_{i→j} c0..c2, ρ'_{j→i} c0..c2, rφ c0..c6] for types (ti, tj).
void fill_eam_density_row(const EamTables& t, int ti, int tj, std::size_t m, double* row);
void fill_eam_force_row(const EamTables& t, int ti, int tj, std::size_t m, double* row);

/// The EAM pair terms from a force row (layout above) at fraction p, r = |r_ij|, with the
/// embedding slopes F'_i, F'_j: returns the central force factor
/// −(F'_i ρ'_{j→i} + F'_j ρ'_{i→j} + φ')/r (force on i = r_ij times it) and sets φ.
inline double eam_pair_force(const double* c, double p, double r, double fp_i, double fp_j, double& phi) {
  const double rhoip = spline_slope(c, p);      // d/dr density at j due to i
  const double rhojp = spline_slope(c + 3, p);  // d/dr density at i due to j
  const double z2p = spline_slope(c + 6, p);
  const double z2 = spline_value(c + 9, p);
  const double recip = 1.0 / r;
  phi = z2 * recip;
  const double phip = z2p * recip - phi * recip;
  return -(fp_i * rhojp + fp_j * rhoip + phip) * recip;
}

class EmbeddedAtomPotential : public Potential {
 public:
  /// `type_names[t]` names the element of type t ("" when the file does not name it), checked
  /// against the atoms' type names.
  EmbeddedAtomPotential(std::string style, EamTables tables, std::vector<std::string> type_names)
      : style_(std::move(style)), tables_(std::move(tables)), type_names_(std::move(type_names)) {}

  std::string style() const override { return style_; }
  double cutoff() const override { return tables_.cut; }
  void check_types(const Atoms& atoms) const override;

  const EamTables& tables() const { return tables_; }
  /// The mass of atom type t (0-based) given by the potential file, amu.
  double type_mass(int t) const { return tables_.type_mass[static_cast<std::size_t>(t)]; }
  /// The element of each atom type named by the potential file ("" where it names none).
  const std::vector<std::string>& type_names() const { return type_names_; }

 private:
  std::string style_;
  EamTables tables_;
  std::vector<std::string> type_names_;
};

}  // namespace shockfield::md::potentials
