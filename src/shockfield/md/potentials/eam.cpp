#include "shockfield/md/potentials/eam.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::md::potentials {
namespace {

constexpr std::size_t kDensityStride = 8;
constexpr std::size_t kForceStride = 16;  // 13 used, padded to two cache lines

// LAMMPS's m = max(1, min(int(p), last)) with p clamped before the cast, so that a huge or NaN
// p (a NaN position, a tiny grid step) gives a valid row instead of an overflowing cast.
inline int table_interval(double p, int last) {
  if (!(p >= 1.0)) return 1;
  return p < last ? static_cast<int>(p) : last;
}

// The radial table position of PairEAM::compute(): 1-based interval m and fraction p.
struct RadialPoint {
  std::size_t row;  // m - 1
  double p;
};
inline RadialPoint radial_point(double r, double rdr, int nr) {
  double p = r * rdr + 1.0;
  const int m = table_interval(p, nr - 1);
  p -= m;
  p = std::min(p, 1.0);
  return {static_cast<std::size_t>(m - 1), p};
}

inline double cubic(const double* c, double p) { return ((c[0] * p + c[1]) * p + c[2]) * p + c[3]; }
inline double quadratic(const double* c, double p) { return (c[0] * p + c[1]) * p + c[2]; }

struct DensityKernel {
  const double* rows;
  const int* type;
  const double cutsq, rdr;
  const int nr, ntypes;
  bool operator()(int i, int j, double rsq, double& to_i, double& to_j) const {
    if (!(rsq < cutsq)) return false;  // NaN distances too
    const auto [row, p] = radial_point(std::sqrt(rsq), rdr, nr);
    const auto pair = static_cast<std::size_t>(type[i] * ntypes + type[j]);
    const double* c = rows + (pair * static_cast<std::size_t>(nr) + row) * kDensityStride;
    to_i = cubic(c, p);
    to_j = cubic(c + 4, p);
    return true;
  }
};

struct ForceKernel {
  const double* rows;
  const int* type;
  const double* fp;
  const double cutsq, rdr;
  const int nr, ntypes;
  bool operator()(int i, int j, double rsq, double& fpair, double& energy) const {
    if (!(rsq < cutsq)) return false;  // NaN distances too
    const double r = std::sqrt(rsq);
    const auto [row, p] = radial_point(r, rdr, nr);
    const auto pair = static_cast<std::size_t>(type[i] * ntypes + type[j]);
    const double* c = rows + (pair * static_cast<std::size_t>(nr) + row) * kForceStride;
    const double rhoip = quadratic(c, p);      // d/dr density at j due to i
    const double rhojp = quadratic(c + 3, p);  // d/dr density at i due to j
    const double z2p = quadratic(c + 6, p);
    const double z2 = cubic(c + 9, p);
    const double recip = 1.0 / r;
    const double phi = z2 * recip;
    const double phip = z2p * recip - phi * recip;
    fpair = -(fp[i] * rhojp + fp[j] * rhoip + phip) * recip;
    energy = phi;
    return true;
  }
};

}  // namespace

EamPotential::EamPotential(std::string style, EamTables tables, std::vector<std::string> type_names)
    : style_(std::move(style)), tables_(std::move(tables)), type_names_(std::move(type_names)) {
  const auto nt = static_cast<std::size_t>(tables_.ntypes);
  const auto nr = static_cast<std::size_t>(tables_.nr);
  density_rows_.assign(nt * nt * nr * kDensityStride, 0.0);
  force_rows_.assign(nt * nt * nr * kForceStride, 0.0);
  for (int ti = 0; ti < tables_.ntypes; ++ti) {
    for (int tj = 0; tj < tables_.ntypes; ++tj) {
      const auto& into_j = tables_.rhor[static_cast<std::size_t>(tables_.rhor_index(ti, tj))];
      const auto& into_i = tables_.rhor[static_cast<std::size_t>(tables_.rhor_index(tj, ti))];
      const auto& z2r = tables_.z2r[static_cast<std::size_t>(tables_.z2r_index(ti, tj))];
      const auto pair = static_cast<std::size_t>(ti * tables_.ntypes + tj);
      for (std::size_t m = 0; m < nr; ++m) {
        double* d = &density_rows_[(pair * nr + m) * kDensityStride];
        std::copy(into_i[m].begin() + 3, into_i[m].end(), d);
        std::copy(into_j[m].begin() + 3, into_j[m].end(), d + 4);
        double* f = &force_rows_[(pair * nr + m) * kForceStride];
        std::copy(into_j[m].begin(), into_j[m].begin() + 3, f);
        std::copy(into_i[m].begin(), into_i[m].begin() + 3, f + 3);
        std::copy(z2r[m].begin(), z2r[m].end(), f + 6);
      }
    }
  }
}

