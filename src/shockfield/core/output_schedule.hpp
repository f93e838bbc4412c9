#pragma once
// Output on a fixed time interval for methods whose time step varies: frame k is due at time
// k·interval and is written at the first step at or past it. `count` is the number of frames
// written so far (checkpointed by each method), so a resumed run continues the same schedule.
// Also the [output] keys of that schedule, shared by the mpm, pd and dbm case files.
#include <optional>

#include "shockfield/core/config.hpp"

namespace shockfield {

/// The output schedule of a time-stepping run ([output] keys of the same names).
struct OutputIntervals {
  double series_interval = 0.0;    ///< series.csv row every ... (default: end time / 100)
  double profile_interval = 0.0;   ///< line profiles every ...; 0: only the last
  double field_interval = 0.0;     ///< grid/particle frames every ...; 0: none
  long long checkpoint_every = 0;  ///< checkpoint every ... steps; 0: only at the end or on a stop
  long long thermo_every = 0;      ///< thermo table row every ... steps; 0: about ten rows per run
};

/// Which of the optional frame kinds a method writes (the keys of the others stay unknown, so a
/// case file that sets them is told so).
struct OutputKinds {
  bool profiles = false;
  bool fields = false;
};

/// Reads the schedule keys of [output] (absent table: the defaults), validated.
OutputIntervals read_output_intervals(const std::optional<Config>& output, double end_time,
                                      OutputKinds kinds);

/// The thermo table's interval: `requested` (thermo_every) if positive, else about ten rows over
/// the `total_steps` of the whole run (not of a resumed part, so a resumed run keeps the schedule).
long long thermo_interval(long long requested, long long total_steps);

/// Calls write(k) for every frame k = count, count+1, ... due by time `t`, advancing `count`.
/// An interval of 0 means no output.
template <class Count, class Write>
void write_due_frames(Count& count, double interval, double t, Write&& write) {
  if (interval <= 0) return;
  for (; static_cast<double>(count) * interval <= t; ++count) write(count);
}

}  // namespace shockfield
