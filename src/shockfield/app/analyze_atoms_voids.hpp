#pragma once
// The voids of `shockfield analyze atoms --voids R` (Xu et al. (2015) §3.2.3, rolling-ball
// surfaces; found by analysis/atoms/atom_surfaces): per frame, the Delaunay division of the atoms
// and its cavities for a ball of radius R — the regions a ball that cannot pass between
// neighbouring atoms can move in without reaching the outside — with their volumes, areas and
// centres (OUTPUT/voids.csv), their surfaces (OUTPUT/voids_<timestep>.vtp for ParaView) and a plot
// of volume and area against time (OUTPUT/voids.png).
#include <CLI/CLI.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <filesystem>
#include <functional>
#include <optional>

#include "shockfield/analysis/atoms/atom_frame.hpp"
#include "shockfield/core/types.hpp"
#include "shockfield/io/checked_file.hpp"

namespace shockfield::app {

struct VoidArgs {
  std::optional<double> probe;  ///< Å
  double min_volume = 0;        ///< Å³
  std::optional<double> atomic_volume;  ///< Å³; default (box volume − voids) / atoms
  std::optional<double> margin;         ///< Å of periodic images around the box; default 15
};

void add_void_options(CLI::App& cmd, VoidArgs& args);

/// The files of a series of surfaces (voids, domains) named NAME: NAME.csv (a row per object and
/// frame), NAME_<timestep>.vtp (the frame's surfaces) and NAME.png (volume and area against time).
class SurfaceSeries {
 public:
  SurfaceSeries() = default;
  /// `add_file` registers an output file (written as .partial until every input is analysed).
  SurfaceSeries(std::string name, const std::string& csv_header,
                const std::function<std::filesystem::path(const std::filesystem::path&)>& add_file);
  io::CheckedOutput& csv() { return csv_; }
  /// Flushes the frame's rows and writes its surfaces.
  void end_frame(long long timestep, const std::vector<std::array<double, 3>>& points,
                 const std::vector<std::array<std::int32_t, 3>>& triangles);
  void close();
  /// NAME.png from the committed NAME.csv in `folder` (a warning, not an error, on failure).
  void plot(const std::filesystem::path& folder) const;

 private:
  std::string name_;
  std::function<std::filesystem::path(const std::filesystem::path&)> add_file_;
  io::CheckedOutput csv_;
};

class VoidOutput {
 public:
  /// `add_file` registers an output file (written as .partial until every input is analysed).
  VoidOutput(const VoidArgs& args, std::function<std::filesystem::path(const std::filesystem::path&)> add_file);
  bool on() const { return args_.probe.has_value(); }
  void add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame);
  void close() { files_.close(); }
  void plot(const std::filesystem::path& folder) const {
    if (on()) files_.plot(folder);
  }
  std::size_t voids() const { return voids_; }

 private:
  VoidArgs args_;
  SurfaceSeries files_;
  std::size_t voids_ = 0;
};

}  // namespace shockfield::app
