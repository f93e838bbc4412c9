#include "shockfield/md/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/md/checkpoint.hpp"
#include "shockfield/md/diagnostics/hugoniot.hpp"
#include "shockfield/md/fixes/deform.hpp"
#include "shockfield/md/fixes/langevin.hpp"
#include "shockfield/md/fixes/nose_hoover.hpp"
#include "shockfield/md/fixes/nose_hoover_npt.hpp"
#include "shockfield/md/fixes/piston.hpp"
#include "shockfield/md/minimize.hpp"
#include "shockfield/md/potentials/registry.hpp"
#include "shockfield/md/run_output.hpp"
#include "shockfield/md/system_builder.hpp"
#include "shockfield/md/velocity.hpp"

namespace shockfield::md {

namespace fs = std::filesystem;

namespace {

struct Prepared {
  BuiltSystem system;
  std::unique_ptr<Potential> potential;
  MdCase md;
  std::vector<std::uint32_t> stage_groups, add_groups;
};

// Everything is read and checked here, before the run folder exists.
Prepared prepare(const Config& root, const RunOptions& options) {
  Prepared p;
  const fs::path case_dir = options.case_file.parent_path();
  p.system = build_system(root.table("system"));
  p.potential = potentials::make_potential(root.table("potential"), case_dir, p.system.atoms.ntypes());
  Atoms& atoms = p.system.atoms;
  for (int t = 0; t < atoms.ntypes(); ++t) {
    if (atoms.mass[t] > 0) continue;
    const auto m = potentials::potential_type_mass(*p.potential, t);
    if (!m) root.table("system").fail("masses", fmt::format("no mass for atom type {} (give masses = [...])", t + 1));
    atoms.mass[t] = *m;
  }
  p.potential->check_types(atoms);
  p.md = read_md_case(root);
  if (options.piston_speed) {  // `shockfield hugoniot --speeds`: one run per piston speed
    for (StageSpec& s : p.md.stages)
      if (s.piston) s.piston->speed = *options.piston_speed;
    root.derive("piston_speed_override_A_ps", *options.piston_speed);
  }
  const auto stages = root.tables("stage");
  for (std::size_t k = 0; k < p.md.stages.size(); ++k) {
    try {
      p.stage_groups.push_back(p.system.groups.find(p.md.stages[k].group));
    } catch (const InputError& e) {
      stages[k].fail("group", e.what());
    }
    StageSpec& s = p.md.stages[k];
    if (s.ensemble != "npt") continue;
    const geometry::Box& box = p.system.box;
    const char* key = s.pressure_dims ? "pressure_dims" : "ensemble";
    if (!s.pressure_dims) s.pressure_dims = std::array<bool, 3>{box.periodic(0), box.periodic(1), box.periodic(2)};
    for (int d = 0; d < 3; ++d)
      if ((*s.pressure_dims)[d] && !box.periodic(d))
        stages[k].fail(key, fmt::format("npt can only change periodic dimensions; {} is not periodic", "xyz"[d]));
    if (*s.pressure_dims == std::array<bool, 3>{false, false, false})
      stages[k].fail(key, "npt needs at least one periodic dimension to barostat");
  }
  for (const auto& add : p.md.velocity_adds) p.add_groups.push_back(p.system.groups.find(add.group));
  root.check_unknown_keys();

  const Vec3 l = p.system.box.length();
  root.derive("atoms", static_cast<long long>(atoms.nlocal));
  root.derive("atom_types", static_cast<long long>(atoms.ntypes()));
  root.derive("box_lengths_A", fmt::format("{} {} {}", l.x(), l.y(), l.z()));
  root.derive("potential_cutoff_A", p.potential->cutoff());
  double mass = 0;
  for (std::size_t i = 0; i < atoms.nlocal; ++i) mass += atoms.mass_of(i);
  root.derive("density_g_cc", mass / p.system.box.volume() * units::metal::amu_per_A3_to_g_per_cc);
  long long total = 0;
  for (const auto& s : p.md.stages) total += s.steps;
  root.derive("total_steps", total);
  root.derive("openmp_threads", static_cast<long long>(omp_get_max_threads()));
  return p;
}

void add_stage_fixes(Simulation& sim, const StageSpec& s, std::uint32_t group, std::uint64_t seed) {
  sim.fixes.clear();
  if (s.ensemble == "langevin") sim.fixes.push_back(std::make_unique<FixLangevin>(s.temperature, s.damping, seed, group));
  else if (s.ensemble == "nvt") sim.fixes.push_back(std::make_unique<FixNoseHoover>(s.temperature, s.damping, s.chain, group));
  else if (s.ensemble == "npt")
    sim.fixes.push_back(std::make_unique<FixNoseHooverNpt>(
        NptSettings{s.temperature, s.damping, s.pressure, s.pressure_damping, *s.pressure_dims, s.couple_iso, s.chain}, group));
  else sim.fixes.push_back(std::make_unique<FixNve>(group));
  if (s.piston) {
    const PistonSpec& p = *s.piston;
    const double start = p.position.value_or(p.side > 0 ? sim.box.lo[p.axis] : sim.box.hi[p.axis]);
    sim.fixes.push_back(std::make_unique<FixPiston>(p.axis, p.side, p.speed, start, sim.time));
  }
  if (s.deform_rate) sim.fixes.push_back(std::make_unique<FixDeform>(*s.deform_rate, sim.box, sim.time));
}

void report_hugoniot(const Simulation& sim, const RunOutput& output, const OutputSpec& spec,
                     const StageSpec& stage, const fs::path& folder, Logger& log) {
  const FixPiston* piston = nullptr;
  for (const auto& fix : sim.fixes)
    if (auto* p = dynamic_cast<const FixPiston*>(fix.get())) piston = p;
  if (!piston || spec.profile_every == 0) return;
  std::vector<Profile> frames;
  for (Profile& p : read_profiles_csv(output.profiles_file()))
    if (p.time >= piston->start_time() - 1e-12) frames.push_back(std::move(p));
  io::CsvWriter front(folder / fmt::format("shock_front_{}.csv", stage.name),
                      {"step", "time_ps", "front_A", "piston_A"});
  for (const Profile& p : frames)
    front.row({static_cast<double>(p.step), p.time, front_position(p, piston->axis(), piston->side(), piston->speed()),
               piston->wall(p.time)});
  const HugoniotState h = extract_hugoniot(frames, piston->axis(), piston->side(), piston->speed(),
                                           piston->start_position(), piston->start_time());
  const fs::path file = folder / fmt::format("hugoniot_{}.toml", stage.name);
  write_file_atomically(file, hugoniot_toml(h));
  log.info("[{}] Hugoniot: Us = {:.3f} km/s, Up = {:.3f} km/s (piston {:.3f}), P = {:.2f} GPa "
           "(rho0 Us Up = {:.2f}), rho = {:.3f} g/cc, T = {:.0f} K -> {}{}",
           stage.name, h.us, h.up, h.piston_speed, h.pressure, h.pressure_rh, h.density, h.temperature,
           file.string(), h.note.empty() ? "" : " (" + h.note + ")");
}

}  // namespace

void run_case(const Config& root, const RunOptions& options) {
  Prepared p = prepare(root, options);
  if (options.validate_only) {
    std::printf("%s: valid md case (%zu atoms, %zu stage(s))\n", options.case_file.string().c_str(),
                p.system.atoms.nlocal, p.md.stages.size());
    return;
  }
  RunSession run = open_run_session(root, options, "md", fmt::format("{} atoms", p.system.atoms.nlocal));
  const fs::path& folder = run.folder;
  const fs::path& checkpoint = run.checkpoint;
  Logger& log = run.log;

  Simulation sim(p.system.box, std::move(p.system.atoms), std::move(p.potential), p.md.timestep, p.md.skin);
  sim.neighbor_every = p.md.neighbor_every;
  sim.neighbor_delay = p.md.neighbor_delay;
  sim.neighbor_check = p.md.neighbor_check;
  CheckpointPosition start{};
  std::optional<std::int64_t> resume_step;
  if (options.resume) {
    if (!fs::exists(checkpoint)) throw InputError(fmt::format("--resume: no checkpoint in '{}'", folder.string()));
    start = read_checkpoint_header(checkpoint);
  } else {
    if (p.md.temperature) create_velocities(sim.atoms, *p.md.temperature, p.md.seed);
    for (std::size_t k = 0; k < p.md.velocity_adds.size(); ++k)
      add_velocity(sim.atoms, p.md.velocity_adds[k].velocity, p.add_groups[k]);
  }

  clear_stop_request();
  install_stop_handlers();
  std::int64_t steps_this_session = 0;
  std::optional<RunOutput> output;
  for (auto k = static_cast<std::size_t>(start.stage); k < p.md.stages.size(); ++k) {
    const StageSpec& stage = p.md.stages[k];
    add_stage_fixes(sim, stage, p.stage_groups[k], p.md.seed + k);
    std::int64_t done = 0;
    const bool resuming_here = options.resume && k == static_cast<std::size_t>(start.stage);
    if (resuming_here) {
      read_checkpoint(checkpoint, sim);
      resume_step = sim.step;
      done = start.stage_step;
      log.info("resumed from {} at step {} (stage '{}', {} of {} steps done)", checkpoint.string(), sim.step,
               stage.name, done, stage.steps);
    }
    if (!output) output.emplace(folder, p.md.output, resume_step);
    const auto want_per_atom = [&](std::int64_t step) { return output->needs_per_atom(step); };

    if (stage.ensemble == "minimize") {
      const MinimizeResult r = minimize_fire(sim, stage.minimize);
      const Vec3 l = sim.box.length();
      log.info("[{}] FIRE minimisation: {} after {} iterations; E = {:.10g} eV ({:.10g} eV/atom), max |f| = {:.3g} eV/A, "
               "P = {:.3g} {:.3g} {:.3g} bar, box {:.10g} {:.10g} {:.10g} A",
               stage.name, r.reason, r.iterations, r.energy, r.energy / static_cast<double>(sim.atoms.nlocal),
               r.max_force, r.pressure.x(), r.pressure.y(), r.pressure.z(), l.x(), l.y(), l.z());
      sim.setup(want_per_atom(sim.step));
      output->write(sim, true);
      if (stop_requested()) {
        write_checkpoint(checkpoint, sim, {static_cast<std::int64_t>(k), 0});
        throw StopRequested(fmt::format("stopped during minimisation '{}'; checkpoint {}", stage.name, checkpoint.string()));
      }
      continue;
    }

    if (!resuming_here) {
      sim.setup(want_per_atom(sim.step));
      for (auto& fix : sim.fixes) fix->setup(sim);
      output->write(sim, true);
    }
    log.info("[{}] {} steps, ensemble {}, dt = {} ps{}{}", stage.name, stage.steps, stage.ensemble, sim.dt,
             stage.piston ? fmt::format(", piston {} km/s", stage.piston->speed * units::metal::A_per_ps_to_km_per_s) : "",
             stage.deform_rate ? ", deforming" : "");
    Progress progress(stage.name, done, stage.steps - done, !options.quiet);
    try {
      for (; done < stage.steps; ++done) {
        sim.advance(want_per_atom);
        sim.check_health();
        output->write(sim);
        ++steps_this_session;
        const CheckpointPosition here{static_cast<std::int64_t>(k), done + 1};
        if (p.md.output.checkpoint_every > 0 && sim.step % p.md.output.checkpoint_every == 0)
          write_checkpoint(checkpoint, sim, here);
        progress.update(done + 1);
        if (stop_requested() || (options.stop_after > 0 && steps_this_session == options.stop_after)) {
          progress.finish(done + 1);
          write_checkpoint(checkpoint, sim, here);
          log.info("stopped at step {}: checkpoint written to {}", sim.step, checkpoint.string());
          throw StopRequested(fmt::format("stopped at step {}; continue with: shockfield run {} --output {} --resume",
                                          sim.step, options.case_file.string(), folder.string()));
        }
      }
    } catch (const RunError& e) {
      log.info("run stopped: {}", e.what());
      log.info("the output written so far is kept in {}", folder.string());
      throw;
    }
    progress.finish(stage.steps);
    log.info("[{}] done at step {} ({:.1f} steps/s, {} neighbour rebuilds)", stage.name, sim.step,
             progress.rate(stage.steps), sim.rebuilds);
    output->write(sim, true);
    report_hugoniot(sim, *output, p.md.output, stage, folder, log);
  }
  write_checkpoint(checkpoint, sim, {static_cast<std::int64_t>(p.md.stages.size()), 0});
  io::write_data(folder / "final.data", sim.box, sim.atoms);
  log.info("finished: {} steps; final configuration in {}", sim.step, (folder / "final.data").string());
}

}  // namespace shockfield::md
