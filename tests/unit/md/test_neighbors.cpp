// Half neighbour lists with ghost atoms hold each physical pair exactly once, including boxes
// thinner than the cutoff (several periodic images of one pair).
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <limits>
#include <map>

#include "md_fixture.hpp"
#include "shockfield/md/force_evaluation.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/ghosts.hpp"

using namespace shockfield;
using namespace shockfield::md;

namespace {

// Brute force: Σ over pairs and periodic images of the LJ energy (ε, σ, r_c as argon_lj()).
double brute_force_lj(const Atoms& a, const geometry::Box& box, double rc) {
  const double eps = 0.0104, sig = 3.4;
  const Vec3 l = box.length();
  const int ni = static_cast<int>(std::ceil(rc / l.x())), nj = static_cast<int>(std::ceil(rc / l.y())),
            nk = static_cast<int>(std::ceil(rc / l.z()));
  double e = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i)
    for (std::size_t j = 0; j < a.nlocal; ++j)
      for (int p = -ni; p <= ni; ++p)
        for (int q = -nj; q <= nj; ++q)
          for (int r = -nk; r <= nk; ++r) {
            if (i == j && p == 0 && q == 0 && r == 0) continue;
            const Vec3 d = a.x[j] + Vec3(p * l.x(), q * l.y(), r * l.z()) - a.x[i];
            const double r2 = d.squaredNorm();
            if (r2 >= rc * rc) continue;
            const double s6 = std::pow(sig * sig / r2, 3);
            e += 0.5 * 4 * eps * (s6 * s6 - s6);
          }
  return e;
}

}  // namespace

TEST(NeighborList, EveryPhysicalPairOnceInAPeriodicBox) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {4, 4, 4}, box, 63.55);
  fixture::perturb(atoms, 0.2, 3);
  const double cut = 5.0;
  rebuild_ghosts(atoms, box, cut);
  geometry::NeighborList list;
  geometry::build_neighbor_list(atoms.x, atoms.nlocal, cut, true, list);
  // Count pairs by (owner i, owner j, rounded separation) and compare with brute force.
  std::map<std::tuple<long, long, long, long, long>, int> seen;
  auto key = [&](std::size_t i, int j, const Vec3& d) {
    const long a = static_cast<long>(std::min<std::size_t>(i, j)), b = static_cast<long>(std::max<std::size_t>(i, j));
    const Vec3 s = (static_cast<std::size_t>(j) > i ? d : Vec3(-d)) * 1000.0;
    return std::make_tuple(a, b, std::lround(s.x()), std::lround(s.y()), std::lround(s.z()));
  };
  for (std::size_t i = 0; i < list.nlocal(); ++i)
    for (auto k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const int j = list.neighbors[k];
      const int owner = static_cast<std::size_t>(j) < atoms.nlocal ? j : atoms.ghost_owner[j - atoms.nlocal];
      const Vec3 d = atoms.x[j] - atoms.x[i];
      if (d.norm() < cut) ++seen[key(i, owner, d)];
    }
  std::size_t expected = 0;
  for (std::size_t i = 0; i < atoms.nlocal; ++i)
    for (std::size_t j = i + 1; j < atoms.nlocal; ++j)
      if (box.minimum_image(atoms.x[j] - atoms.x[i]).norm() < cut) ++expected;
  std::size_t found = 0;
  for (const auto& [k, count] : seen) {
    EXPECT_EQ(count, 1);
    found += static_cast<std::size_t>(count);
  }
  EXPECT_EQ(found, expected);
}

TEST(NeighborList, ThinBoxSumsEveryPeriodicImage) {
  // 2×2×1 cells of 3.615 Å: z is thinner than the 8.5 Å cutoff, so a pair has several images.
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {2, 2, 1}, box, 39.95);
  fixture::perturb(atoms, 0.1, 5);
  auto lj = fixture::argon_lj();
  geometry::NeighborList list;
  rebuild_ghosts(atoms, box, lj->cutoff() + 0.5);
  geometry::build_neighbor_list(atoms.x, atoms.nlocal, lj->cutoff() + 0.5, true, list);
  ForceResult result;
  evaluate_forces(atoms, *lj, list, result, false);
  EXPECT_NEAR(result.energy, brute_force_lj(atoms, box, 8.5), 1e-10 * std::abs(result.energy));
  Vec3 total = Vec3::Zero();
  for (std::size_t i = 0; i < atoms.nlocal; ++i) total += atoms.f[i];
  EXPECT_LT(total.norm(), 1e-10);
}

// A non-finite position (a run that blew up) is a RunError, not an out-of-bounds cell access:
// min/max skip a NaN and an infinity makes the cell grid meaningless (found by the case_run fuzzer).
TEST(NeighborList, NonFinitePositionIsARunError) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -1e308 * 10}) {
    std::vector<Vec3> points{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, bad, 0), Vec3(0, 0, 1)};
    geometry::NeighborList list;
    EXPECT_THROW(geometry::build_neighbor_list(points, points.size(), 1.5, true, list), RunError) << bad;
  }
}

