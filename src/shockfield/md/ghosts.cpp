#include "shockfield/md/ghosts.hpp"

#include <omp.h>

#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::md {
namespace {
constexpr double kMaxGhostLayers = 8;

// Number of image layers needed along periodic dimension d (0 when d is not periodic): the
// cutoff over the cell's thickness between the faces d (its length for an orthogonal box).
int image_layers(const geometry::Box& box, int d, double cutoff) {
  if (!box.periodic(d)) return 0;
  const double length = box.triclinic() ? box.face_distances()[d] : box.hi[d] - box.lo[d];
  const double needed = std::ceil(cutoff / length);
  // Each layer copies every atom again: beyond a few layers the box is degenerate, not small.
  if (!(needed <= kMaxGhostLayers))
    throw RunError(fmt::format("the periodic box is {} Å long along {}, less than 1/{} of the "
                               "interaction range {} Å (cutoff + skin): ghost images cannot be built",
                               length, "xyz"[d], kMaxGhostLayers, cutoff));
  return static_cast<int>(needed);
}

void wrap_owned(Atoms& atoms, const geometry::Box& box) {
  const auto n = static_cast<std::ptrdiff_t>(atoms.nlocal);
  std::ptrdiff_t failed = n;  // the first atom that cannot be wrapped
#pragma omp parallel for schedule(static) reduction(min : failed)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (!box.try_wrap(atoms.x[u], atoms.image[u])) failed = std::min(failed, i);
  }
  if (failed < n) box.wrap(atoms.x[static_cast<std::size_t>(failed)], atoms.image[static_cast<std::size_t>(failed)]);
}

// The images of entries [0, n) along dimension d: for each layer and side in turn, the entries
// whose shifted position lies within `cutoff` of the box. Each thread counts its contiguous range
// of entries per (layer, side) pass; the prefix sums give every thread the slots a serial loop
// would have used, so the threads then write their ghosts in parallel in serial order.
void append_images_along(Atoms& atoms, const geometry::Box& box, double cutoff, int d, int layers) {
  const double length = box.hi[d] - box.lo[d];
  const std::size_t n = atoms.size();  // owned + ghosts of earlier dimensions
  const std::size_t nlocal = atoms.nlocal;
  const int passes = 2 * layers;       // pass p: layer p/2 + 1, side -1 (p even) or +1 (p odd)
  auto shift_of = [&](int p) { return (p % 2 == 0 ? -1 : 1) * (p / 2 + 1); };
  // A triclinic cell selects in fractional coordinates, the cutoff measured along the face
  // normal as LAMMPS's Comm::setup does (cutghost = cutoff / face distance in lamda units).
  const bool triclinic = box.triclinic();
  const double fractional_cutoff = cutoff / box.face_distances()[d];
  auto selected = [&](std::size_t i, int p) {
    if (triclinic) {
      const double s = box.to_fractional(atoms.x[i])[d] + shift_of(p);
      return !(s < -fractional_cutoff || s >= 1 + fractional_cutoff);
    }
    const double y = atoms.x[i][d] + shift_of(p) * length;
    return !(y < box.lo[d] - cutoff || y >= box.hi[d] + cutoff);
  };
  const int nthreads = omp_get_max_threads();
  std::vector<std::size_t> slot(static_cast<std::size_t>(passes * nthreads) + 1, 0);  // [pass][thread]
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num(), team = omp_get_num_threads();
    const std::size_t begin = n * t / team, end = n * (t + 1) / team;
    for (int p = 0; p < passes; ++p) {
      std::size_t count = 0;
      for (std::size_t i = begin; i < end; ++i) count += selected(i, p) ? 1 : 0;
      slot[static_cast<std::size_t>(p * nthreads + t) + 1] = count;
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t k = 1; k < slot.size(); ++k) slot[k] += slot[k - 1];
      const std::size_t total = n + slot.back();
      atoms.x.resize(total);
      atoms.type.resize(total);
      atoms.ghost_owner.resize(total - nlocal);
      atoms.ghost_image.resize(total - nlocal);
    }
    for (int p = 0; p < passes; ++p) {
      std::size_t k = n + slot[static_cast<std::size_t>(p * nthreads + t)];
      Vec3 shift = Vec3::Zero();
      if (triclinic) shift = shift_of(p) * box.edge(d);
      else shift[d] = shift_of(p) * length;
      for (std::size_t i = begin; i < end; ++i) {
        if (!selected(i, p)) continue;
        const bool is_ghost = i >= nlocal;
        std::array<int, 3> image{0, 0, 0};
        if (is_ghost) image = atoms.ghost_image[i - nlocal];
        image[static_cast<std::size_t>(d)] += shift_of(p);
        atoms.x[k] = atoms.x[i] + shift;
        atoms.type[k] = atoms.type[i];
        atoms.ghost_owner[k - nlocal] = is_ghost ? atoms.ghost_owner[i - nlocal] : static_cast<int>(i);
        atoms.ghost_image[k - nlocal] = image;
        ++k;
      }
    }
  }
}

}  // namespace

std::size_t ghost_capacity(std::size_t nlocal, const geometry::Box& box, double cutoff) {
  double factor = 1.05;
  for (int d = 0; d < 3; ++d)
    if (box.periodic(d)) factor *= 1.0 + 2.0 * cutoff / box.face_distances()[d];
  return static_cast<std::size_t>(static_cast<double>(nlocal) * std::min(factor, 64.0)) + 64;
}

std::size_t most_entries(std::size_t nlocal, const geometry::Box& box, double cutoff) {
  std::size_t images = 1;
  for (int d = 0; d < 3; ++d) images *= static_cast<std::size_t>(2 * image_layers(box, d, cutoff) + 1);
  return nlocal * images;
}

void append_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff) {
  wrap_owned(atoms, box);
  for (int d = 0; d < 3; ++d) {
    const int layers = image_layers(box, d, cutoff);
    if (layers > 0) append_images_along(atoms, box, cutoff, d, layers);
  }
}

void rebuild_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff) {
  atoms.clear_ghosts();
  append_ghosts(atoms, box, cutoff);
  atoms.f.resize(atoms.size());
}

}  // namespace shockfield::md
