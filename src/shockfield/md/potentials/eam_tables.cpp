#include "shockfield/md/potentials/eam_tables.hpp"

#include <algorithm>

namespace shockfield::md::potentials {
namespace {

// file2array()'s 4-point Lagrange resampling of a table f (step fdelta) onto n points of step
// delta. LAMMPS (1-based f): p = x/fdelta + 1, k = clamp(int(p), 2, nf-2), p -= k, p <= 2,
// value = c1 f[k-1] + c2 f[k] + c3 f[k+1] + c4 f[k+2].
std::vector<double> resample(const std::vector<double>& f, double fdelta, int n, double delta) {
  constexpr double sixth = 1.0 / 6.0;
  const int nf = static_cast<int>(f.size());
  std::vector<double> out(static_cast<std::size_t>(n));
  for (int m = 1; m <= n; ++m) {
    const double x = (m - 1) * delta;
    double p = x / fdelta + 1.0;
    // k = clamp(int(p), 2, nf - 2), clamped before the cast so that no p overflows it.
    const int k = !(p >= 2.0) ? 2 : p < nf - 2 ? static_cast<int>(p) : nf - 2;
    p -= k;
    p = std::min(p, 2.0);
    const double c1 = -sixth * p * (p - 1.0) * (p - 2.0);
    const double c2 = 0.5 * (p * p - 1.0) * (p - 2.0);
    const double c3 = -0.5 * p * (p + 1.0) * (p - 2.0);
    const double c4 = sixth * p * (p * p - 1.0);
    const double* g = f.data() + (k - 2);  // g[0] is LAMMPS's f[k-1]
    out[static_cast<std::size_t>(m - 1)] = c1 * g[0] + c2 * g[1] + c3 * g[2] + c4 * g[3];
  }
  return out;
}

// type2z2r: lower-triangular index of the element pair (row >= column).
int lower_triangle(int a, int b) {
  const int row = std::max(a, b), col = std::min(a, b);
  return row * (row + 1) / 2 + col;
}

void spline_all(EamTables& t, const std::vector<std::vector<double>>& frho,
                const std::vector<std::vector<double>>& rhor,
                const std::vector<std::vector<double>>& z2r) {
  for (const auto& f : frho) t.frho.push_back(spline_coefficients(f, t.drho));
  for (const auto& f : rhor) t.rhor.push_back(spline_coefficients(f, t.dr));
  for (const auto& f : z2r) t.z2r.push_back(spline_coefficients(f, t.dr));
}

}  // namespace

SplineTable spline_coefficients(const std::vector<double>& f, double delta) {
  // PairEAM::interpolate() with 0-based s[k] = LAMMPS spline[k+1]. Slopes (coefficient 5, per
  // grid step): one-sided at the ends, central next to them, 5-point central inside; then the
  // cubic Hermite coefficients 4 and 3 on each interval; the last point is constant.
  const int n = static_cast<int>(f.size());
  SplineTable s(static_cast<std::size_t>(n));
  auto at = [&s](int m) -> Spline7& { return s[static_cast<std::size_t>(m - 1)]; };  // 1-based
  for (int m = 1; m <= n; ++m) at(m)[6] = f[static_cast<std::size_t>(m - 1)];
  at(1)[5] = at(2)[6] - at(1)[6];
  at(2)[5] = 0.5 * (at(3)[6] - at(1)[6]);
  at(n - 1)[5] = 0.5 * (at(n)[6] - at(n - 2)[6]);
  at(n)[5] = at(n)[6] - at(n - 1)[6];
  for (int m = 3; m <= n - 2; ++m)
    at(m)[5] = ((at(m - 2)[6] - at(m + 2)[6]) + 8.0 * (at(m + 1)[6] - at(m - 1)[6])) / 12.0;
  for (int m = 1; m <= n - 1; ++m) {
    at(m)[4] = 3.0 * (at(m + 1)[6] - at(m)[6]) - 2.0 * at(m)[5] - at(m + 1)[5];
    at(m)[3] = at(m)[5] + at(m + 1)[5] - 2.0 * (at(m + 1)[6] - at(m)[6]);
  }
  at(n)[4] = 0.0;
  at(n)[3] = 0.0;
  for (int m = 1; m <= n; ++m) {
    at(m)[2] = at(m)[5] / delta;
    at(m)[1] = 2.0 * at(m)[4] / delta;
    at(m)[0] = 3.0 * at(m)[3] / delta;
  }
  return s;
}

EamTables tabulate_funcfl(const std::vector<FuncflFile>& files, const std::vector<int>& type_file) {
  EamTables t;
  // Common grid: the largest spacings and extents of the files in use; 0.5 for round-off.
  double rmax = 0;
  for (const auto& f : files) {
    t.dr = std::max(t.dr, f.grid.dr);
    t.drho = std::max(t.drho, f.grid.drho);
    rmax = std::max(rmax, (f.grid.nr - 1) * f.grid.dr);
    t.rhomax = std::max(t.rhomax, (f.grid.nrho - 1) * f.grid.drho);
    t.cut = std::max(t.cut, f.grid.cut);  // init_one(): cutmax over the files
  }
  t.nr = static_cast<int>(rmax / t.dr + 0.5);
  t.nrho = static_cast<int>(t.rhomax / t.drho + 0.5);

  std::vector<std::vector<double>> frho, rhor, z2r;
  for (const auto& f : files) {
    frho.push_back(resample(f.frho, f.grid.drho, t.nrho, t.drho));
    rhor.push_back(resample(f.rhor, f.grid.dr, t.nr, t.dr));
  }
  // r*phi for every file pair i >= j from the resampled effective charges.
  constexpr double hartree_bohr = 27.2 * 0.529;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto zi = resample(files[i].zr, files[i].grid.dr, t.nr, t.dr);
    for (std::size_t j = 0; j <= i; ++j) {
      const auto zj = resample(files[j].zr, files[j].grid.dr, t.nr, t.dr);
      std::vector<double> z2(zi.size());
      for (std::size_t m = 0; m < zi.size(); ++m) z2[m] = hartree_bohr * zi[m] * zj[m];
      z2r.push_back(std::move(z2));
    }
  }
  spline_all(t, frho, rhor, z2r);

