#include "shockfield/app/analyze_atoms_voxels.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::app {

void add_voxel_options(CLI::App& cmd, VoxelArgs& a) {
  cmd.add_option("--voxel", a.spacing,
                 "Voxel field: the fraction of the --voxel-select atoms (default the hcp atoms of the adaptive CNA) on "
                 "a grid of this node spacing (Å; cloud-in-cell), per frame OUTPUT/voxels_<timestep>.vti with the "
                 "arrays fraction and density: the order parameter xi a phase-field case reads as [initial] file")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--voxel-smooth", a.smoothing,
                 "Gaussian smoothing of the voxel field, standard deviation in Å (0: none; about the nearest-neighbour "
                 "distance fills the nodes between atoms when the spacing is finer than the atoms)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--voxel-select", a.select, "Which atoms count for the voxel fraction, as --cluster-select")
      ->capture_default_str();
}

VoxelOutput::VoxelOutput(const VoxelArgs& args, std::function<std::filesystem::path(const std::filesystem::path&)> add_file)
    : args_(args), add_file_(std::move(add_file)) {}

void VoxelOutput::add(const analysis::atoms::AtomFrame& frame, const std::vector<bool>& selected) {
  last_ = analysis::atoms::voxel_fraction(frame, selected, {*args_.spacing, args_.smoothing});
  io::VtkImage image;
  image.points = last_.n;
  image.origin = last_.origin;
  image.spacing = {last_.spacing, last_.spacing, last_.spacing};
  image.length_units = "A";
  image.point_data.push_back({"fraction", 1, last_.fraction, "1"});
  image.point_data.push_back({"density", 1, last_.density, "1/A^3"});
  io::write_vti(add_file_(fmt::format("voxels_{}.vti", frame.timestep)), image, io::VtkFormat(io::VtkEncoding::Zlib));
  ++frames_;
  empty_ += last_.empty_nodes;
}

std::string VoxelOutput::summary() const {
  const auto& g = last_;
  std::string s = fmt::format("voxel fields of '{}': {} frames, {} x {} x {} nodes, spacing {} Å, stretch {:.5f} {:.5f} {:.5f}",
                              args_.select, frames_, g.n[0], g.n[1], g.n[2], g.spacing, g.stretch[0], g.stretch[1],
                              g.stretch[2]);
  if (empty_ > 0)
    s += fmt::format("; {} nodes received no atom and were set to 0 (use a larger --voxel or --voxel-smooth)", empty_);
  return s;
}

}  // namespace shockfield::app
