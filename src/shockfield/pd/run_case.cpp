#include "shockfield/pd/run_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <variant>

#include "shockfield/core/derived_arrays.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_driver.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/core/state_array.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/pd/bar_impact.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/case_file.hpp"
#include "shockfield/pd/check_body.hpp"
#include "shockfield/pd/checkpoint.hpp"
#include "shockfield/pd/homogeneous_case.hpp"
#include "shockfield/pd/lattice_bonds.hpp"
#include "shockfield/pd/run_output.hpp"
#include "shockfield/pd/run_ranks.hpp"
#include "shockfield/parallel/method_mirror.hpp"

namespace shockfield::pd {

namespace fs = std::filesystem;

namespace {

// Resolved values the run echoes under [derived], common to every material.
void derive_common(const Config& root, const PdCase& c, double points, double bonds, const Simulation& sim,
                   double dt) {
  root.derive("points", static_cast<long long>(points));
  root.derive("bonds", static_cast<long long>(bonds));
  root.derive("horizon_m", c.body.horizon());
  root.derive("stable_time_step_s", sim.stable_step());
  root.derive("time_step_s", dt);
  root.derive("steps", static_cast<long long>(std::ceil(c.solver.end_time / dt - 1e-9)));
}

// J2: the uniaxial-strain wave speeds and stresses of the symmetric impact (Liu et al. 2025, §3.1:
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
  if (c.impact_speed > 0.0)
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
  std::function<ModelState()> save;
  /// Takes back the saved state.
  std::function<void(const ModelState&)> restore;
  std::function<void(const Config&)> derive;
  /// A bond model's BondForce::set_ghost_forward (MPI ranks); empty for the others.
  std::function<void(std::function<void(std::vector<double>&)>)> set_ghost_forward = {};
};

// Correspondence (J2 or crystal): σ, the plastic measure and the material state of every point.
template <class Spec>
ModelRun make_model(const Config& root, const PdCase& c, const Spec& spec, const PointCloud& cloud,
                    const Family& family, const std::vector<unsigned char>&) {
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
               [&force](const ModelState& state) { force.restore_state(state); },
               [&c, materials = std::move(materials), grain = grain](const Config& r) {
                 derive_material(r, c, materials, grain);
               }};
  run.force = std::move(model);
  return run;
}

// PMB or LPS: no stress nor plastic measure (NaN columns), damage only; the checkpoint keeps the
// bonds' intact flags and the points' critical stretches (BondForce::saved_state); the contact
// force has no state (contact.hpp). The bonds a pre-crack cuts are broken before the first step.
template <class Law>
ModelRun make_model(const Config&, const PdCase& c, const BondSpec<Law>& spec, const PointCloud& cloud,
                    const Family& family, const std::vector<unsigned char>& cut) {
  auto model = std::make_unique<BondForce<Law>>(cloud, family, spec.law, c.body.influence, spec.damage, spec.contact);
  if (!cut.empty()) model->break_bonds(cut);
  BondForce<Law>& force = *model;
  ModelRun run{nullptr,
               spec.density,
               {{}, {}, std::vector<int>(cloud.size(), 0), {}},
               [&force] { return force.saved_state(); },
               [&force](const ModelState& state) { force.restore_state(state); },
               {},
               [&force](std::function<void(std::vector<double>&)> forward) { force.set_ghost_forward(std::move(forward)); }};
  run.force = std::move(model);
  return run;
}

// The family a model runs on, without the bonds between separate bodies, and the bonds the
// pre-cracks cut (precrack.hpp): the bond models keep
// the cut bonds in their family (broken from step 0, counted in the damage); the correspondence
// models, which have no broken-bond state, run on the family without them.
struct CrackedFamily {
  Family family;
  std::vector<unsigned char> cut;  ///< per bond of `family`, for the bond models (empty: none cut)
  std::size_t cut_count = 0;       ///< bonds cut (each counted from both ends)
};

