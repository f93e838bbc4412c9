#pragma once
// Output on a fixed time interval for methods whose time step varies: frame k is due at time
// k·interval and is written at the first step at or past it. `count` is the number of frames
// written so far (checkpointed by each method), so a resumed run continues the same schedule.
// Also the [output] keys of that schedule, shared by the mpm, pd and dbm case files.
//
// What a run writes is bounded before it starts: end_time / interval is the number of rows or
// frames a schedule can write, and the case reader refuses an interval that would write more
// than max_series_rows rows or max_frames frames, naming the key and the count. At most one
// frame is written per step (frames due at one step would be identical copies).
#include <algorithm>
#include <cmath>
#include <optional>

#include "shockfield/core/config.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield {

/// Most series rows a run may write (about 100 MB of CSV).
inline constexpr double max_series_rows = 1e6;
/// Most profiles or field frames a run may write.
inline constexpr double max_frames = 1e5;

/// The output schedule of a time-stepping run ([output] keys of the same names).
struct OutputIntervals {
  double series_interval = 0.0;    ///< series.csv row every ... (default: end time / 100)
  double profile_interval = 0.0;   ///< line profiles every ...; 0: only the last
  double field_interval = 0.0;     ///< grid/particle frames every ...; 0: none
  long long checkpoint_every = 0;  ///< checkpoint every ... steps; 0: only at the end or on a stop
  long long thermo_every = 0;      ///< thermo table row every ... steps; 0: about ten rows per run
  /// How field frames store their arrays (vtk_encoding, vtk_precision; methods with fields):
  /// appended binary compressed with zlib, in single precision, unless the case says otherwise;
  /// and in how many pieces (vtk_pieces, default 1: single files; io/vtk_pieces).
  io::VtkFormat vtk{io::VtkEncoding::Zlib, io::VtkPrecision::Float32};
  /// With every particle frame also a LAMMPS text dump (`dump`; methods with particle frames).
  bool dumps = false;
};

/// Which of the optional frame kinds a method writes (the keys of the others stay unknown, so a
/// case file that sets them is told so).
struct OutputKinds {
  bool profiles = false;
  bool fields = false;
  bool vtk = false;  ///< field frames are VTK files (vtk_encoding, vtk_precision, vtk_pieces)
  bool dumps = false;  ///< particle frames can also be LAMMPS dumps (dump)
};

/// Reads the schedule keys of [output] (absent table: the defaults), validated, including the
/// bounds on the number of rows and frames above.
OutputIntervals read_output_intervals(const std::optional<Config>& output, double end_time,
                                      OutputKinds kinds);

/// The thermo table's interval: `requested` (thermo_every) if positive, else about ten rows over
/// the `total_steps` of the whole run (not of a resumed part, so a resumed run keeps the schedule).
long long thermo_interval(long long requested, long long total_steps);

/// With `dt` the (fixed) time step of a run: refuses an interval of [output] that is shorter
/// than one step, naming the key (every step would write the same frame again).
void check_intervals_against_step(const Config& output, const OutputIntervals& s, double dt);

/// A frame (or the end of a run) at time T is due when the clock reads at least T − this fraction of
/// a step. The clock is a sum of steps, whose round-off grows like n·ε·t: 3.3e-13 after 16,000 steps
/// of 1.25e-4 to t = 2, more than the 1e-9 of a step once used, which skipped the last profile of
/// such a run. A millionth of a step is far above that round-off and far below a step.
inline constexpr double kOutputTimeTolerance = 1e-6;

/// Writes frame k = count if it is due by time `t`, then advances `count` past every frame due
/// by `t` (those would repeat the one just written). An interval of 0 means no output. The skip
/// takes constant time: it starts from floor(t / interval) + 1 and corrects that by the same
/// comparison as before (a step at most each way), instead of counting up one frame at a time
/// (10^140 iterations when a PD density of 1e303 made t huge against the interval). A frame
/// count beyond 2^62 means no further frames.
template <class Count, class Write>
void write_due_frames(Count& count, double interval, double t, Write&& write) {
  constexpr double kLastFrame = 4611686018427387904.0;  // 2^62
  if (interval <= 0 || static_cast<double>(count) >= kLastFrame || static_cast<double>(count) * interval > t) return;
  write(count);
  const double next = std::floor(t / interval) + 1;
  if (!(next < kLastFrame)) {
    count = static_cast<Count>(kLastFrame);
    return;
  }
  Count k = std::max(static_cast<Count>(next), static_cast<Count>(count + 1));
  while (k > count + 1 && static_cast<double>(k - 1) * interval > t) --k;
  while (static_cast<double>(k) * interval <= t) ++k;
  count = k;
}

}  // namespace shockfield
