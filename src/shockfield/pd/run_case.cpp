#include "shockfield/pd/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <variant>

#include "shockfield/core/error.hpp"
#include "shockfield/core/interrupt.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/core/progress.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_session.hpp"
#include "shockfield/pd/bar_impact.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/case_file.hpp"
#include "shockfield/pd/checkpoint.hpp"
#include "shockfield/pd/homogeneous_case.hpp"
#include "shockfield/pd/run_output.hpp"

namespace shockfield::pd {

namespace fs = std::filesystem;

namespace {

// Resolved values the run echoes under [derived], common to every material.
void derive_common(const Config& root, const PdCase& c, const Simulation& sim, double dt) {
  root.derive("points", static_cast<long long>(sim.cloud().size()));
  root.derive("bonds", static_cast<long long>(sim.family().bonds()));
  root.derive("horizon_m", c.body.horizon());
  root.derive("stable_time_step_s", sim.stable_step());
  root.derive("time_step_s", dt);
  root.derive("steps", static_cast<long long>(std::ceil(c.solver.end_time / dt - 1e-9)));
  root.derive("openmp_threads", static_cast<long long>(omp_get_max_threads()));
}

// J2: the uniaxial-strain wave speeds and stresses of the symmetric impact (seed 004 §3.1:
// c_L = √(M/ρ), c_p = √(K/ρ), σ_HEL = M·Y/(2G), elastic state ρ c_L v/2, two-wave plastic state
// σ_HEL + ρ c_p (v/2 − u_HEL)).
void derive_material(const Config& root, const PdCase& c, const std::vector<SmallStrainJ2>& materials,
                     const std::vector<int>&) {
  const SmallStrainJ2& m = materials.front();
  const double rho = m.density, g = m.deviatoric.shear_modulus, modulus = m.longitudinal_modulus();
  const double cl = std::sqrt(modulus / rho), cp = std::sqrt(m.bulk / rho);
  const double hel = modulus * m.deviatoric.yield_stress0 / (2.0 * g), u_hel = hel / (rho * cl);
  const double up = 0.5 * c.impact_speed;
  root.derive("elastic_wave_speed_m_s", cl);
  root.derive("plastic_wave_speed_m_s", cp);
  root.derive("hel_Pa", hel);
  root.derive("impact_axial_stress_Pa", up <= u_hel ? rho * cl * up : hel + rho * cp * (up - u_hel));
}

// Crystal: the elastic wave speed along x and the Schmid factor of a single crystal, the grain
// count of a polycrystal.
void derive_material(const Config& root, const PdCase& c, const std::vector<CrystalMaterial>& materials,
                     const std::vector<int>& grain) {
  if (std::get<CrystalSpec>(c.material).polycrystal) {
    root.derive("grains", static_cast<long long>(*std::max_element(grain.begin(), grain.end()) + 1));
    return;
  }
  const CrystalMaterial& m = materials.front();
  root.derive("elastic_wave_speed_m_s", std::sqrt(m.longitudinal_modulus() / m.density));
  if (m.aggregate.orientations.size() == 1)
    root.derive("schmid_factor", schmid_factor_along_x(m));
  else
    root.derive("taylor_grains", static_cast<long long>(m.aggregate.orientations.size()));
}

// The materials of the points (one when all share it) and the grain of each point.
std::pair<std::vector<SmallStrainJ2>, std::vector<int>> point_materials(const SmallStrainJ2& m,
                                                                        const PointCloud& cloud) {
  return {{m}, std::vector<int>(cloud.size(), 0)};
}
std::pair<std::vector<CrystalMaterial>, std::vector<int>> point_materials(const CrystalSpec& spec,
                                                                          const PointCloud& cloud) {
  CrystalBody body = crystal_body(spec, cloud);
  return {std::move(body.materials), std::move(body.grain)};
}

// A force model as the driver sees it: the model, its density, what the output reads of it, its
// state for checkpoints and its [derived] values.
struct ModelRun {
  std::unique_ptr<ForceModel> force;
  double density = 0.0;
  PointFields fields;
  std::function<std::vector<double>()> save;
  /// Takes back the saved state.
  std::function<void(const std::vector<double>&)> restore;
  std::function<void(const Config&)> derive;
};

// Correspondence (J2 or crystal): σ, the plastic measure and the material state of every point.
template <class Spec>
ModelRun make_model(const Config& root, const PdCase& c, const Spec& spec, const PointCloud& cloud,
                    const Family& family) {
  auto [materials, grain] = point_materials(spec, cloud);
  using Force = CorrespondenceForce<typename std::decay_t<decltype(materials)>::value_type>;
  std::unique_ptr<Force> model;
  try {
    model = std::make_unique<Force>(cloud, family, materials, c.body.influence, c.solver.options);
  } catch (const InputError& e) {
    root.table("body").fail("horizon_factor", e.what());
  }
  Force& force = *model;
  ModelRun run{nullptr,
               materials.front().reference_density(),
               {[&force](std::size_t i) { return force.stress(i); },
                [&force](std::size_t i) { return plastic_measure(force.state(i)); }, grain, {}},
               [&force] { return force.saved_state(); },
               [&force](const std::vector<double>& state) { force.restore_state(state); },
               [&c, materials = std::move(materials), grain = grain](const Config& r) {
                 derive_material(r, c, materials, grain);
               }};
  run.force = std::move(model);
  return run;
}

// PMB or LPS: no stress nor plastic measure (NaN columns), damage only; the checkpoint keeps the
// bonds' intact flags and the points' critical stretches (BondForce::saved_state).
template <class Law>
ModelRun make_model(const Config&, const PdCase& c, const BondSpec<Law>& spec, const PointCloud& cloud,
                    const Family& family) {
  auto model = std::make_unique<BondForce<Law>>(cloud, family, spec.law, c.body.influence, spec.damage);
  BondForce<Law>& force = *model;
  ModelRun run{nullptr,
               spec.density,
               {{}, {}, std::vector<int>(cloud.size(), 0), {}},
               [&force] { return force.saved_state(); },
               [&force](const std::vector<double>& state) { force.restore_state(state); },
               {}};
  run.force = std::move(model);
  return run;
}

void run_with(const Config& root, const RunOptions& options, const PdCase& c, const PointCloud& cloud,
              const Family& family, ModelRun m) {
  Simulation sim(cloud, family, std::move(m.force), {m.density});
  const double stable = sim.stable_step();
  const double dt = c.solver.time_step.value_or(c.solver.safety * stable);
  if (dt > stable)
    root.table("solver").fail("time_step", fmt::format("{} s is beyond the stable step {} s of this body and horizon "
                                                       "(velocity-Verlet would blow up); lower it or drop it",
                                                       dt, stable));
  derive_common(root, c, sim, dt);
  if (m.derive) m.derive(root);
  if (options.validate_only) {
    std::printf("%s: valid pd case (%zu points, %zu bonds, dt %.3g s)\n", options.case_file.string().c_str(),
                cloud.size(), family.bonds(), dt);
    return;
  }

  RunSession run = open_run_session(root, options, "pd",
                                    fmt::format("{} points, {} bonds, {}D", cloud.size(), family.bonds(), c.body.dim));
  const fs::path& folder = run.folder;
  const fs::path& checkpoint = run.checkpoint;
  Logger& log = run.log;

  OutputCounters counters;
  std::optional<ResumePoint> resume;
  if (options.resume) {
    if (!fs::exists(checkpoint)) throw InputError(fmt::format("--resume: no checkpoint in '{}'", folder.string()));
    std::vector<double> state;
    counters = read_checkpoint(checkpoint, sim, state);
    m.restore(state);
    resume = ResumePoint{sim.step_count(), counters.profiles};
    log.info("resumed from {} at step {}, t = {} s", checkpoint.string(), sim.step_count(), sim.time());
  } else {
    set_impact_velocity(sim, c.impact_speed);
    sim.setup();
  }
  m.fields.damage = [&sim] { return sim.model().damage(); };
  RunOutput output(folder, std::move(m.fields), resume);

  // Rows at the first step at or past k·interval (the step is fixed).
  const double tol = 1e-9 * dt;
  auto write_due = [&] {
    const double t = sim.time() + tol;
    write_due_frames(counters.series, c.output.series_interval, t, [&](auto) { output.write_series(sim); });
    write_due_frames(counters.profiles, c.output.profile_interval, t, [&](auto k) { output.write_profile(sim, k); });
  };
  auto save = [&] { write_checkpoint(checkpoint, sim, m.save(), counters); };

  clear_stop_request();
  install_stop_handlers();
  if (!options.resume) write_due();
  const long long first = sim.step_count();
  const auto remaining = static_cast<long long>(std::ceil((c.solver.end_time - sim.time()) / dt - 1e-9));
  Progress progress("pd", first, remaining, !options.quiet);
  log.info("running to t = {} s with dt = {} s ({} of the stable {} s; the last step lands on end_time)",
           c.solver.end_time, dt, dt / stable, stable);
  try {
    while (sim.time() < c.solver.end_time - tol) {
      sim.step(std::min(dt, c.solver.end_time - sim.time()));
      write_due();
      progress.update(sim.step_count());
      if (c.output.checkpoint_every > 0 && sim.step_count() % c.output.checkpoint_every == 0) save();
      if (stop_requested() || (options.stop_after > 0 && sim.step_count() - first == options.stop_after)) {
        progress.finish(sim.step_count());
        save();
        log.info("stopped at step {} (t = {} s): checkpoint written to {}", sim.step_count(), sim.time(),
                 checkpoint.string());
        throw StopRequested(fmt::format("stopped at step {}; continue with: shockfield run {} --output {} --resume",
                                        sim.step_count(), options.case_file.string(), folder.string()));
      }
    }
  } catch (const RunError& e) {
    log.info("run stopped: {}", e.what());
    output.write_profile(sim, counters.profiles);
    log.info("the output written so far is kept in {}; the points at the failure: profiles/profile_{}.csv",
             folder.string(), counters.profiles);
    throw;
  }
  progress.finish(sim.step_count());
  if (c.output.profile_interval == 0.0) output.write_profile(sim, counters.profiles++);
  save();
  const Vec3 p = sim.momentum();
  log.info("finished: t = {} s after {} steps ({:.3g} bond-updates/s); kinetic energy {} J, momentum ({}, {}, {})",
           sim.time(), sim.step_count(), progress.rate(sim.step_count()) * static_cast<double>(family.bonds()),
           sim.kinetic_energy(), p[0], p[1], p[2]);
}

}  // namespace

void run_case(const Config& root, const RunOptions& options) {
  if (root.has("homogeneous")) return run_homogeneous(root, options);
  const PdCase c = read_pd_case(root);
  root.check_unknown_keys();
  const PointCloud cloud = lattice_cloud(c.body.dim, c.body.counts, c.body.spacing);
  const Family family = build_family(cloud, c.body.horizon(), c.body.correction);
  std::visit([&](const auto& m) { run_with(root, options, c, cloud, family, make_model(root, c, m, cloud, family)); },
             c.material);
}

}  // namespace shockfield::pd
