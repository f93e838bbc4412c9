#include "shockfield/core/output_schedule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace shockfield {
namespace {

// Refuses `key` when end_time / interval exceeds `most` (what the run would write).
void bound_count(const Config& t, const char* key, double interval, double end_time, double most, const char* what) {
  const double count = end_time / interval;
  if (interval > 0 && count > most)
    t.fail(key, fmt::format("{} with end_time = {} would write {} {}, more than the {:.0f} a run may write; "
                            "use an interval of at least {:.4g}",
                            interval, end_time, std::isfinite(count) ? fmt::format("{:.4g}", count) : "over 1e308",
                            what, most, end_time / most));
}

}  // namespace

OutputIntervals read_output_intervals(const std::optional<Config>& output, double end_time,
                                      OutputKinds kinds) {
  OutputIntervals s;
  s.series_interval = end_time / 100.0;
  if (!output) return s;
  const Config& t = *output;
  s.series_interval = t.get_double_or("series_interval", s.series_interval, Range::positive());
  bound_count(t, "series_interval", s.series_interval, end_time, max_series_rows, "series rows");
  if (kinds.profiles) {
    s.profile_interval = t.get_double_or("profile_interval", 0.0, Range::non_negative());
    bound_count(t, "profile_interval", s.profile_interval, end_time, max_frames, "profiles");
  }
  if (kinds.fields) {
    s.field_interval = t.get_double_or("field_interval", 0.0, Range::non_negative());
    bound_count(t, "field_interval", s.field_interval, end_time, max_frames, "field frames");
  }
  if (kinds.vtk) {
    const std::string encoding = t.get_choice_or("vtk_encoding", {"ascii", "base64", "raw", "zlib"}, "zlib");
    for (io::VtkEncoding e : {io::VtkEncoding::Ascii, io::VtkEncoding::Base64, io::VtkEncoding::Raw, io::VtkEncoding::Zlib})
      if (encoding == io::encoding_name(e)) s.vtk.encoding = e;
    s.vtk.precision =
        t.get_choice_or("vtk_precision", {"float32", "float64"}, "float32") == "float32" ? io::VtkPrecision::Float32
                                                                                        : io::VtkPrecision::Float64;
    s.vtk.pieces = static_cast<int>(t.get_int_or("vtk_pieces", 1, Range::closed(1, 4096)));
  }
  if (kinds.dumps) s.dumps = t.get_bool_or("dump", false);
  s.checkpoint_every = t.get_int_or("checkpoint_every", 0, Range::non_negative());
  s.thermo_every = t.get_int_or("thermo_every", 0, Range::non_negative());
  return s;
}

void check_intervals_against_step(const Config& output, const OutputIntervals& s, double dt) {
  const std::pair<const char*, double> intervals[] = {
      {"series_interval", s.series_interval}, {"profile_interval", s.profile_interval}, {"field_interval", s.field_interval}};
  for (const auto& [key, interval] : intervals)
    if (interval > 0 && interval < dt * (1 - 1e-9) && output.has(key))
      output.fail(key, fmt::format("{} is shorter than the time step dt = {:.6g}: every step would write the same "
                                   "output again; use {} >= {:.6g}",
                                   interval, dt, key, dt));
}

long long thermo_interval(long long requested, long long total_steps) {
  return requested > 0 ? requested : std::max(1LL, (total_steps + 9) / 10);
}

}  // namespace shockfield
