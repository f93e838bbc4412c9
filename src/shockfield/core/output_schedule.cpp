#include "shockfield/core/output_schedule.hpp"

#include <algorithm>

namespace shockfield {

OutputIntervals read_output_intervals(const std::optional<Config>& output, double end_time,
                                      OutputKinds kinds) {
  OutputIntervals s;
  s.series_interval = end_time / 100.0;
  if (!output) return s;
  const Config& t = *output;
  s.series_interval = t.get_double_or("series_interval", s.series_interval, Range::positive());
  if (kinds.profiles)
    s.profile_interval = t.get_double_or("profile_interval", 0.0, Range::non_negative());
  if (kinds.fields)
    s.field_interval = t.get_double_or("field_interval", 0.0, Range::non_negative());
  s.checkpoint_every = t.get_int_or("checkpoint_every", 0, Range::non_negative());
  s.thermo_every = t.get_int_or("thermo_every", 0, Range::non_negative());
  return s;
}

long long thermo_interval(long long requested, long long total_steps) {
  return requested > 0 ? requested : std::max(1LL, (total_steps + 9) / 10);
}

}  // namespace shockfield