  t.ntypes = static_cast<int>(type_file.size());
  for (int i = 0; i < t.ntypes; ++i) {
    const int fi = type_file[static_cast<std::size_t>(i)];
    t.type2frho.push_back(fi);
    t.type_mass.push_back(files[static_cast<std::size_t>(fi)].mass);
    for (int j = 0; j < t.ntypes; ++j) {
      t.type2rhor.push_back(fi);  // funcfl: the density depends only on the source atom
      t.type2z2r.push_back(lower_triangle(fi, type_file[static_cast<std::size_t>(j)]));
    }
  }
  return t;
}

EamTables tabulate_setfl(const SetflFile& file, const std::vector<int>& type_element) {
  EamTables t;
  t.nrho = file.grid.nrho;
  t.nr = file.grid.nr;
  t.drho = file.grid.drho;
  t.dr = file.grid.dr;
  t.rhomax = (t.nrho - 1) * t.drho;
  t.cut = file.grid.cut;
  spline_all(t, file.frho, file.rhor, file.z2r);

  const int ne = static_cast<int>(file.elements.size());
  t.ntypes = static_cast<int>(type_element.size());
  for (int i = 0; i < t.ntypes; ++i) {
    const int ei = type_element[static_cast<std::size_t>(i)];
    t.type2frho.push_back(ei);
    t.type_mass.push_back(file.mass[static_cast<std::size_t>(ei)]);
    for (int j = 0; j < t.ntypes; ++j) {
      const int ej = type_element[static_cast<std::size_t>(j)];
      // setfl: rho depends on the source element; fs: on the (source, receiver) pair.
      t.type2rhor.push_back(file.finnis_sinclair ? ei * ne + ej : ei);
      t.type2z2r.push_back(lower_triangle(ei, ej));
    }
  }
  return t;
}

AdpTables tabulate_adp(const AdpFile& file, const std::vector<int>& type_element) {
  AdpTables t{tabulate_setfl(file.setfl, type_element), {}, {}};
  for (const auto& f : file.u2r) t.u2r.push_back(spline_coefficients(f, t.eam.dr));
  for (const auto& f : file.w2r) t.w2r.push_back(spline_coefficients(f, t.eam.dr));
  return t;
}

}  // namespace shockfield::md::potentials
