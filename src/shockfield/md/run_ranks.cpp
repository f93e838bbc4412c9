#include "shockfield/md/run_ranks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <unordered_map>

#include "shockfield/core/error.hpp"
#include "shockfield/md/force_evaluation.hpp"
#include "shockfield/parallel/communicator.hpp"

namespace shockfield::md {
namespace {

// The refusals of decompose_run: `why` is appended to each message.
void refuse_undecomposed(const Config& root, const MdCase& md, const geometry::Box& box, const std::string& why) {
  const auto stages = root.tables("stage");
  for (std::size_t k = 0; k < md.stages.size(); ++k) {
    const StageSpec& s = md.stages[k];
    if (s.ensemble != "nve" && s.ensemble != "nvt" && s.ensemble != "langevin")
      stages[k].fail("ensemble", fmt::format("expected nve, nvt or langevin under mpirun: {} runs {}", s.ensemble, why));
    if (s.piston) stages[k].fail("piston", fmt::format("none under mpirun: a piston runs {}", why));
    if (s.deform_rate || s.deform_tilt_rate)
      stages[k].fail(s.deform_rate ? "deform_rate" : "deform_tilt_rate", fmt::format("none under mpirun: deform runs {}", why));
  }
  const Config system = root.table("system");
  const Config where = system.has("lattice") ? system.table("lattice") : system;
  if (box.triclinic())
    where.fail(where.has("tilt") ? "tilt" : "boundary", fmt::format("an orthogonal box under mpirun: a triclinic box runs {}", why));
  if (!(box.periodic(0) && box.periodic(1) && box.periodic(2)))
    where.fail("boundary", fmt::format("expected \"ppp\" under mpirun: fixed or shrink-wrapped boundaries run {}", why));
  const OutputSpec& out = md.output;
  const Config output = root.table("output");
  if (out.profile_every > 0) output.fail("profile_every", fmt::format("expected 0 under mpirun: binned profiles run {}", why));
  if (out.h5md_every > 0) output.fail("h5md_every", fmt::format("expected 0 under mpirun: the H5MD trajectory runs {}", why));
  for (const std::string& f : out.dump_fields)
    if (f == "pe" || (f.size() == 3 && f[0] == 's'))
      output.fail("dump_fields", fmt::format("no per-atom energy or stress column under mpirun: '{}' runs {}", f, why));
  if (out.analysis.every > 0)
    root.table("analysis").fail("every", fmt::format("no [analysis] under mpirun: the structure analysis runs {}", why));
}

}  // namespace

std::shared_ptr<Decomposition> decompose_run(const Config& root, const MdCase& md, const geometry::Box& box,
                                             double interaction_range, const RunOptions& options) {
  const parallel::Communicator world = parallel::Communicator::world();
  if (world.size() == 1 && options.rank_grid.empty()) return nullptr;
  const std::string why = fmt::format("on one rank only so far ({} ranks started{}; docs/parallel.md)", world.size(),
                                      options.rank_grid.empty() ? "" : ", --rank-grid given");
  refuse_undecomposed(root, md, box, why);
  const parallel::Dims3 given = options.rank_grid.empty() ? parallel::Dims3{0, 0, 0}
                                                          : parallel::parse_rank_grid(options.rank_grid);
  const parallel::Dims3 dims = md_rank_grid(box, interaction_range, world.size(), given);
  return std::make_shared<Decomposition>(world, dims, box, interaction_range);
}

void deal_out_checkpoint(Simulation& sim, const std::shared_ptr<Decomposition>& domain) {
  Atoms& atoms = sim.atoms;
  std::unordered_map<std::int64_t, std::pair<Vec3, Vec3>> now;  // position and force by id
  for (std::size_t i = 0; i < atoms.nlocal; ++i) now.emplace(atoms.id[i], std::pair{atoms.x[i], atoms.f[i]});
  const std::vector<Vec3> x_rebuild = sim.positions_at_rebuild();
  std::copy(x_rebuild.begin(), x_rebuild.end(), atoms.x.begin());
  keep_own_atoms(*domain, atoms);  // by the rebuild positions, which lie in the box: no migration
  sim.domain = domain;
  const std::int64_t rebuilds = sim.rebuilds, since = sim.steps_since_rebuild;
  sim.rebuild();
  for (std::size_t i = 0; i < atoms.nlocal; ++i) atoms.x[i] = now.at(atoms.id[i]).first;
  atoms.update_ghost_positions(sim.box);
  evaluate_forces(atoms, *sim.potential, sim.list, sim.forces, false);
  for (std::size_t i = 0; i < atoms.nlocal; ++i) atoms.f[i] = now.at(atoms.id[i]).second;
  sim.rebuilds = rebuilds;
  sim.steps_since_rebuild = since;
}

std::optional<Simulation> gather_simulation(const Simulation& sim) {
  const Decomposition& domain = *sim.domain;
  Atoms atoms = gather_atoms(domain, sim.atoms);
  const std::vector<Vec3> forces = gather_by_id(domain, sim.atoms, sim.atoms.f);
  std::vector<Vec3> x_rebuild = gather_by_id(domain, sim.atoms, sim.positions_at_rebuild());
  if (!domain.comm().is_root()) return std::nullopt;
  std::copy(forces.begin(), forces.end(), atoms.f.begin());
  std::optional<Simulation> whole;
  whole.emplace(sim.box, std::move(atoms), nullptr, sim.dt, sim.skin);
  whole->shrink_margin = sim.shrink_margin;
  whole->step = sim.step;
  whole->time = sim.time;
  whole->rebuilds = sim.rebuilds;
  whole->steps_since_rebuild = sim.steps_since_rebuild;
  whole->set_rebuild_reference(std::move(x_rebuild), sim.box_at_rebuild());
  return whole;
}

}  // namespace shockfield::md
