#include "shockfield/core/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace shockfield {

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60) return fmt::format("{:.1f}s", s);
  const auto total = static_cast<long long>(s);
  if (s < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
}

Progress::Progress(std::string label, std::int64_t first, std::int64_t total, bool enabled,
                   double plain_interval_s)
    : label_(std::move(label)), first_(first), total_(total), enabled_(enabled),
      terminal_(isatty(STDOUT_FILENO) != 0), plain_interval_s_(plain_interval_s),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

double Progress::rate(std::int64_t step) const {
  const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return dt > 0 ? static_cast<double>(step - first_) / dt : 0.0;
}

void Progress::update(std::int64_t step, double fraction_done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (terminal_ ? 0.25 : plain_interval_s_)) return;
  last_print_ = now;
  print(step, false, fraction_done);
}

void Progress::finish(std::int64_t step) {
  if (!enabled_) return;
  print(step, true, 1.0);
}

void Progress::print(std::int64_t step, bool final, double fraction_done) {
  const double r = rate(step);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const bool by_fraction = fraction_done >= 0;
  double pct = 100.0, eta = NAN;
  if (by_fraction) {
    pct = 100.0 * fraction_done;
    if (fraction_done > 0) eta = elapsed * (1.0 - fraction_done) / fraction_done;
  } else if (total_ > 0) {
    pct = 100.0 * static_cast<double>(step - first_) / static_cast<double>(total_);
    if (r > 0) eta = static_cast<double>(total_ - (step - first_)) / r;
  }
  const std::string count = by_fraction || final ? fmt::format("{}", step - first_)
                                                 : fmt::format("{}/{}", step - first_, total_);
  const std::string text = fmt::format("{} step {} ({:.0f}%)  {:.1f} steps/s  {} {}", label_, count, pct, r,
                                       final ? "elapsed" : "ETA", format_duration(final ? elapsed : eta));
  if (terminal_) std::fprintf(stdout, "\r\033[K%s%s", text.c_str(), final ? "\n" : "");
  else std::fprintf(stdout, "%s\n", text.c_str());
  std::fflush(stdout);
}

}  // namespace shockfield
