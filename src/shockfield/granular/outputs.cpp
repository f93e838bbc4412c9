#include "shockfield/granular/outputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/granular/signal.hpp"

namespace shockfield::granular {
namespace {

// "time_s", then "<prefix>_<g><suffix>" per grain g (suffix: the unit, "_J", or none).
std::vector<std::string> grain_columns(const std::vector<std::size_t>& grains, const char* prefix,
                                       const char* suffix = "") {
  std::vector<std::string> out{"time_s"};
  for (std::size_t g : grains) out.push_back(fmt::format("{}_{}{}", prefix, g, suffix));
  return out;
}

// The force below grain i (contact (i, i+1), or the wall's for the last grain) and its overlap.
double force_below(const Simulation& sim, std::size_t i) {
  return i + 1 < sim.size() ? sim.contact_force()[i] : sim.wall_force();
}
double overlap_below(const Simulation& sim, std::size_t i) {
  return i + 1 < sim.size() ? sim.overlap(i) : (sim.chain().has_wall ? sim.wall_overlap() : 0.0);
}

}  // namespace

std::vector<std::string> RunOutputs::thermo_columns() {
  return {"time_s", "step", "kinetic_J", "potential_J", "total_J", "external_work_J", "signal_depth_m"};
}

std::vector<double> RunOutputs::thermo_values(const Thermo& t) {
  return {t.time, static_cast<double>(t.step), t.kinetic, t.potential, t.total, t.external_work, t.signal_depth};
}

io::ParticleFrame RunOutputs::grain_frame(const Simulation& sim, const std::vector<int>& types) {
  const std::size_t n = sim.size();
  const Chain& chain = sim.chain();
  std::vector<double> xyz(3 * n), velocity(3 * n), force(3 * n), displacement(3 * n), contact(n), overlap(n), grain(n);
  const auto up = [](double down) { return 0.0 - down; };  // (not −x: no "-0" in the files)
  for (std::size_t i = 0; i < n; ++i) {  // along z, up: the chain's depth and "+ down" turned over
    xyz[3 * i + 2] = up(sim.position(i));
    velocity[3 * i + 2] = up(sim.velocity()[i]);
    force[3 * i + 2] = up(sim.force()[i]);
    displacement[3 * i + 2] = up(sim.displacement()[i]);
    contact[i] = force_below(sim, i);
    overlap[i] = overlap_below(sim, i);
    grain[i] = static_cast<double>(i);
  }
  return {sim.step_count(), sim.time(), std::move(xyz), types,
          *std::max_element(chain.radius.begin(), chain.radius.end()),
          {{"velocity", 3, std::move(velocity), "m/s"},
           {"force", 3, std::move(force), "N"},
           {"displacement", 3, std::move(displacement), "m"},
           {"contact_force", 1, std::move(contact), "N"},
           {"overlap", 1, std::move(overlap), "m"},
           {"radius", 1, chain.radius, "m"},
           {"mass", 1, chain.mass, "kg"},
           {"grain", 1, std::move(grain), "1", true}}};
}

RunOutputs::RunOutputs(const std::filesystem::path& folder, const GranularCase& c, const Simulation& sim,
                       long long last_step, const double* resume_from)
    : spec_(c.output), types_(sim.size(), 1) {
  for (std::size_t k = 0; k < c.chain.impurities.size(); ++k)
    types_[static_cast<std::size_t>(c.chain.impurities[k].index)] = 2 + static_cast<int>(k);
  if (spec_.schedule.profile_interval > 0)
    grains_ = io::ParticleOutput(folder, folder / "profiles", "grains", spec_.schedule.vtk, spec_.schedule.dumps,
                                 io::step_digits(last_step), resume_from);
  series_ = io::CsvWriter(folder / "series.csv", thermo_columns(), resume_from);
  if (!spec_.energy_above.empty())
    energy_above_ = io::CsvWriter(folder / "energy_above.csv", grain_columns(spec_.energy_above, "energy_above", "_J"), resume_from);
  if (!spec_.probes.empty()) {
    std::vector<std::string> cols{"time_s"};
    for (std::size_t g : spec_.probes)
      for (const char* q : {"velocity_{}_m_s", "force_{}_N", "overlap_{}_m"}) cols.push_back(fmt::format(fmt::runtime(q), g));
    probes_ = io::CsvWriter(folder / "probes.csv", cols, resume_from);
  }
  if (spec_.schedule.field_interval > 0) {
    for (std::size_t g = 0; g < sim.size(); g += static_cast<std::size_t>(spec_.spacetime_stride)) field_grains_.push_back(g);
    force_field_ = io::CsvWriter(folder / "spacetime_force.csv", grain_columns(field_grains_, "force", "_N"), resume_from);
    velocity_field_ = io::CsvWriter(folder / "spacetime_velocity.csv", grain_columns(field_grains_, "velocity", "_m_s"), resume_from);
  }
  if (spec_.signal_interval > 0)
    signal_ = io::CsvWriter(folder / "signal.csv", {"time_s", "grain", "depth_m", "velocity_m_s", "force_N", "width_grains"}, resume_from);
}

void RunOutputs::write_due(const Simulation& sim, OutputCounters& n) {
  const double t = sim.time();
  write_due_frames(n.series, spec_.schedule.series_interval, t, [&](auto) {
    series_.row(thermo_values(sim.thermo()));
    if (energy_above_.is_open()) {
      std::vector<double> row{t};
      for (std::size_t g : spec_.energy_above) row.push_back(sim.excess_energy(0, g));
      energy_above_.row(row);
    }
  });
  if (probes_.is_open())
    write_due_frames(n.probes, spec_.probe_interval, t, [&](auto) {
      std::vector<double> row{t};
      for (std::size_t g : spec_.probes) row.insert(row.end(), {sim.velocity()[g], force_below(sim, g), overlap_below(sim, g)});
      probes_.row(row);
    });
  if (force_field_.is_open())
    write_due_frames(n.spacetime, spec_.schedule.field_interval, t, [&](auto) {
      std::vector<double> force{t}, velocity{t};
      for (std::size_t g : field_grains_) {
        force.push_back(force_below(sim, g) - sim.rest_force(g));
        velocity.push_back(sim.velocity()[g]);
      }
      force_field_.row(force);
      velocity_field_.row(velocity);
    });
  if (spec_.schedule.profile_interval > 0)
    write_due_frames(n.profiles, spec_.schedule.profile_interval, t,
                     [&](auto k) { grains_.write(grain_frame(sim, types_), k); });
  if (signal_.is_open())
    write_due_frames(n.signal, spec_.signal_interval, t, [&](auto) {
      const SignalFront f = measure_signal(sim);
      if (f.valid) signal_.row({t, f.sample.position, f.sample.depth, f.sample.velocity, f.sample.force, f.sample.width});
    });
}

std::vector<std::pair<std::string, double>> summary_results(const Simulation& sim, double initial_total) {
  const Thermo t = sim.thermo();
  double max_speed = 0.0, max_force = sim.wall_force();
  for (double v : sim.velocity()) max_speed = std::max(max_speed, std::abs(v));
  for (double f : sim.contact_force()) max_force = std::max(max_force, f);
  const double scale = std::max(std::abs(initial_total), std::abs(t.external_work));
  return {{"time", t.time},
          {"steps", static_cast<double>(t.step)},
          {"kinetic", t.kinetic},
          {"potential", t.potential},
          {"total", t.total},
          {"energy_error", scale > 0 ? std::abs(t.total - t.external_work - initial_total) / scale : 0.0},
          {"signal_depth", t.signal_depth},
          {"max_speed", max_speed},
          {"max_contact_force", max_force}};
}

}  // namespace shockfield::granular
