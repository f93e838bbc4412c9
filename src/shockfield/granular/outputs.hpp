#pragma once
// The scheduled outputs of a granular run, CSV files in the run folder (columns in
// docs/granular.md):
//   series.csv                  thermo rows (time, step, energies, signal depth) every series_interval;
//   energy_above.csv            with each series row, the energy above the equilibrium held by grains
//                               [0, g) and their contacts for each chosen g (energy_above; the
//                               energy reflected above an impurity is this minus the same column of
//                               a run without the impurity, docs/granular.md);
//   probes.csv                  velocity, force and overlap of the chosen grains every probe_interval;
//   spacetime_force.csv,
//   spacetime_velocity.csv      one row per field_interval: the dynamic contact force F_k − F⁰_k and
//                               the grain velocity of every spacetime_stride-th grain (grain index × time);
//   signal.csv                  the leading peak's position, depth, velocity, force and width
//                               (signal.hpp) every signal_interval;
//   profiles/grains_<k>.vtp     every profile_interval, every grain as a VTK vertex, indexed by
//                               profiles/grains.pvd, and with dump = true the same frame as a LAMMPS
//                               dump dumps/dump.<step>.lammpstrj (io/particle_frame; the column
//                               stands along z, grain 0 on top: z = −depth).
// A row due at time k·interval is written at the first step at or past it (core/output_schedule).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "shockfield/granular/case_file.hpp"
#include "shockfield/granular/checkpoint.hpp"
#include "shockfield/granular/simulation.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/particle_frame.hpp"

namespace shockfield::granular {

class RunOutputs {
 public:
  /// Opens the files; with `resume_from`, keeps the rows up to that time (a resumed run).
  /// `last_step`: the run's last step (the digits of the dump names).
  RunOutputs(const std::filesystem::path& folder, const GranularCase& c, const Simulation& sim, long long last_step,
             const double* resume_from = nullptr);
  /// Writes every row due by sim.time(), advancing the counters.
  void write_due(const Simulation& sim, OutputCounters& counters);

  static std::vector<std::string> thermo_columns();
  static std::vector<double> thermo_values(const Thermo& t);
  /// Every grain now as a particle frame: positions (0, 0, −depth) [m]; velocity, force (net, on
  /// the grain) and displacement as vectors along z (+ up); contact_force and overlap of the
  /// contact below (the wall's for the last grain); radius, mass; grain (index, Int32); type 1,
  /// an impurity 2 + its place in the [[impurity]] list.
  static io::ParticleFrame grain_frame(const Simulation& sim, const std::vector<int>& types);

 private:
  OutputSpec spec_;
  std::vector<std::size_t> field_grains_;
  std::vector<int> types_;
  io::CsvWriter series_, energy_above_, probes_, force_field_, velocity_field_, signal_;
  io::ParticleOutput grains_;
};

/// A run's key results (for summary.json), by name: time, steps, kinetic, potential, total
/// energies [J], energy_error (|total − external work − initial total| / max(initial total,
/// external work), the integrator's error without damping), signal_depth [m], max_speed [m/s],
/// max_contact_force [N] (largest |v| and F_k now).
std::vector<std::pair<std::string, double>> summary_results(const Simulation& sim, double initial_total);

}  // namespace shockfield::granular
