#include "shockfield/mpm/sample_builders.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <random>
#include <unordered_map>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"

namespace shockfield::mpm {

namespace {

void check_body(int dim, const Body& body) {
  if (dim != 2 && dim != 3) throw InputError(fmt::format("mpm sample: dim = {} (expected 2 or 3)", dim));
  if (!(body.spacing > 0.0)) throw InputError(fmt::format("mpm sample: spacing = {} m (expected > 0)", body.spacing));
  if (body.id < 0) throw InputError(fmt::format("mpm sample: body id {} (expected >= 0)", body.id));
  for (int a = 0; a < dim; ++a)
    if (!(body.hi[a] - body.lo[a] >= body.spacing))
      throw InputError(fmt::format("mpm sample: body extent along axis {} is [{}, {}] m (expected at least one "
                                   "spacing, {} m)", a, body.lo[a], body.hi[a], body.spacing));
}

double ball_volume(int dim, double r) {
  return dim == 2 ? std::numbers::pi * r * r : 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

// Calls fn(shift) for every lattice translation by −1, 0 or +1 period along each periodic axis
// (period[a] > 0), the zero shift first.
template <class Fn>
void for_each_shift(const Vec3& period, Fn&& fn) {
  for (int code = 0; code < 27; ++code) {
    Vec3 shift = Vec3::Zero();
    bool valid = true;
    for (int a = 0, c = code; a < 3; ++a, c /= 3) {
      const int step = c % 3 == 2 ? -1 : c % 3;  // 0, +1, −1
      if (step != 0 && !(period[a] > 0.0)) valid = false;
      shift[a] = step * period[a];
    }
    if (valid) fn(shift);
  }
}

// Random sequential addition with a bucket grid of the largest diameter for overlap tests. Along
// periodic axes a candidate is tested in each of its images, so stored centres stay in the body
// and the minimum-image distance decides (a void is smaller than the period, so ±1 suffices).
class VoidPacker {
 public:
  VoidPacker(int dim, double bucket, const Vec3& period) : dim_(dim), bucket_(bucket), period_(period) {}
  bool fits(const Void& v) const {
    bool ok = true;
    for_each_shift(period_, [&](const Vec3& shift) { ok = ok && fits_here(Void{v.centre + shift, v.radius}); });
    return ok;
  }
  void add(const Void& v) {
    const auto c = key(v.centre);
    buckets_[pack(c[0], c[1], c[2])].push_back(voids_.size());
    voids_.push_back(v);
  }
  std::vector<Void> take() { return std::move(voids_); }

 private:
  bool fits_here(const Void& v) const {
    const auto c = key(v.centre);
    for (int dz = dim_ == 3 ? -1 : 0; dz <= (dim_ == 3 ? 1 : 0); ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          auto it = buckets_.find(pack(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == buckets_.end()) continue;
          for (std::size_t i : it->second)
            if ((voids_[i].centre - v.centre).norm() < voids_[i].radius + v.radius) return false;
        }
    return true;
  }
  std::array<long, 3> key(const Vec3& x) const {
    return {static_cast<long>(std::floor(x[0] / bucket_)), static_cast<long>(std::floor(x[1] / bucket_)),
            static_cast<long>(std::floor(x[2] / bucket_))};
  }
  static long pack(long i, long j, long k) { return (i * 73856093L) ^ (j * 19349663L) ^ (k * 83492791L); }
  int dim_;
  double bucket_;
  Vec3 period_;
  std::vector<Void> voids_;
  std::unordered_map<long, std::vector<std::size_t>> buckets_;
};

// The wrapped images of `voids` that reach into the body across a periodic side.
std::vector<Void> periodic_images(int dim, const Body& body, const Vec3& period, const std::vector<Void>& voids) {
  std::vector<Void> images;
  for (const Void& v : voids)
    for_each_shift(period, [&](const Vec3& shift) {
      if (shift.isZero()) return;
      const Void image{v.centre + shift, v.radius};
      bool reaches = true;
      for (int a = 0; a < dim; ++a)
        reaches = reaches && image.centre[a] - image.radius < body.hi[a] && image.centre[a] + image.radius > body.lo[a];
      if (reaches) images.push_back(image);
    });
  return images;
}

}  // namespace

BodyStats add_body(Particles& p, int dim, const Body& body, const materials::SolidMaterial& mat,
                   const std::vector<Void>& voids) {
  check_body(dim, body);
  std::array<long, 3> n{1, 1, 1};
  for (int a = 0; a < dim; ++a)
    n[static_cast<std::size_t>(a)] = std::lround(std::floor((body.hi[a] - body.lo[a]) / body.spacing + 1e-9));
  const double volume = std::pow(body.spacing, dim);
  Vec3 half = Vec3::Constant(0.5 * body.spacing);
  if (dim == 2) half[2] = 0.0;
  BodyStats stats;
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i) {
        Vec3 x = body.lo + body.spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
        if (dim == 2) x[2] = 0.0;
        ++stats.lattice_points;
        const bool inside_void = std::any_of(voids.begin(), voids.end(), [&](const Void& v) {
          return (x - v.centre).squaredNorm() < v.radius * v.radius;
        });
        if (inside_void) continue;
        p.add(x, body.velocity, volume, half, mat, body.material, body.id);
        ++stats.added;
      }
  return stats;
}

std::vector<Void> place_voids(int dim, const Body& body, const VoidSpec& spec, const PeriodicAxes& periodic) {
  check_body(dim, body);
  // Random sequential addition jams at 0.547 (discs) and 0.384 (spheres) (Feder 1980; Torquato,
  // Random Heterogeneous Materials, 2002, §3.1): beyond it no placement succeeds.
  const double jamming = dim == 2 ? 0.547 : 0.384;
  if (!(spec.porosity > 0.0 && spec.porosity < jamming))
    throw InputError(fmt::format("mpm porous sample: porosity = {} (expected 0 < Δ < {}, the random-packing limit of "
                                 "non-overlapping {} voids)", spec.porosity, jamming, dim == 2 ? "circular" : "spherical"));
  if (!(spec.mean_radius > 0.0))
    throw InputError(fmt::format("mpm porous sample: mean void radius = {} m (expected > 0)", spec.mean_radius));
  if (!(spec.radius_spread >= 0.0 && spec.radius_spread < 1.0))
    throw InputError(fmt::format("mpm porous sample: radius spread = {} (expected 0 <= spread < 1)", spec.radius_spread));
  const double r_max = spec.mean_radius * (1.0 + spec.radius_spread);
  double body_volume = 1.0;
  Vec3 period = Vec3::Zero();  // > 0 along the axes where voids cross the sides
  for (int a = 0; a < dim; ++a) {
    const double extent = body.hi[a] - body.lo[a];
    body_volume *= extent;
    if (spec.cross_periodic_sides && periodic[static_cast<std::size_t>(a)]) period[a] = extent;
    if (2.0 * r_max >= extent)
      throw InputError(fmt::format("mpm porous sample: voids of radius up to {} m do not fit the body, {} m along axis {}",
                                   r_max, extent, a));
  }
  // The number of voids before any is drawn: a radius far below the body's size asks for more
  // voids than any machine holds (a fuzzed 2.5e-308 m ran out of memory drawing radii).
  const double smallest = ball_volume(dim, spec.mean_radius * (1.0 - spec.radius_spread));
  const double most_voids = spec.porosity * body_volume / smallest;
  if (!(most_voids <= kMaxParticles))
    throw InputError(fmt::format("mpm porous sample: void radius {} m gives up to {:.3g} voids in the body (porosity "
                                 "{}; expected at most {:.0e}): the radius is far below the body's size",
                                 spec.mean_radius, most_voids, spec.porosity, kMaxParticles));
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Radii first, until the target void volume is reached.
  std::vector<double> radii;
  double placed_volume = 0.0;
  const double target = spec.porosity * body_volume;
  while (placed_volume < target) {
    const double r = spec.mean_radius * (1.0 + spec.radius_spread * (2.0 * unit(rng) - 1.0));
    const double v = ball_volume(dim, r);
    if (placed_volume + v - target > target - placed_volume) break;  // stop at the closer total
    radii.push_back(r);
    placed_volume += v;
  }
  if (radii.empty())
    throw InputError(fmt::format("mpm porous sample: porosity {} of a {} m^{} body is less than one void of radius {} m",
                                 spec.porosity, body_volume, dim, spec.mean_radius));
  std::sort(radii.begin(), radii.end(), std::greater<>());  // large first packs better
  VoidPacker packer(dim, 2.0 * r_max, period);
  const std::size_t max_attempts = 2000 * radii.size() + 100000;
  std::size_t attempts = 0, placed = 0;
  for (double r : radii) {
    bool ok = false;
    while (!ok && attempts < max_attempts) {
      ++attempts;
      Void v{Vec3::Zero(), r};
      for (int a = 0; a < dim; ++a)  // over the whole period, or keeping r from the faces
        v.centre[a] = period[a] > 0.0 ? body.lo[a] + unit(rng) * period[a]
                                      : body.lo[a] + r + unit(rng) * (body.hi[a] - body.lo[a] - 2.0 * r);
      ok = packer.fits(v);
      if (ok) packer.add(v);
    }
    if (!ok)
      throw InputError(fmt::format("mpm porous sample: could place only {} of {} voids (radius {} m, porosity {}) after "
                                   "{} attempts; lower the porosity or the radius", placed, radii.size(),
                                   spec.mean_radius, spec.porosity, attempts));
    ++placed;
  }
  std::vector<Void> voids = packer.take();
  const std::vector<Void> images = periodic_images(dim, body, period, voids);
  voids.insert(voids.end(), images.begin(), images.end());
  return voids;
}

Void cavity_at(int dim, const Body& body, double depth, double radius) {
  check_body(dim, body);
  const int axis = dim - 1;
  Void v{0.5 * (body.lo + body.hi), radius};
  if (dim == 2) v.centre[2] = 0.0;
  v.centre[axis] = body.lo[axis] + depth;
  for (int a = 0; a < dim; ++a)
    if (!(radius > 0.0 && v.centre[a] - radius >= body.lo[a] && v.centre[a] + radius <= body.hi[a]))
      throw InputError(fmt::format("mpm cavity: radius {} m at depth {} m does not lie inside the body along axis {}",
                                   radius, depth, a));
  return v;
}

GridSpec impact_grid(int dim, const Vec3& lo, const Vec3& hi, double h, Wall low_face) {
  GridSpec g;
  g.dim = dim;
  g.origin = lo;
  g.cell_size = Vec3::Constant(h);
  const int axis = dim - 1;
  for (int a = 0; a < dim; ++a) {
    const double cells = (hi[a] - lo[a]) / h;
    const long n = std::lround(cells);
    const bool lateral = a != axis;
    if (n < 1 || (lateral && std::abs(cells - static_cast<double>(n)) > 1e-6))
      throw InputError(fmt::format("mpm grid: extent {} m along axis {} is not a whole number (>= 1) of cells of {} m",
                                   hi[a] - lo[a], a, h));
    g.cells[static_cast<std::size_t>(a)] = static_cast<int>(lateral ? n : std::ceil(cells - 1e-9));
    g.periodic[static_cast<std::size_t>(a)] = lateral;
  }
  g.walls[static_cast<std::size_t>(axis)][0] = low_face;
  g.validate();
  return g;
}

std::vector<BodyStats> add_symmetric_impact(Particles& p, int dim, const Body& lower, double speed,
                                            const materials::SolidMaterial& mat) {
  const int axis = dim - 1;
  Body a = lower, b = lower;
  a.velocity = Vec3::Zero();
  a.velocity[axis] = speed;
  b.velocity = -a.velocity;
  b.id = a.id + 1;
  const double height = lower.hi[axis] - lower.lo[axis];
  b.lo[axis] += height;
  b.hi[axis] += height;
  return {add_body(p, dim, a, mat), add_body(p, dim, b, mat)};
}

}  // namespace shockfield::mpm
