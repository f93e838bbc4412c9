#pragma once
// `shockfield convert`: a checkpoint (docs/checkpoints.md) as the method's ordinary outputs, read
// from the file alone (its named datasets and attributes, no case file needed):
//   md                       -> a LAMMPS data file (io/lammps_data write_data: atom style atomic,
//                               masses with element comments, velocities, image flags)
//   mpm, pd, granular,
//   macroparticle,
//   phasefield.sharp_front   -> a .vtp (io/vtk_xml): one point per particle, every per-particle
//                               dataset as a point array with its units
//   dbm, phasefield          -> a .vti: DBM ρ, u, T (and the reactant) as cell data on the
//                               interior cells (Xu et al. (2015), eqs. 20–22), phase-field ξ as
//                               point data
// and, for any method, a listing of the attributes and datasets with their shapes and units.
#include <filesystem>
#include <optional>
#include <string>

#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::app {

enum class ConvertFormat { automatic, lammps_data, vtp, vti, list };

struct ConvertRequest {
  std::filesystem::path checkpoint;
  std::optional<std::filesystem::path> output;  ///< default: beside the checkpoint, its extension changed
  ConvertFormat format = ConvertFormat::automatic;
  io::VtkFormat vtk{io::VtkEncoding::Zlib, io::VtkPrecision::Float32};
};

/// Converts (InputError naming the file when it is not a checkpoint, is damaged, or the format does
/// not fit its method) and returns what to print: the listing, or a line naming the file written.
std::string convert_checkpoint(const ConvertRequest& request);

}  // namespace shockfield::app
