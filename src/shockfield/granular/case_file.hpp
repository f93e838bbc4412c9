#pragma once
// The granular case file (method = "granular"), read and validated completely before anything
// runs: [chain], [wall], [impulse], [[impurity]], [run], [output] (every key in docs/granular.md).
// Every value goes through Config, so an error names the file, the key and its line; a radius
// that makes no grain, initial grains overlapping beyond the static equilibrium (a negative
// gap) and a time step above the stable step are refused here. SI units.
#include <cstddef>
#include <optional>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/granular/chain.hpp"
#include "shockfield/granular/simulation.hpp"

namespace shockfield::granular {

struct RunSpec {
  double end_time = 0.0;            ///< [s]
  std::optional<double> time_step;  ///< [s]; else safety × the stable step
  double safety = 0.05;
  double stable_step = 0.0;         ///< derived [s]
};

struct OutputSpec {
  OutputIntervals schedule;           ///< series (thermo rows), checkpoint_every; field_interval = space–time rows
  std::vector<std::size_t> probes;    ///< grains whose velocity, force and overlap are written
  double probe_interval = 0.0;        ///< [s]; default: the time step
  long long spacetime_stride = 1;     ///< every ... grain in the space–time field
  double signal_interval = 0.0;       ///< [s] signal measurements; 0: none
  /// grains g whose energy above (grains [0, g) and their contacts, Simulation::excess_energy)
  /// is written with every series row
  std::vector<std::size_t> energy_above;
};

struct GranularCase {
  ChainSpec chain;
  Impulse impulse;
  RunSpec run;
  OutputSpec output;
};

/// Reads the case and derives the stable step and time step (recorded under [derived]).
GranularCase read_granular_case(const Config& root);

/// The simulation of a case read by read_granular_case.
Simulation build_simulation(const GranularCase& c);

}  // namespace shockfield::granular
