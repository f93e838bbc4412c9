#include "shockfield/pd/run_ranks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <variant>

#include "shockfield/core/error.hpp"
#include "shockfield/parallel/communicator.hpp"

namespace shockfield::pd {
namespace {

bool per_bond(const ModelStateArray& a) { return a.name.rfind("bond_", 0) == 0; }

// Row `from` of `a` appended to `out` as doubles (integers are exact below 2^53), and back.
void pack_row(const ModelStateArray& a, std::size_t from, std::vector<double>& out) {
  const std::size_t w = a.row_size();
  for (std::size_t q = 0; q < w; ++q)
    out.push_back(a.integer ? static_cast<double>(a.counts[from * w + q]) : a.reals[from * w + q]);
}
const double* unpack_row(ModelStateArray& a, std::size_t to, const double* in) {
  const std::size_t w = a.row_size();
  for (std::size_t q = 0; q < w; ++q, ++in)
    if (a.integer)
      a.counts[to * w + q] = static_cast<std::int64_t>(*in);
    else
      a.reals[to * w + q] = *in;
  return in;
}

}  // namespace

std::shared_ptr<Decomposition> decompose_run(const Config& root, const PdCase& c, const PointCloud& cloud,
                                             const Family& family, const RunOptions& options) {
  const parallel::Communicator world = parallel::Communicator::world();
  if (world.size() == 1 && options.rank_grid.empty()) return nullptr;
  const std::string why = fmt::format("on one rank only so far ({} ranks started{}; docs/parallel.md)", world.size(),
                                      options.rank_grid.empty() ? "" : ", --rank-grid given");
  const Config material = root.table("material");
  if (std::holds_alternative<SmallStrainJ2>(c.material) || std::holds_alternative<CrystalSpec>(c.material))
    material.fail("model", fmt::format("pmb or lps under mpirun: the correspondence models run {}", why));
  const bool contact = std::visit(
      [](const auto& m) {
        if constexpr (requires { m.contact; }) return m.contact;
        return false;
      },
      c.material);
  if (contact)
    material.fail("contact", fmt::format("false under mpirun: the short-range contact force (on by default) runs {}", why));
  const parallel::Dims3 given = options.rank_grid.empty() ? parallel::Dims3{0, 0, 0}
                                                          : parallel::parse_rank_grid(options.rank_grid);
  const parallel::Dims3 dims = pd_rank_grid(cloud, family.horizon, world.size(), given);
  return std::make_shared<Decomposition>(world, dims, cloud, family);
}

ModelState local_state(const Decomposition& domain, const ModelState& whole) {
  ModelState local = whole;
  for (std::size_t k = 0; k < whole.size(); ++k) {
    const ModelStateArray& from = whole[k];
    ModelStateArray& to = local[k];
    const std::vector<std::size_t>& origin = per_bond(from) ? domain.bond_origin() : domain.point_origin();
    const std::size_t w = from.row_size();
    to.rows = origin.size();
    to.reals.clear(), to.counts.clear();
    for (std::size_t r : origin)
      for (std::size_t q = 0; q < w; ++q)
        if (from.integer)
          to.counts.push_back(from.counts[r * w + q]);
        else
          to.reals.push_back(from.reals[r * w + q]);
  }
  return local;
}

void deal_out(const Decomposition& domain, const Simulation& whole, Simulation& local) {
  const std::vector<std::size_t>& origin = domain.point_origin();
  std::vector<Vec3> y(origin.size()), v(origin.size()), f(origin.size());
  for (std::size_t l = 0; l < origin.size(); ++l) {
    y[l] = whole.positions()[origin[l]];
    v[l] = whole.velocities()[origin[l]];
    f[l] = whole.force_density()[origin[l]];
  }
  local.restore(std::move(y), std::move(v), std::move(f), whole.step_count(), whole.time());
}

void gather_whole(const Decomposition& domain, const Simulation& local, const ModelState& local_state,
                  Simulation& whole, ModelState& whole_state) {
  // One record per owned point (index, y, v, f, its per-point arrays' rows) and per bond of an
  // owned point (its per-bond arrays' rows; an owned point has all its bonds, in the whole
  // family's order, so rank 0 places them by the point's index).
  std::vector<double> points, bonds;
  for (std::size_t l = 0; l < domain.owned(); ++l) {
    points.push_back(static_cast<double>(domain.point_origin()[l]));
    for (const Vec3* a : {&local.positions()[l], &local.velocities()[l], &local.force_density()[l]})
      points.insert(points.end(), a->data(), a->data() + 3);
    for (const ModelStateArray& a : local_state)
      if (!per_bond(a)) pack_row(a, l, points);
    for (int b = domain.family().begin(l); b < domain.family().end(l); ++b)
      for (const ModelStateArray& a : local_state)
        if (per_bond(a)) pack_row(a, static_cast<std::size_t>(b), bonds);
  }
  const std::vector<double> all_points = domain.comm().gather(points), all_bonds = domain.comm().gather(bonds);
  if (!domain.comm().is_root()) return;
  const std::size_t n = whole.cloud().size();
  std::vector<Vec3> y(n), v(n), f(n);
  std::vector<int> seen(n, 0);
  const double* bond_in = all_bonds.data();
  for (const double* in = all_points.data(); in < all_points.data() + all_points.size();) {
    const auto g = static_cast<std::size_t>(*in++);
    ++seen[g];
    y[g] = Vec3(in[0], in[1], in[2]), v[g] = Vec3(in[3], in[4], in[5]), f[g] = Vec3(in[6], in[7], in[8]);
    in += 9;
    for (ModelStateArray& a : whole_state)
      if (!per_bond(a)) in = unpack_row(a, g, in);
    for (int b = whole.family().begin(g); b < whole.family().end(g); ++b)
      for (ModelStateArray& a : whole_state)
        if (per_bond(a)) bond_in = unpack_row(a, static_cast<std::size_t>(b), bond_in);
  }
  // A point lost or held twice is a bug of the decomposition: rank 0 alone knows, so it ends every
  // rank (MPI_Abort, exit 3) rather than leave them waiting in the next collective.
  const auto missing = std::count_if(seen.begin(), seen.end(), [](int s) { return s != 1; });
  if (missing > 0) {
    fmt::print(stderr, "error: pd on {} ranks: {} of {} points lost or held twice at step {} (a decomposition bug)\n",
               domain.comm().size(), missing, n, local.step_count());
    domain.comm().abort(3);
  }
  whole.restore(std::move(y), std::move(v), std::move(f), local.step_count(), local.time());
}

}  // namespace shockfield::pd
