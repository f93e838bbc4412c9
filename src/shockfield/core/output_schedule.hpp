#pragma once
// Output on a fixed time interval for methods whose time step varies: frame k is due at time
// k·interval and is written at the first step at or past it. `count` is the number of frames
// written so far (checkpointed by each method), so a resumed run continues the same schedule.

namespace shockfield {

/// Calls write(k) for every frame k = count, count+1, ... due by time `t`, advancing `count`.
/// An interval of 0 means no output.
template <class Count, class Write>
void write_due_frames(Count& count, double interval, double t, Write&& write) {
  if (interval <= 0) return;
  for (; static_cast<double>(count) * interval <= t; ++count) write(count);
}

}  // namespace shockfield
