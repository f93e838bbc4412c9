#include "shockfield/md/potentials/eam.hpp"

#include <algorithm>
#include <cmath>

namespace shockfield::md::potentials {
namespace {

constexpr std::size_t kDensityStride = 8;
constexpr std::size_t kForceStride = 16;  // 13 used, padded to two cache lines

struct DensityKernel {
  PairRowLookup rows;
  double cutsq;
  bool operator()(int i, int j, const Vec3&, double rsq, double& to_i, double& to_j) const {
    if (!(rsq < cutsq)) return false;  // NaN distances too
    double p;
    const double* c = rows.at(i, j, std::sqrt(rsq), p);
    to_i = spline_value(c, p);
    to_j = spline_value(c + 4, p);
    return true;
  }
};

struct ForceKernel {
  PairRowLookup rows;
  const double* fp;
  double cutsq;
  bool operator()(int i, int j, double rsq, double& fpair, double& energy) const {
    if (!(rsq < cutsq)) return false;  // NaN distances too
    const double r = std::sqrt(rsq);
    double p;
    const double* c = rows.at(i, j, r, p);
    fpair = eam_pair_force(c, p, r, fp[i], fp[j], energy);
    return true;
  }
};

}  // namespace

EamPotential::EamPotential(std::string style, EamTables tables, std::vector<std::string> type_names)
    : EmbeddedAtomPotential(std::move(style), std::move(tables), std::move(type_names)),
      density_rows_(this->tables(), kDensityStride,
                    [this](int ti, int tj, std::size_t m, double* row) { fill_eam_density_row(this->tables(), ti, tj, m, row); }),
      force_rows_(this->tables(), kForceStride,
                  [this](int ti, int tj, std::size_t m, double* row) { fill_eam_force_row(this->tables(), ti, tj, m, row); }) {}

void EamPotential::compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) {
  const EamTables& t = tables();
  const double cutsq = t.cut * t.cut;

  rho_.assign(atoms.size(), 0.0);
  accumulate_pair_scalars(atoms, list, DensityKernel{{density_rows_, atoms.type.data(), t}, cutsq}, rho_,
                          scratch_.scalar, &accepted_);
  atoms.reverse_sum(rho_);

  // Embedding on owned atoms (PairEAM::compute(), "fp = derivative of embedding energy").
  fp_.assign(atoms.size(), 0.0);
  out.energy += sum_over_atoms(atoms.nlocal, [&](std::size_t i) {
    const auto [energy, slope] = embedding(t, atoms.type[i], rho_[i]);
    fp_[i] = slope;
    if (out.per_atom) out.energy_atom[i] += energy;
    return energy;
  });
  atoms.forward_copy(fp_);

  accumulate_pair_forces(atoms, list, ForceKernel{{force_rows_, atoms.type.data(), t}, fp_.data(), cutsq}, out,
                         scratch_, &accepted_);
  rho_.resize(atoms.nlocal);
}

}  // namespace shockfield::md::potentials