CrackedFamily cracked_family(const PdCase& c, const PointCloud& cloud, const BodySpec& body) {
  CrackedFamily f{build_family(cloud, body.horizon(), body.correction), {}, 0};
  // Separate bodies (regions.hpp) and the bodies of several point files first: their bonds to the
  // rest never existed.
  if (!body.part.empty() || std::any_of(c.regions.begin(), c.regions.end(), [](const LoadRegion& r) { return r.separate; }))
    f.family = without_bonds(f.family, bonds_between_bodies(cloud, f.family, c.regions, body.part));
  if (c.cracks.empty()) return f;
  std::vector<unsigned char> cut = cut_bonds(cloud, f.family, c.cracks);
  f.cut_count = static_cast<std::size_t>(std::count(cut.begin(), cut.end(), 1));
  const bool bond_model = std::holds_alternative<PmbSpec>(c.material) || std::holds_alternative<LpsSpec>(c.material);
  if (bond_model)
    f.cut = std::move(cut);
  else
    f.family = without_bonds(f.family, cut);
  return f;
}

// Peridynamics as a plug-in of the run driver: velocity-Verlet with a fixed step to end_time
// (the last step lands on it), rows and profiles at the first step at or past k·interval.
// Under mpirun (run_ranks.hpp) every rank builds the whole body and its model as in a serial run,
// starts or resumes it, then deals its points out to `local_` (owned points and ghosts), which the
// steps advance. Rank 0 runs the driver and announces each collective call to the other ranks,
// which serve() by making the same call (parallel/method_mirror.hpp); before anything reads the
// state (an output due, a thermo row, a checkpoint, the results) sync() gathers every rank's
// points into rank 0's whole body, from which the serial code writes every output.
class PdMethod final : public Method, public DerivedArrays {
 public:
  /// `options.validate_only` (shockfield run --check): the model is built on a sub-body
  /// (checked_body) and the sizes of the whole body are counted, not built.
  /// Under mpirun (or with --rank-grid) the body is then decomposed (run_ranks.hpp).
  PdMethod(const Config& root, const PdCase& c, const RunOptions& options)
      : c_(c), built_(options.validate_only ? checked_body(c_.body) : c_.body),
        cloud_(built_.cloud ? *built_.cloud : lattice_cloud(built_.dim, built_.counts, built_.spacing, built_.origin)),
        cracked_(cracked_family(c_, cloud_, built_)),
        model_(std::visit([&](const auto& m) { return make_model(root, c_, m, cloud_, cracked_.family, cracked_.cut); },
                          c_.material)),
        sim_(cloud_, cracked_.family, std::move(model_.force), {model_.density}), stable_(sim_.stable_step()),
        dt_(c_.solver.time_step.value_or(c_.solver.safety * stable_)), tol_(kOutputTimeTolerance * dt_) {
    if (dt_ > stable_)
      root.table("solver").fail("time_step", fmt::format("{} s is beyond the stable step {} s of this body and horizon "
                                                         "(velocity-Verlet would blow up); lower it or drop it",
                                                         dt_, stable_));
    derive_common(root, c_, points(), bonds(), sim_, dt_);
    if (model_.derive) model_.derive(root);
    model_.fields.damage = [this] { return sim_.model().damage(); };
    if (!options.validate_only) decompose(root, options);
  }
  ~PdMethod() override { announce(parallel::MethodCall::quit); }
  PdMethod(const PdMethod&) = delete;
  PdMethod& operator=(const PdMethod&) = delete;
  /// The ranks other than 0 of a decomposed run: their part of each of rank 0's calls.
  void serve() {
    if (mirror_) mirror_->serve(*this);
  }

  std::string name() const override { return "pd"; }
  std::string size_text() const override {
    const std::string text = fmt::format("{} points, {} bonds, {}D", cloud_.size(), cracked_.family.bonds(), c_.body.dim);
    if (!domain_) return text;
    const parallel::Dims3& d = domain_->dims();
    return fmt::format("{}, on {} ranks (rank grid {} x {} x {})", text, domain_->comm().size(), d[0], d[1], d[2]);
  }
  std::string check_text() const override {
    const auto& n = built_.counts;
    const std::string sub = whole() ? ""
        : fmt::format("; the stable step and the model checked on a {} x {} x {} sub-body{}{}", n[0], n[1], n[2],
                      polycrystal() ? " (its grains only)" : "",
                      holds_every_kind(built_, c_.body) ? "" : " (smaller than four horizons: the step is an estimate)");
    return fmt::format("pd case ({} points, {} bonds, dt {:.3g} s; {} when it runs{})", points(), bonds(), dt_,
                       memory_text(pd_bytes(points(), bonds())), sub);
  }