// The ghosts are written by all threads in the order of the serial loop (x, then y, then z; per
// dimension layer 1 below, layer 1 above, layer 2 below, ...; entries in index order), so a run's
// neighbour lists and force sums do not depend on the thread count. The reference here is that
// serial loop written out, on a box thinner than the cutoff along y (two image layers) and
// shrink-wrapped along z; each ghost must sit at its owner's position plus image·L.
TEST(Ghosts, ParallelImagesAreTheSerialLoopsOnAnyThreadCount) {
  geometry::Box box;
  Atoms owned = fixture::fcc_atoms(3.615, {5, 1, 3}, box, 63.55);
  box.boundary[2] = geometry::Boundary::shrink;
  fixture::perturb(owned, 0.3, 11);
  const double cut = 5.5;
  // The serial loop: for each periodic d, pass p over entries [0, n) present before d.
  Atoms ref = owned;
  for (std::size_t i = 0; i < ref.nlocal; ++i) box.wrap(ref.x[i], ref.image[i]);
  for (int d = 0; d < 3; ++d) {
    if (!box.periodic(d)) continue;
    const double len = box.hi[d] - box.lo[d];
    const int layers = static_cast<int>(std::ceil(cut / len));
    const std::size_t n = ref.size();
    for (int layer = 1; layer <= layers; ++layer)
      for (int side = -1; side <= 1; side += 2)
        for (std::size_t i = 0; i < n; ++i) {
          const double y = ref.x[i][d] + side * layer * len;
          if (y < box.lo[d] - cut || y >= box.hi[d] + cut) continue;
          std::array<int, 3> image{0, 0, 0};
          if (i >= ref.nlocal) image = ref.ghost_image[i - ref.nlocal];
          image[static_cast<std::size_t>(d)] += side * layer;
          Vec3 x = ref.x[i];
          x[d] += side * layer * len;
          ref.x.push_back(x);
          ref.type.push_back(ref.type[i]);
          ref.ghost_owner.push_back(i < ref.nlocal ? static_cast<int>(i) : ref.ghost_owner[i - ref.nlocal]);
          ref.ghost_image.push_back(image);
        }
  }
  ASSERT_GT(ref.nghost(), 2 * ref.nlocal);  // several layers along y: the case is not trivial
  for (int threads : {1, 2, 3, 7}) {
    omp_set_num_threads(threads);
    Atoms atoms = owned;
    rebuild_ghosts(atoms, box, cut);
    ASSERT_EQ(atoms.size(), ref.size()) << threads;
    EXPECT_EQ(atoms.f.size(), atoms.size());
    EXPECT_EQ(atoms.ghost_owner, ref.ghost_owner) << threads;
    EXPECT_EQ(atoms.ghost_image, ref.ghost_image) << threads;
    EXPECT_EQ(atoms.type, ref.type) << threads;
    for (std::size_t k = 0; k < atoms.size(); ++k) ASSERT_EQ(atoms.x[k], ref.x[k]) << threads << " entry " << k;
    const Vec3 l = box.length();
    for (std::size_t g = 0; g < atoms.nghost(); ++g) {
      const auto& im = atoms.ghost_image[g];
      const Vec3 expected = atoms.x[static_cast<std::size_t>(atoms.ghost_owner[g])] +
                            Vec3(im[0] * l.x(), im[1] * l.y(), im[2] * l.z());
      ASSERT_LT((atoms.x[atoms.nlocal + g] - expected).norm(), 1e-12) << g;
    }
  }
  omp_set_num_threads(1);
}

// ghost_capacity() is enough for a uniform crystal, so appending the ghosts does not reallocate.
TEST(Ghosts, ReservedCapacityHoldsTheGhostsOfAUniformCrystal) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(3.615, {12, 12, 12}, box, 63.55);
  const double cut = 3.6;
  const std::size_t capacity = ghost_capacity(atoms.nlocal, box, cut);
  atoms.x.reserve(capacity);
  const Vec3* before = atoms.x.data();
  append_ghosts(atoms, box, cut);
  EXPECT_EQ(atoms.x.data(), before);  // appended in place
  EXPECT_EQ(atoms.nghost(), 2929u);  // 1.125³ − 1 of the owned atoms: 3 of 24 lattice planes per axis are within 3.6 Å of a face
  EXPECT_LE(atoms.size(), capacity);
}

// most_entries() bounds owned + ghost entries however the atoms lie (the in-process views of
// docs/python.md rely on it): atoms anywhere in a box shorter than the interaction range along
// some axes (two image layers there), and reserving the bound keeps x in place through rebuilds.
TEST(Ghosts, MostEntriesBoundsEveryRebuild) {
  geometry::Box box;
  Atoms owned = fixture::fcc_atoms(3.615, {5, 1, 3}, box, 63.55);
  const double cut = 5.5;  // y: 3.615 Å long, 2 layers; x, z: 1 layer
  const std::size_t bound = most_entries(owned.nlocal, box, cut);
  EXPECT_EQ(bound, owned.nlocal * 3 * 5 * 3);
  Atoms atoms = owned;
  atoms.x.reserve(bound);
  const Vec3* before = atoms.x.data();
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Atoms moved = owned;
    fixture::perturb(moved, 0.2 * static_cast<double>(seed), seed);  // up to 4 Å: any arrangement
    std::copy(moved.x.begin(), moved.x.begin() + static_cast<std::ptrdiff_t>(moved.nlocal), atoms.x.begin());
    rebuild_ghosts(atoms, box, cut);
    ASSERT_LE(atoms.size(), bound) << seed;
    ASSERT_EQ(atoms.x.data(), before) << seed;
  }
}
