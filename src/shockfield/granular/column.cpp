#include "shockfield/granular/column.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/contact_law.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::granular {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The Hertz pair force of md::potentials::PairForceKernel: fpair = F/r (force on i = (x_i − x_j)
// fpair), energy (2/5) κ δ^{5/2}; pairs not touching are rejected.
struct HertzPairKernel {
  const int* type;
  int ntypes;
  const double* kappa;    ///< per type pair
  const double* contact;  ///< R_i + R_j per type pair
  bool operator()(int i, int j, double rsq, double& fpair, double& energy) const {
    const auto p = static_cast<std::size_t>(type[i] * ntypes + type[j]);
    const double d = contact[p];
    if (rsq >= d * d) return false;
    const double r = std::sqrt(rsq), delta = d - r, root = std::sqrt(delta);
    fpair = kappa[p] * delta * root / r;
    energy = 0.4 * kappa[p] * delta * delta * root;
    return true;
  }
};

// The overlap of a sphere of radius R at distance `gap` (centre to wall) with a wall.
double wall_overlap(double radius, double gap) { return std::max(radius - gap, 0.0); }

}  // namespace

Column::Column(ColumnSpec spec, md::Atoms spheres) : spec_(std::move(spec)), atoms_(std::move(spheres)) {
  const auto nt = spec_.types.size();
  if (nt == 0) throw InputError("a column needs at least one sphere type");
  if (atoms_.nghost() != 0) throw InputError("a column's spheres have no ghosts (walls, no periodic faces)");
  if (!(spec_.time_step > 0)) throw InputError("the column's time step must be positive");
  atoms_.mass.assign(nt, 0.0);
  radius_.resize(nt);
  wall_kappa_.resize(nt);
  double smallest = kInf;
  for (std::size_t t = 0; t < nt; ++t) {
    const SphereType& s = spec_.types[t];
    if (!(s.radius > 0) || !(s.density > 0) || !(s.youngs_modulus > 0) || !(s.poisson_ratio > -1 && s.poisson_ratio < 0.5))
      throw InputError(fmt::format("sphere type {}: radius, density and modulus must be positive and "
                                   "Poisson's ratio in (-1, 0.5)", t + 1));
    radius_[t] = s.radius;
    atoms_.mass[t] = 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius * s.density;
    wall_kappa_[t] = hertz_kappa(s.youngs_modulus, s.poisson_ratio, s.radius, kInf, 0.0, kInf);
    smallest = std::min(smallest, s.radius);
  }
  pair_kappa_.resize(nt * nt);
  pair_contact_.resize(nt * nt);
  for (std::size_t a = 0; a < nt; ++a)
    for (std::size_t b = 0; b < nt; ++b) {
      const SphereType &s = spec_.types[a], &u = spec_.types[b];
      pair_kappa_[a * nt + b] = hertz_kappa(s.youngs_modulus, s.poisson_ratio, s.radius, u.youngs_modulus,
                                            u.poisson_ratio, u.radius);
      pair_contact_[a * nt + b] = s.radius + u.radius;
    }
  if (spec_.skin <= 0) spec_.skin = 0.1 * smallest;
  for (std::size_t i = 0; i < atoms_.nlocal; ++i) {
    const Vec3& x = atoms_.x[i];
    if (atoms_.type[i] < 0 || atoms_.type[i] >= static_cast<int>(nt))
      throw InputError(fmt::format("sphere {} has type {}, the column has {} types", i, atoms_.type[i] + 1, nt));
    if (x.z() != 0 || x.x() < spec_.left || x.x() > spec_.right || x.y() < spec_.floor)
      throw InputError(fmt::format("sphere {} at ({}, {}, {}) m is outside the column's box (z = 0)", i, x.x(),
                                   x.y(), x.z()));
  }
  atoms_.v.resize(atoms_.nlocal, Vec3::Zero());
  atoms_.f.assign(atoms_.nlocal, Vec3::Zero());
  build_list();
  compute_forces();
}

void Column::build_list() {
  const double reach = *std::max_element(pair_contact_.begin(), pair_contact_.end());
  geometry::build_neighbor_list(atoms_.x, atoms_.nlocal, reach + spec_.skin, true, list_);
  built_at_ = atoms_.x;
  ++builds_;
}

void Column::compute_forces() {
  const std::size_t n = atoms_.nlocal;
  std::fill(atoms_.f.begin(), atoms_.f.end(), Vec3::Zero());
  md::ForceResult out;
  const HertzPairKernel kernel{atoms_.type.data(), static_cast<int>(spec_.types.size()), pair_kappa_.data(),
                               pair_contact_.data()};
  md::potentials::accumulate_pair_forces(atoms_, list_, kernel, out, scratch_);
  contact_energy_ = out.energy;
  const double g = spec_.gravity, left = spec_.left, right = spec_.right, floor = spec_.floor;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const auto t = static_cast<std::size_t>(atoms_.type[i]);
    const double R = radius_[t], k = wall_kappa_[t];
    const Vec3& x = atoms_.x[i];
    const double dl = wall_overlap(R, x.x() - left), dr = wall_overlap(R, right - x.x()),
                 df = wall_overlap(R, x.y() - floor);
    atoms_.f[i].x() += k * (dl * std::sqrt(dl) - dr * std::sqrt(dr));
    atoms_.f[i].y() += k * df * std::sqrt(df) - atoms_.mass[t] * g;
  }
}

void Column::step() {
  const std::size_t n = atoms_.nlocal;
  const double dt = spec_.time_step, half = 0.5 * dt, limit = 0.25 * spec_.skin * spec_.skin;
  bool rebuild = false;
#pragma omp parallel for schedule(static) reduction(|| : rebuild)
  for (std::size_t i = 0; i < n; ++i) {
    const double inv_m = 1.0 / atoms_.mass[static_cast<std::size_t>(atoms_.type[i])];
    atoms_.v[i] += half * inv_m * atoms_.f[i];
    atoms_.x[i] += dt * atoms_.v[i];
    rebuild = rebuild || (atoms_.x[i] - built_at_[i]).squaredNorm() > limit;
  }
  if (rebuild) build_list();
  compute_forces();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    atoms_.v[i] += half / atoms_.mass[static_cast<std::size_t>(atoms_.type[i])] * atoms_.f[i];
  ++steps_;
  time_ = static_cast<double>(steps_) * dt;
}

double Column::total_energy() const {
  double e = contact_energy_;
  for (std::size_t i = 0; i < atoms_.nlocal; ++i) {
    const auto t = static_cast<std::size_t>(atoms_.type[i]);
    const double R = radius_[t], m = atoms_.mass[t];
    const Vec3& x = atoms_.x[i];
    e += 0.5 * m * atoms_.v[i].squaredNorm() + m * spec_.gravity * (x.y() - spec_.floor);
    for (double d : {wall_overlap(R, x.x() - spec_.left), wall_overlap(R, spec_.right - x.x()),
                     wall_overlap(R, x.y() - spec_.floor)})
      e += 0.4 * wall_kappa_[t] * d * d * std::sqrt(d);
  }
  return e;
}

}  // namespace shockfield::granular