  void start(RunContext& run) override {
    announce(parallel::MethodCall::start);
    set_impact_velocity(sim_, c_.impact_speed);
    apply_regions(sim_, c_.regions, true);
    sim_.setup();
    deal_out_whole();
    open(run, std::nullopt);
    write_due();
  }
  // Under mpirun every rank reads the whole (serial) checkpoint, then deals it out.
  void resume(RunContext& run) override {
    if (mirror_) mirror_->announce_resume(run.checkpoint.string());
    ModelState state;
    counters_ = read_checkpoint(run.checkpoint, sim_, state);
    model_.restore(state);
    apply_regions(sim_, c_.regions, false);
    deal_out_whole();
    open(run, ResumePoint{sim_.step_count(), counters_.profiles, sim_.time()});
  }
  bool finished() const override { return !(clock().time() < c_.solver.end_time - tol_); }
  // A decomposed step that is not finite on some rank fails on every rank, with the serial message
  // raised from the gathered whole body.
  void advance() override {
    const double dt = std::min(dt_, c_.solver.end_time - clock().time());
    if (!domain_) return sim_.step(dt);
    announce(parallel::MethodCall::advance);
    int finite = 1;
    try {
      local_->step(dt);
    } catch (const RunError&) {
      finite = 0;
    }
    if (domain_->comm().min(finite) == 1) return;
    sync();
    sim_.throw_unstable(dt);
  }
  void write_outputs() override {
    announce(parallel::MethodCall::write_outputs);
    write_due();
  }
  std::int64_t step() const override { return clock().step_count(); }
  std::string position() const override { return fmt::format(" (t = {} s)", clock().time()); }
  std::int64_t steps_left() const override {
    return static_cast<std::int64_t>(std::ceil((c_.solver.end_time - clock().time()) / dt_ - 1e-9));
  }
  std::int64_t checkpoint_every() const override { return c_.output.checkpoint_every; }
  void write_checkpoint(const fs::path& file) override {
    announce(parallel::MethodCall::write_checkpoint);
    sync();
    if (writes()) pd::write_checkpoint(file, sim_, model_.save(), counters_);
  }
  std::string write_failure_state() override {
    output_->write_profile(sim_, counters_.profiles);
    return fmt::format("the points at the failure: profiles/profile_{}.csv", counters_.profiles);
  }
  void write_final_outputs() override {
    announce(parallel::MethodCall::write_final_outputs);
    if (c_.output.profile_interval != 0.0) return;
    sync();
    if (writes()) output_->write_profile(sim_, counters_.profiles);
    ++counters_.profiles;
  }
  void log_results(double steps_per_second) override {
    const Vec3 p = sim_.momentum();
    const char* per = units::si::per_missing_dimensions_text(c_.body.dim);
    log_->info("finished: t = {} s after {} steps ({:.3g} bond-updates/s); kinetic energy {} J{}, momentum ({}, {}, {}) "
               "kg m/s{}",
               sim_.time(), sim_.step_count(), steps_per_second * static_cast<double>(cracked_.family.bonds()),
               sim_.kinetic_energy(), per, p[0], p[1], p[2], per);
  }

  std::vector<std::string> thermo_columns() const override {
    return {"Step", "Time", "KinEng", "Px", "MeanDamage", "Broken"};
  }
  std::vector<double> thermo_values() const override {
    announce(parallel::MethodCall::thermo_values);
    return whole_values();
  }
  std::int64_t thermo_every() const override {
    return thermo_interval(c_.output.thermo_every, total_steps());
  }
  double work_items() const override { return static_cast<double>(cloud_.size()); }
  std::string work_item_name() const override { return "point"; }

