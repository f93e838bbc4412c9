#include "shockfield/md/potentials/adp.hpp"

#include <algorithm>
#include <cmath>

namespace shockfield::md::potentials {
namespace {

constexpr std::size_t kMomentStride = 16;
constexpr std::size_t kForceStride = 32;  // 27 used, padded to four cache lines

// Indices into AdpAtomTerms::v.
constexpr std::size_t kRho = 0, kFp = 0, kMu = 1, kLambda = 4;

// S d for a symmetric tensor S stored in Voigt order xx yy zz xy xz yz.
inline Vec3 symmetric_times(const double* s, const Vec3& d) {
  return {s[0] * d.x() + s[3] * d.y() + s[4] * d.z(), s[3] * d.x() + s[1] * d.y() + s[5] * d.z(),
          s[4] * d.x() + s[5] * d.y() + s[2] * d.z()};
}

// Rows: the EAM part of embedded_atom.hpp, then u and w (c3..c6 in the moment row; c0..c6 in the
// force row from offset 13 and 20).
void fill_moment_row(const AdpTables& t, int ti, int tj, std::size_t m, double* row) {
  fill_eam_density_row(t.eam, ti, tj, m, row);
  const auto table = static_cast<std::size_t>(t.eam.z2r_index(ti, tj));
  std::copy(t.u2r[table][m].begin() + 3, t.u2r[table][m].end(), row + 8);
  std::copy(t.w2r[table][m].begin() + 3, t.w2r[table][m].end(), row + 12);
}

void fill_force_row(const AdpTables& t, int ti, int tj, std::size_t m, double* row) {
  fill_eam_force_row(t.eam, ti, tj, m, row);
  const auto table = static_cast<std::size_t>(t.eam.z2r_index(ti, tj));
  std::copy(t.u2r[table][m].begin(), t.u2r[table][m].end(), row + 13);
  std::copy(t.w2r[table][m].begin(), t.w2r[table][m].end(), row + 20);
}

struct MomentKernel {
  PairRowLookup rows;
  double cutsq;
  bool operator()(int i, int j, const Vec3& d, double rsq, AdpAtomTerms& to_i, AdpAtomTerms& to_j) const {
    if (!(rsq < cutsq)) return false;  // NaN distances too
    double p;
    const double* c = rows.at(i, j, std::sqrt(rsq), p);
    const double u = spline_value(c + 8, p), w = spline_value(c + 12, p);
    to_i.v[kRho] = spline_value(c, p);
    to_j.v[kRho] = spline_value(c + 4, p);
    for (int a = 0; a < 3; ++a) {
      to_i.v[kMu + a] = u * d[a];   // μ_i += u r_ij
      to_j.v[kMu + a] = -u * d[a];  // μ_j += u r_ji
    }
    const double lambda[6] = {w * d.x() * d.x(), w * d.y() * d.y(), w * d.z() * d.z(),
                              w * d.x() * d.y(), w * d.x() * d.z(), w * d.y() * d.z()};
    std::copy(lambda, lambda + 6, to_i.v.begin() + kLambda);
    std::copy(lambda, lambda + 6, to_j.v.begin() + kLambda);
    return true;
  }
};

struct ForceKernel {
  PairRowLookup rows;
  const AdpAtomTerms* terms;
  double cutsq;
  bool operator()(int i, int j, const Vec3& d, double rsq, Vec3& fij, double& energy) const {
    if (!(rsq < cutsq)) return false;  // NaN distances too
    const double r = std::sqrt(rsq);
    double p;
    const double* c = rows.at(i, j, r, p);
    const double* a = terms[i].v.data();
    const double* b = terms[j].v.data();
    const double central = eam_pair_force(c, p, r, a[kFp], b[kFp], energy);
    const double up = spline_slope(c + 13, p), u = spline_value(c + 16, p);
    const double wp = spline_slope(c + 20, p), w = spline_value(c + 23, p);
    const Vec3 dmu(a[kMu] - b[kMu], a[kMu + 1] - b[kMu + 1], a[kMu + 2] - b[kMu + 2]);
    double dsum[6];
    for (std::size_t k = 0; k < 6; ++k) dsum[k] = a[kLambda + k] + b[kLambda + k];
    const Vec3 dd = symmetric_times(dsum, d);
    fij = d * (central - (up * dmu.dot(d) + wp * d.dot(dd)) / r) - u * dmu - 2.0 * w * dd;
    return true;
  }
};

}  // namespace

AdpPotential::AdpPotential(const AdpTables& tables, std::vector<std::string> type_names)
    : EmbeddedAtomPotential("adp", tables.eam, std::move(type_names)),
      moment_rows_(tables.eam, kMomentStride,
                   [&tables](int ti, int tj, std::size_t m, double* row) { fill_moment_row(tables, ti, tj, m, row); }),
      force_rows_(tables.eam, kForceStride,
                  [&tables](int ti, int tj, std::size_t m, double* row) { fill_force_row(tables, ti, tj, m, row); }) {}

std::vector<double> AdpPotential::density() const {
  std::vector<double> rho;
  for (const auto& m : moments_) rho.push_back(m.v[kRho]);
  return rho;
}

void AdpPotential::compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) {
  const EamTables& t = tables();
  const double cutsq = t.cut * t.cut;

  moments_.assign(atoms.size(), AdpAtomTerms{});
  accumulate_pair_scalars(atoms, list, MomentKernel{{moment_rows_, atoms.type.data(), t}, cutsq}, moments_,
                          thread_moments_, &accepted_);
  atoms.reverse_sum(moments_);

  // Step 3: the embedding and angular energy of each owned atom, and F', μ, D for the forces.
  terms_.assign(atoms.size(), AdpAtomTerms{});
  out.energy += sum_over_atoms(atoms.nlocal, [&](std::size_t i) {
    const auto& m = moments_[i].v;
    auto& term = terms_[i].v;
    const auto [embed, slope] = embedding(t, atoms.type[i], m[kRho]);
    const double* mu = m.data() + kMu;
    const double* lambda = m.data() + kLambda;
    const double nu = lambda[0] + lambda[1] + lambda[2];
    const double energy = embed + 0.5 * (mu[0] * mu[0] + mu[1] * mu[1] + mu[2] * mu[2]) +
                          0.5 * (lambda[0] * lambda[0] + lambda[1] * lambda[1] + lambda[2] * lambda[2]) +
                          (lambda[3] * lambda[3] + lambda[4] * lambda[4] + lambda[5] * lambda[5]) -
                          nu * nu / 6.0;
    term[kFp] = slope;
    std::copy(mu, mu + 3, term.begin() + kMu);
    std::copy(lambda, lambda + 6, term.begin() + kLambda);
    for (std::size_t a = 0; a < 3; ++a) term[kLambda + a] -= nu / 3.0;
    if (out.per_atom) out.energy_atom[i] += energy;
    return energy;
  });
  atoms.forward_copy(terms_);

  accumulate_pair_forces(atoms, list, ForceKernel{{force_rows_, atoms.type.data(), t}, terms_.data(), cutsq},
                         out, scratch_, &accepted_);
  moments_.resize(atoms.nlocal);
}

}  // namespace shockfield::md::potentials
