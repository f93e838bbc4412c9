#include "shockfield/md/ghosts.hpp"

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

}  // namespace

double GhostAtoms::coordinate(std::size_t i, int d) const {
  return triclinic ? box.to_fractional(atoms.x[i])[d] : atoms.x[i][d];
}

void GhostAtoms::pack_ghost(std::size_t i, int d, int periods, double* out) const {
  Vec3 shift = Vec3::Zero();
  if (triclinic) shift = static_cast<double>(periods) * box.edge(d);
  else shift[d] = periods * (box.hi[d] - box.lo[d]);
  const Vec3 x = atoms.x[i] + shift;
  const bool is_ghost = i >= atoms.nlocal;
  std::array<int, 3> image{0, 0, 0};
  if (is_ghost) image = atoms.ghost_image[i - atoms.nlocal];
  image[static_cast<std::size_t>(d)] += periods;
  const double owner = is_ghost ? atoms.ghost_owner[i - atoms.nlocal] : static_cast<double>(i);
  const double record[ghost_width] = {x[0], x[1], x[2], static_cast<double>(atoms.type[i]), owner,
                                      static_cast<double>(image[0]), static_cast<double>(image[1]),
                                      static_cast<double>(image[2])};
  std::copy(record, record + ghost_width, out);
}

void GhostAtoms::append_ghosts(const double* in, std::size_t count, bool from_self) {
  const std::size_t first = atoms.size(), nlocal = atoms.nlocal;
  atoms.x.resize(first + count);
  atoms.type.resize(first + count);
  atoms.ghost_owner.resize(first + count - nlocal);
  atoms.ghost_image.resize(first + count - nlocal);
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t j = 0; j < n; ++j) {
    const double* r = in + j * ghost_width;
    const std::size_t k = first + static_cast<std::size_t>(j);
    atoms.x[k] = Vec3(r[0], r[1], r[2]);
    atoms.type[k] = static_cast<int>(r[3]);
    atoms.ghost_owner[k - nlocal] = from_self ? static_cast<int>(r[4]) : -1;
    atoms.ghost_image[k - nlocal] = {static_cast<int>(r[5]), static_cast<int>(r[6]), static_cast<int>(r[7])};
  }
}

std::array<parallel::AxisSpan, 3> ghost_spans(const geometry::Box& box) {
  std::array<parallel::AxisSpan, 3> spans;
  for (int d = 0; d < 3; ++d)
    spans[d] = box.triclinic() ? parallel::AxisSpan{0.0, 1.0, box.periodic(d)}
                               : parallel::AxisSpan{box.lo[d], box.hi[d], box.periodic(d)};
  return spans;
}

std::array<double, 3> ghost_cutoffs(const geometry::Box& box, double cutoff) {
  // A triclinic cell selects in fractional coordinates, the cutoff measured along the face
  // normal as LAMMPS's Comm::setup does (cutghost = cutoff / face distance in lamda units).
  if (!box.triclinic()) return {cutoff, cutoff, cutoff};
  const Vec3 faces = box.face_distances();
  return {cutoff / faces[0], cutoff / faces[1], cutoff / faces[2]};
}

std::array<int, 3> ghost_layers(const geometry::Box& box, double cutoff) {
  return {image_layers(box, 0, cutoff), image_layers(box, 1, cutoff), image_layers(box, 2, cutoff)};
}

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
  const std::array<bool, 3> periodic{box.periodic(0), box.periodic(1), box.periodic(2)};
  const parallel::ParticleExchange one_rank(parallel::Communicator::single().cartesian({1, 1, 1}, periodic),
                                            ghost_spans(box), ghost_cutoffs(box, cutoff));
  GhostAtoms view{atoms, box, box.triclinic()};
  one_rank.build_ghosts(view, ghost_layers(box, cutoff));
}

void rebuild_ghosts(Atoms& atoms, const geometry::Box& box, double cutoff) {
  atoms.clear_ghosts();
  append_ghosts(atoms, box, cutoff);
  atoms.f.resize(atoms.size());
}

}  // namespace shockfield::md