  std::vector<StateArray> state_arrays() override {
    const std::size_t n = sim_.positions().size();
    return {state_array("positions", sim_.positions(), n, "m"), state_array("velocities", sim_.velocities(), n, "m/s"),
            state_array("force_densities", sim_.force_density(), n, "N/m³")};
  }
  // What the profiles write of each point, computed from the model rather than stored
  // (Simulation.fields() in Python): damage (the share of its bonds broken; 0 for correspondence
  // models) and, for models that have them, the Cauchy stress (n, 3, 3) and the plastic measure.
  std::vector<DerivedArray> derived_arrays() const override {
    const PointFields& f = model_.fields;
    std::vector<double> damage = f.damage();
    const std::size_t n = damage.size();
    std::vector<DerivedArray> arrays{{"damage", std::move(damage), {n}, "1"}};
    if (f.stress) {
      DerivedArray stress{"stress", std::vector<double>(9 * n), {n, 3, 3}, "Pa"};
      using RowMajor = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;  // [i, row, column], as the profiles
      for (std::size_t i = 0; i < n; ++i) Eigen::Map<RowMajor>(&stress.values[9 * i]) = f.stress(i);
      arrays.push_back(std::move(stress));
    }
    if (f.plastic) {
      DerivedArray plastic{"plastic", std::vector<double>(n), {n}, "1"};
      for (std::size_t i = 0; i < n; ++i) plastic.values[i] = f.plastic(i);
      arrays.push_back(std::move(plastic));
    }
    return arrays;
  }
  double time() const override { return clock().time(); }
  std::string time_unit() const override { return "s"; }
  Json results() const override {
    announce(parallel::MethodCall::results);
    const std::vector<double> values = whole_values();
    const Vec3 p = sim_.momentum();
    const std::string per = units::si::per_missing_dimensions_column(c_.body.dim);  // totals: per m in 2D
    return Json::object()
        .set("kinetic_energy_J" + per, values[2])
        .set("momentum_kg_m_s" + per, Json::Array{p[0], p[1], p[2]})
        .set("mean_damage", values[4])
        .set("damaged_points", static_cast<long long>(values[5]));
  }
  std::vector<std::string> resume_safe_keys() const override {
    return {"solver.end_time", "output.*_interval", "output.thermo_every", "output.checkpoint_every"};
  }

 private:
  // The thermo row of the whole body (after sync()).
  std::vector<double> whole_values() const {
    sync();
    const std::vector<double> damage = model_.fields.damage();
    double mean = 0.0, broken = 0.0;
    for (double d : damage) mean += d, broken += d > 0.0 ? 1.0 : 0.0;
    if (!damage.empty()) mean /= static_cast<double>(damage.size());
    return {static_cast<double>(sim_.step_count()), sim_.time(), sim_.kinetic_energy(), sim_.momentum()[0], mean,
            broken};
  }

  // ---- MPI ranks (run_ranks.hpp)
  void decompose(const Config& root, const RunOptions& options) {
    domain_ = decompose_run(root, c_, cloud_, cracked_.family, options);
    if (!domain_) return;
    std::vector<unsigned char> cut;
    if (!cracked_.cut.empty())
      for (std::size_t b : domain_->bond_origin()) cut.push_back(cracked_.cut[b]);
    local_model_ = std::visit(
        [&](const auto& m) { return make_model(root, c_, m, domain_->cloud(), domain_->family(), cut); }, c_.material);
    local_.emplace(domain_->cloud(), domain_->family(), std::move(local_model_.force), std::vector<double>{model_.density});
    const Decomposition* domain = domain_.get();
    local_model_.set_ghost_forward([domain](std::vector<double>& values) { domain->forward(values); });
    apply_regions(*local_, c_.regions, false);
    local_->add_hook(Simulation::Stage::before_force,
                     [domain](Simulation& s) { domain->forward(s.positions(), s.velocities()); });
    mirror_.emplace(domain_->comm());
  }
  void announce(parallel::MethodCall call) const {
    if (mirror_) mirror_->announce(call);
  }
  // Only rank 0 writes.
  bool writes() const { return !domain_ || domain_->comm().is_root(); }
  // The simulation the steps advance: the rank's points under mpirun, else the whole body.
  const Simulation& clock() const { return local_ ? *local_ : sim_; }
  // The whole body's state (on every rank, as started or resumed) to this rank's points.
  void deal_out_whole() {
    if (!domain_) return;
    deal_out(*domain_, sim_, *local_);
    local_model_.restore(local_state(*domain_, model_.save()));
    synced_step_ = sim_.step_count();
  }
  // Rank 0's whole body takes every rank's points, at most once a step. Collective.
  void sync() const {
    if (!domain_ || synced_step_ == local_->step_count()) return;
    ModelState whole = model_.save();
    gather_whole(*domain_, *local_, local_model_.save(), sim_, whole);
    if (writes()) model_.restore(whole);
    synced_step_ = local_->step_count();
  }

