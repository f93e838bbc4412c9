#pragma once
// The plug-in interface of a simulation method (md, mpm, pd, dbm, ...). A method reads its case,
// builds its simulation and advances it one step at a time; the run driver (run_driver.hpp) owns
// everything around that: the run folder, the session log, stop handlers and --stop-after, the
// checkpoint schedule, --resume, the progress line, the thermo table, the performance summary
// and the exit codes. docs/architecture.md says how a new method is added.
//
// Why an abstract class and not a C++20 concept: the method is chosen at run time by the case
// file's `method` name from an explicit registry, so the driver needs one type for all of them;
// a handful of virtual calls per step costs nothing next to a step (thousands of atoms, cells or
// particles). The hot loops inside a method stay templates on their models.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/json.hpp"
#include "shockfield/core/logger.hpp"
#include "shockfield/core/run_options.hpp"

namespace shockfield {

/// What a method may use once the run folder exists.
struct RunContext {
  std::filesystem::path folder;
  std::filesystem::path checkpoint;  ///< folder/checkpoint.h5
  Logger& log;
  const RunOptions& options;
};

/// One per-particle array of a method's state, for a program that steps the method itself and
/// reads or writes its state between steps (the Python module's numpy views, docs/python.md):
/// `rows` × `columns` values of `type`, row-major at `data`, owned by the method; a grid's field
/// gives its `shape` instead (slowest index first, x fastest: (nz, ny, nx) in 3D). A member of an
/// array of structs (one value per particle inside its state) gives `shape` and `strides` too.
struct StateArray {
  enum class Type { f64, i32, i64 };
  std::string name;  ///< "positions", "velocities", ...
  void* data = nullptr;
  std::size_t rows = 0, columns = 1;
  Type type = Type::f64;
  std::string unit;  ///< "Å", "m/s", "" for indices
  std::vector<std::size_t> shape;  ///< empty: rows × columns (or rows when columns = 1)
  std::vector<std::size_t> strides;  ///< bytes from one index to the next along each of `shape`; empty: row-major
};

/// A wall-time share a method measured itself (e.g. MD's force and neighbour phases).
struct PhaseTime {
  std::string name;
  double seconds = 0.0;
};

class Method {
 public:
  virtual ~Method() = default;

  // ---- Before the run folder exists: a method's factory reads and validates the whole case,
  // derives its values (Config::derive) and checks the unknown keys; --check stops after it.
  /// The method's name as in the case file ("md").
  virtual std::string name() const = 0;
  /// The size of the run for the log header ("12800 atoms").
  virtual std::string size_text() const = 0;
  /// What --check prints after "CASE: valid " ("md case (4000 atoms, 2 stage(s))").
  virtual std::string check_text() const = 0;

  // ---- With the run folder.
  /// A fresh run: the initial state and the first scheduled outputs.
  virtual void start(RunContext& run) = 0;
  /// A resumed run: the state from run.checkpoint, the outputs reopened at it.
  virtual void resume(RunContext& run) = 0;
  /// True when no step is left.
  virtual bool finished() const = 0;
  /// One step (a method with stages also moves between its stages here).
  virtual void advance() = 0;
  /// Throws a RunError naming what went wrong (NaN, negative density, ...), if anything did.
  virtual void check_health() {}
  /// The outputs due after the step just made.
  virtual void write_outputs() = 0;
  /// The step counter (continues across a resume).
  virtual std::int64_t step() const = 0;
  /// Where the run is besides its step, for log lines: ", t = 1e-08 s" or " (stage 'shock', ...)".
  virtual std::string position() const = 0;
  /// Fraction of the run done (simulated time / end time), or a negative value to let the
  /// progress line count steps against steps_left().
  virtual double fraction_done() const { return -1.0; }
  /// Steps left (an estimate for adaptive steps).
  virtual std::int64_t steps_left() const = 0;
  /// The checkpoint schedule: every ... steps; 0: only at the end and on a stop.
  virtual std::int64_t checkpoint_every() const = 0;
  virtual void write_checkpoint(const std::filesystem::path& file) = 0;
  /// Output written when the run stops on request (before the checkpoint); returns what it wrote
  /// for the log ("the state in profiles/profile_3.csv"), or "".
  virtual std::string write_stop_state() { return ""; }
  /// Output written when a step failed (RunError); returns what it wrote for the log, or "".
  virtual std::string write_failure_state() { return ""; }
  /// The outputs of the end of the run (before the last checkpoint).
  virtual void write_final_outputs() {}
  /// The closing log lines with the method's results; `steps_per_second` of this session.
  virtual void log_results(double steps_per_second) = 0;

  // ---- Thermo table and performance summary.
  /// Column names and the values at the current step (LAMMPS-like, docs/architecture.md).
  virtual std::vector<std::string> thermo_columns() const = 0;
  virtual std::vector<double> thermo_values() const = 0;
  /// A thermo row every ... steps (> 0; the same for a resumed run: output_schedule.hpp's
  /// thermo_interval).
  virtual std::int64_t thermo_every() const = 0;
  /// Whether the method writes thermo.csv itself (else the driver writes the thermo table there).
  virtual bool writes_thermo_csv() const { return false; }
  /// Work per step and its unit for the rates of the performance summary: (12800, "atom").
  virtual double work_items() const = 0;
  virtual std::string work_item_name() const = 0;
  /// Simulated time per step in ns for MD's ns/day (0: not reported).
  virtual double ns_per_step() const { return 0.0; }
  /// Phases the method timed itself (seconds, cumulated over the session).
  virtual std::vector<PhaseTime> phase_times() const { return {}; }

  // ---- In-process access (RunDriver's caller between steps).
  /// The per-particle arrays (empty: the method offers none). Their storage stays in place for
  /// the rest of the run: a method whose arrays can grow reserves their largest size here.
  virtual std::vector<StateArray> state_arrays() { return {}; }

  // ---- summary.json and --resume.
  /// Simulated time and its unit ("ps", "s", "1" for lattice units).
  virtual double time() const = 0;
  virtual std::string time_unit() const = 0;
  /// The method's key results for summary.json's "results" (docs/summary-json.md), at any point
  /// of the run (also when it stopped or failed).
  virtual Json results() const = 0;
  /// Case keys (key_matches patterns, case_diff.hpp) that --resume may find changed: the end of
  /// the run and the output schedule. Any other change is refused.
  virtual std::vector<std::string> resume_safe_keys() const = 0;
};

/// Reads, validates and derives a method's case (before the run folder exists).
using MethodFactory = std::function<std::unique_ptr<Method>(const Config& root, const RunOptions& options)>;

}  // namespace shockfield
