#include "shockfield/io/particle_frame.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "shockfield/core/error.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/vtk_pieces.hpp"

namespace shockfield::io {

namespace {

// The dump column names of one array (particle_dump_frame) and, per column, its component.
std::vector<std::pair<std::string, int>> dump_columns(const VtkArray& a) {
  if (a.components == 1) return {{a.name, 0}};
  if (a.components == 3) {
    if (a.name == "velocity") return {{"vx", 0}, {"vy", 1}, {"vz", 2}};
    if (a.name == "force") return {{"fx", 0}, {"fy", 1}, {"fz", 2}};
    return {{a.name + "_x", 0}, {a.name + "_y", 1}, {a.name + "_z", 2}};
  }
  if (a.components == 9)  // row-major: xx 0, yy 4, zz 8, xy 1, xz 2, yz 5
    return {{a.name + "_xx", 0}, {a.name + "_yy", 4}, {a.name + "_zz", 8},
            {a.name + "_xy", 1}, {a.name + "_xz", 2}, {a.name + "_yz", 5}};
  throw InputError(fmt::format("particle array '{}' has {} components; a dump takes 1, 3 or 9", a.name, a.components));
}

}  // namespace

DumpFrame particle_dump_frame(const ParticleFrame& p) {
  const std::size_t n = p.size();
  DumpFrame frame;
  frame.timestep = p.step;
  frame.time = p.time;
  frame.units = "si";
  frame.bounds = {"ss", "ss", "ss"};
  std::vector<double> id(n), type(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<double>(i + 1);
  if (!p.type.empty()) std::copy(p.type.begin(), p.type.end(), type.begin());
  frame.set_column("id", std::move(id));
  frame.set_column("type", std::move(type));
  for (int d = 0; d < 3; ++d) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = p.xyz[3 * i + static_cast<std::size_t>(d)];
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
    frame.box.lo[d] = n ? lo - p.margin : -p.margin;
    frame.box.hi[d] = n ? hi + p.margin : p.margin;
    frame.set_column(std::string(1, "xyz"[d]), std::move(x));
  }
  for (const VtkArray& a : p.arrays)
    for (const auto& [name, c] : dump_columns(a)) {
      std::vector<double> values(n);
      for (std::size_t i = 0; i < n; ++i) values[i] = a.values[static_cast<std::size_t>(a.components) * i + static_cast<std::size_t>(c)];
      frame.set_column(name, std::move(values));
    }
  return frame;
}

ParticleOutput::ParticleOutput(const std::filesystem::path& run, const std::filesystem::path& folder, std::string stem,
                               VtkFormat vtk, bool dumps, int pad, const double* resume_time)
    : run_(run), folder_(folder), stem_(std::move(stem)), vtk_(vtk), dumps_(dumps), pad_(pad) {
  std::filesystem::create_directories(folder_);
  if (dumps_) std::filesystem::create_directories(run_ / "dumps");
  pvd_ = PvdSeries(folder_ / (stem_ + ".pvd"), resume_time, "s");  // SI frames (pd, granular)
}

void ParticleOutput::write(const ParticleFrame& frame, std::int64_t index) {
  const std::string name = fmt::format("{}_{}", stem_, index);
  if (frame.type.empty()) {
    pvd_.add(frame.time, write_points_frame(folder_, name, frame.xyz, frame.arrays, vtk_));
  } else {
    std::vector<VtkArray> arrays = frame.arrays;
    arrays.push_back({"type", 1, std::vector<double>(frame.type.begin(), frame.type.end()), "1", true});
    pvd_.add(frame.time, write_points_frame(folder_, name, frame.xyz, arrays, vtk_));
  }
  if (!dumps_) return;
  CheckedOutput out(run_ / "dumps" / fmt::format("dump.{:0{}}.lammpstrj", frame.step, pad_));
  write_dump_frame(out.stream(), particle_dump_frame(frame), DumpWriteOptions{true});
  out.close();
}

int step_digits(long long last_step) { return static_cast<int>(std::to_string(std::max(0LL, last_step)).size()); }

}  // namespace shockfield::io