  void open(RunContext& run, std::optional<ResumePoint> resume) {
    log_ = &run.log;
    for (const std::string& note : c_.material_notes) log_->info("material file: {}", note);
    if (!c_.cracks.empty())
      log_->info("pre-cracks: {} crack(s) cut {} bonds ({})", c_.cracks.size(), cracked_.cut_count / 2,
                 cracked_.cut.empty() ? "left out of the correspondence family" : "broken from step 0");
    for (std::size_t k = 0; k < c_.regions.size(); ++k)
      log_->info("region {}: {}", k, describe(c_.regions[k], points_in(c_.regions[k].shape, cloud_).size()));
    if (writes()) output_.emplace(run.folder, c_.body.dim, model_.fields, c_.output, total_steps(), resume);
    if (!finished())
      log_->info("running to t = {} s with dt = {} s ({} of the stable {} s; the last step lands on end_time)",
                 c_.solver.end_time, dt_, dt_ / stable_, stable_);
  }
  long long total_steps() const { return static_cast<long long>(std::ceil(c_.solver.end_time / dt_ - 1e-9)); }
  void write_due() {
    const double t = clock().time() + tol_;
    write_due_frames(counters_.series, c_.output.series_interval, t, [&](auto) {
      sync();
      if (writes()) output_->write_series(sim_);
    });
    write_due_frames(counters_.profiles, c_.output.profile_interval, t, [&](auto k) {
      sync();
      if (writes()) output_->write_profile(sim_, k);
    });
  }

  // The whole body's points and bonds: as built, or for a --check sub-body counted
  // (pd/lattice_bonds.hpp; LatticeBonds.EqualsTheBuiltFamilyExactly).
  bool whole() const { return built_.counts == c_.body.counts; }
  double points() const {
    return whole() ? static_cast<double>(cloud_.size())
                   : static_cast<double>(c_.body.counts[0]) * c_.body.counts[1] * c_.body.counts[2];
  }
  double bonds() const {
    return whole() ? static_cast<double>(cracked_.family.bonds())
                   : lattice_bonds(c_.body.dim, c_.body.counts, c_.body.horizon_factor);
  }
  bool polycrystal() const {
    const auto* crystal = std::get_if<CrystalSpec>(&c_.material);
    return crystal && crystal->polycrystal;
  }

  PdCase c_;
  BodySpec built_;  ///< c_.body, or for --check its sub-body
  PointCloud cloud_;
  CrackedFamily cracked_;
  // mutable: the const reads of a decomposed run (a thermo row, the results) first gather the
  // whole body from the ranks (sync).
  mutable ModelRun model_;
  mutable Simulation sim_;
  double stable_, dt_, tol_;
  OutputCounters counters_;
  std::optional<RunOutput> output_;
  Logger* log_ = nullptr;
  std::shared_ptr<Decomposition> domain_;  ///< the rank grid under mpirun; null on one rank
  ModelRun local_model_;                   ///< the force model of this rank's points
  std::optional<Simulation> local_;        ///< this rank's points (owned, then ghosts)
  std::optional<parallel::MethodMirror> mirror_;
  mutable std::int64_t synced_step_ = -1;  ///< the step rank 0's whole body was last gathered at
};

}  // namespace

std::unique_ptr<Method> make_method(const Config& root, const RunOptions& options) {
  if (root.has("homogeneous")) {
    const int ranks = parallel::Communicator::world().size();
    if (ranks > 1 || !options.rank_grid.empty())
      throw InputError(fmt::format("{}: a [homogeneous] pd case runs on one rank only so far ({} ranks started); "
                                   "run it without mpirun (docs/parallel.md)",
                                   options.case_file.string(), ranks));
    return make_homogeneous_method(root, options);
  }
  const PdCase c = read_pd_case(root);
  root.check_unknown_keys();
  return std::make_unique<PdMethod>(root, c, options);
}

void serve_ranks(const Config& root, const RunOptions& options) {
  const std::unique_ptr<Method> method = make_method(root, options);  // bad input: thrown on every rank
  static_cast<PdMethod&>(*method).serve();
}

void run_case(const Config& root, const RunOptions& options) { run_method(root, options, &make_method); }

}  // namespace shockfield::pd