void EamPotential::check_types(const Atoms& atoms) const {
  if (atoms.ntypes() != tables_.ntypes)
    throw InputError(fmt::format("pair style {}: the potential maps {} atom types, the atoms have {}",
                                 style_, tables_.ntypes, atoms.ntypes()));
  for (std::size_t t = 0; t < atoms.type_names.size() && t < type_names_.size(); ++t) {
    const auto& have = atoms.type_names[t];
    if (!have.empty() && !type_names_[t].empty() && have != type_names_[t])
      throw InputError(fmt::format("pair style {}: atom type {} is {} but the potential maps it to {}",
                                   style_, t + 1, have, type_names_[t]));
  }
}

void EamPotential::compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) {
  const EamTables& t = tables_;
  const double cutsq = t.cut * t.cut;
  const double rdr = 1.0 / t.dr, rdrho = 1.0 / t.drho;

  rho_.assign(atoms.size(), 0.0);
  accumulate_pair_scalars(atoms, list,
                          DensityKernel{density_rows_.data(), atoms.type.data(), cutsq, rdr, t.nr,
                                        t.ntypes},
                          rho_, scratch_, &accepted_);
  atoms.reverse_sum(rho_);

  // Embedding on owned atoms (PairEAM::compute(), "fp = derivative of embedding energy").
  fp_.assign(atoms.size(), 0.0);
  const int nthreads = omp_get_max_threads();
  std::vector<double> embedding(static_cast<std::size_t>(nthreads), 0.0);
  const auto nlocal = static_cast<std::ptrdiff_t>(atoms.nlocal);
#pragma omp parallel num_threads(nthreads)
  {
    double sum = 0;
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < nlocal; ++i) {
      const double rho = rho_[static_cast<std::size_t>(i)];
      // LAMMPS: p = rho/drho + 1, m = max(1, min(int p, nrho-1)).
      double p = rho * rdrho + 1.0;
      const int m = table_interval(p, t.nrho - 1);
      p -= m;
      p = std::min(p, 1.0);
      const int table = t.type2frho[static_cast<std::size_t>(atoms.type[static_cast<std::size_t>(i)])];
      const auto& c = t.frho[static_cast<std::size_t>(table)][static_cast<std::size_t>(m - 1)];
      const double fpi = quadratic(c.data(), p);
      double phi = cubic(c.data() + 3, p);
      if (rho > t.rhomax) phi += fpi * (rho - t.rhomax);
      fp_[static_cast<std::size_t>(i)] = fpi;
      sum += phi;
      if (out.per_atom) out.energy_atom[static_cast<std::size_t>(i)] += phi;
    }
    embedding[static_cast<std::size_t>(omp_get_thread_num())] = sum;
  }
  for (double e : embedding) out.energy += e;
  atoms.forward_copy(fp_);

  accumulate_pair_forces(atoms, list,
                         ForceKernel{force_rows_.data(), atoms.type.data(), fp_.data(), cutsq, rdr,
                                     t.nr, t.ntypes},
                         out, scratch_, &accepted_);
  rho_.resize(atoms.nlocal);
}

}  // namespace shockfield::md::potentials
