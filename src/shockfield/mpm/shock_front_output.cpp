#include "shockfield/mpm/shock_front_output.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "shockfield/core/error.hpp"
#include "shockfield/core/run_folder.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/mpm/diagnostics.hpp"
#include "shockfield/mpm/run_output.hpp"

namespace shockfield::mpm {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFile = "shock_front.csv";
constexpr std::size_t kPositions = 6;  // front, precursor front, leading edge, rise, impact face, free end

// step, time, the six positions, the state ahead, then for the plateau and the precursor's
// plateau their mass and each quantity's mean and std.
std::vector<std::string> columns(int dim) {
  std::vector<std::string> c{"step", "time_s", "front_m", "precursor_front_m", "leading_edge_m", "rise_m",
                             "impact_face_m", "free_end_m"};
  const auto quantities = profile_quantities(dim);
  for (const auto& q : quantities) c.push_back("ahead_" + q.name + "_mean_" + q.unit);
  for (const char* part : {"plateau", "precursor"}) {
    c.push_back(std::string(part) + "_mass_kg" + units::si::per_missing_dimensions_column(dim));
    for (const auto& q : quantities) {
      c.push_back(fmt::format("{}_{}_mean_{}", part, q.name, q.unit));
      c.push_back(fmt::format("{}_{}_std_{}", part, q.name, q.unit));
    }
  }
  return c;
}

std::vector<double> row(const FrontFrame& f, std::int64_t step) {
  std::vector<double> r{static_cast<double>(step), f.time, f.front, f.precursor, f.leading, f.rise, f.face,
                         f.free_end};
  r.insert(r.end(), f.ahead.begin(), f.ahead.end());
  for (const auto* part : {&f.plateau, &f.precursor_plateau}) {
    r.push_back(part->empty() ? 0.0 : part->front().weight);
    for (const analysis::WeightedMoments& m : *part) r.push_back(m.mean), r.push_back(m.std);
  }
  return r;
}

// The inverse of row(); at_free_end recomputed from the positions as analyse_front sets it.
FrontFrame frame_of(const std::vector<double>& r, std::size_t nq, const ShockFrontSettings& s) {
  FrontFrame f;
  f.time = r[1];
  f.front = r[2], f.precursor = r[3], f.leading = r[4], f.rise = r[5], f.face = r[6], f.free_end = r[7];
  f.at_free_end = s.direction * (f.free_end - f.leading) <= s.margin_bins * s.bin_width;
  std::size_t k = 2 + kPositions;
  for (std::size_t q = 0; q < nq; ++q) f.ahead.push_back(r[k++]);
  for (auto* part : {&f.plateau, &f.precursor_plateau}) {
    const double mass = r[k++];
    for (std::size_t q = 0; q < nq; ++q, k += 2) part->push_back({r[k], r[k + 1], mass});
  }
  return f;
}

}  // namespace

ShockFrontOutput::ShockFrontOutput(const fs::path& folder, const GridSpec& grid, ShockFrontSpec spec,
                                   std::optional<std::int64_t> resume_step)
    : folder_(folder), grid_(grid), spec_(std::move(spec)) {
  const double keep = resume_step ? static_cast<double>(*resume_step) : 0.0;
  csv_ = io::CsvWriter(folder / kFile, columns(grid.dim), resume_step ? &keep : nullptr, true);
}

void ShockFrontOutput::record(const Simulation& sim) {
  const int axis = grid_.dim - 1;
  const double lo = grid_.origin[axis];
  const ShockProfile profile = shock_profile(sim.particles(), grid_.dim, spec_.settings.body, lo, lo + grid_.length(axis),
                                             spec_.settings.bin_width, window_cross_section(grid_), sim.time());
  csv_.row(row(analyse_front(profile, grid_.dim, spec_.settings), sim.step_count()));
}

ShockHugoniot ShockFrontOutput::finish() const {
  const fs::path file = folder_ / kFile;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const std::size_t nq = profile_quantities(grid_.dim).size(), width = columns(grid_.dim).size();
  std::vector<FrontFrame> frames;
  while (std::getline(in, line)) {
    std::vector<double> r;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) r.push_back(std::strtod(cell.c_str(), nullptr));
    if (r.size() != width)
      throw RunError(fmt::format("{}: a row of {} values, expected {} (the file was changed during the run)",
                                 file.string(), r.size(), width));
    frames.push_back(frame_of(r, nq, spec_.settings));
  }
  const ShockHugoniot h = fit_hugoniot(frames, grid_.dim, spec_.settings);
  const std::string title = fmt::format("Hugoniot state of body {} ({}), shock running {} the axis", spec_.settings.body,
                                        spec_.material, spec_.settings.direction > 0 ? "up" : "down");
  write_file_atomically(toml_file(), hugoniot_toml(h, grid_.dim, title));
  return h;
}

}  // namespace shockfield::mpm
