#pragma once
// The voids of `shockfield analyze atoms --voids R` (Xu et al. (2015) §3.2.3, rolling-ball
// surfaces; geometry/rolling_ball): per frame, the Delaunay division of the atoms and its
// cavities for a ball of radius R — the regions a ball that cannot pass between neighbouring atoms
// can move in without reaching the outside — with their volumes, areas and centres
// (OUTPUT/voids.csv) and their surfaces (OUTPUT/voids_<timestep>.vtp for ParaView).
#include <CLI/CLI.hpp>

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

class VoidOutput {
 public:
  /// `add_file` registers an output file (written as .partial until every input is analysed).
  VoidOutput(const VoidArgs& args, std::function<std::filesystem::path(const std::filesystem::path&)> add_file);
  bool on() const { return args_.probe.has_value(); }
  void add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame);
  void close();
  std::size_t voids() const { return voids_; }

 private:
  VoidArgs args_;
  std::function<std::filesystem::path(const std::filesystem::path&)> add_file_;
  io::CheckedOutput csv_;
  std::size_t voids_ = 0;
};

}  // namespace shockfield::app
