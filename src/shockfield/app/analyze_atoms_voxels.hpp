#pragma once
// The voxel fields of `shockfield analyze atoms --voxel H` (analysis/atoms/voxel_field): per
// frame, the fraction of the atoms of --voxel-select (default acna:hcp) on a grid of spacing H,
// OUTPUT/voxels_<timestep>.vti with the point arrays `fraction` and `density` — a field file the
// phase-field model's [initial] file reads (docs/phasefield.md), ξ = the hcp fraction.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "shockfield/analysis/atoms/voxel_field.hpp"

namespace shockfield::app {

struct VoxelArgs {
  std::optional<double> spacing;  ///< Å
  double smoothing = 0.0;         ///< Å
  std::string select = "acna:hcp";
};

void add_voxel_options(CLI::App& cmd, VoxelArgs& args);

class VoxelOutput {
 public:
  /// `add_file` registers an output file (written as .partial until every input is analysed).
  VoxelOutput(const VoxelArgs& args, std::function<std::filesystem::path(const std::filesystem::path&)> add_file);
  bool on() const { return args_.spacing.has_value(); }
  void add(const analysis::atoms::AtomFrame& frame, const std::vector<bool>& selected);
  /// What was written (frames, nodes, stretch, empty nodes), for the command's summary.
  std::string summary() const;

 private:
  VoxelArgs args_;
  std::function<std::filesystem::path(const std::filesystem::path&)> add_file_;
  std::size_t frames_ = 0, empty_ = 0;
  analysis::atoms::VoxelField last_;
};

}  // namespace shockfield::app
