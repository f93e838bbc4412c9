#pragma once
// Progress report for long loops: on a terminal a single line rewritten in place with step,
// steps/s and ETA; otherwise a plain line every `plain_interval_s` seconds (logs, CI, pipes).
#include <chrono>
#include <cstdint>
#include <string>

namespace shockfield {

class Progress {
 public:
  /// `label` prefixes the line; `total` is the number of steps the loop will make.
  Progress(std::string label, std::int64_t first, std::int64_t total, bool enabled,
           double plain_interval_s = 30.0);
  /// Call once per step with the step number; cheap when nothing is printed. Methods whose step
  /// count is not known in advance (adaptive time steps) pass the fraction of the run done
  /// (simulated time / end time), which then sets the percentage and the ETA.
  void update(std::int64_t step, double fraction_done = -1.0);
  /// Ends the line (terminal) and prints the final rate.
  void finish(std::int64_t step);
  /// Steps per second since the start.
  double rate(std::int64_t step) const;

 private:
  void print(std::int64_t step, bool final, double fraction_done);
  std::string label_;
  std::int64_t first_, total_;
  bool enabled_, terminal_;
  double plain_interval_s_;
  std::chrono::steady_clock::time_point start_, last_print_;
};

/// "1h02m", "3m05s", "12.3s".
std::string format_duration(double seconds);

}  // namespace shockfield
