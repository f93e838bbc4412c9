// `shockfield convert CHECKPOINT [-o OUT] [--format ...]`: a checkpoint as the method's ordinary
// outputs (app/checkpoint_convert.hpp).
#include <cstdio>
#include <memory>

#include "shockfield/app/checkpoint_convert.hpp"
#include "shockfield/app/commands.hpp"

namespace shockfield::app {

void add_convert_command(CLI::App& app) {
  auto o = std::make_shared<ConvertRequest>();
  auto precision = std::make_shared<std::string>("float32");
  CLI::App* cmd = app.add_subcommand(
      "convert",
      "Turn a run's checkpoint.h5 (any method; docs/checkpoints.md) into the method's ordinary outputs,\n"
      "so that its state can start a new case in shockfield or be opened in another code:\n"
      "  md                         -> LAMMPS data file (atom style atomic: masses with their\n"
      "                                elements, atoms with image flags, velocities), readable by\n"
      "                                LAMMPS read_data and by shockfield's [system] data_file\n"
      "  mpm, pd, granular,\n"
      "  macroparticle, phasefield\n"
      "  sharp-front                -> .vtp (ParaView): one point per particle, every per-particle\n"
      "                                dataset as a point array with its units\n"
      "  dbm, phasefield            -> .vti: DBM rho, velocity, T (and the reactant) as cell data,\n"
      "                                phase-field xi as point data\n"
      "--format list prints the checkpoint's method, format, step, time, provenance and every dataset\n"
      "with its type, shape and units. A file that is not a checkpoint, is damaged, is of an older\n"
      "layout, or a format that does not fit the method: exit 2 with the file named.\n"
      "Example: shockfield convert runs/md_shock/checkpoint.h5 -o start.data");
  cmd->add_option("checkpoint", o->checkpoint, "A run's checkpoint.h5")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output,
                  "File to write (default: beside the checkpoint, named checkpoint.data, .vtp or .vti)");
  cmd->add_option("--format", o->format,
                  "auto (the method's: data for md, vtp for the particle methods, vti for the grid methods), "
                  "data, vtp, vti, or list")
      ->transform(CLI::CheckedTransformer(std::map<std::string, ConvertFormat>{{"auto", ConvertFormat::automatic},
                                                                               {"data", ConvertFormat::lammps_data},
                                                                               {"vtp", ConvertFormat::vtp},
                                                                               {"vti", ConvertFormat::vti},
                                                                               {"list", ConvertFormat::list}}))
      ->default_str("auto");
  cmd->add_option("--vtk-precision", *precision,
                  "Real arrays of .vtp/.vti as float32 (default) or float64 (bit for bit); zlib-compressed")
      ->check(CLI::IsMember({"float32", "float64"}));
  cmd->callback([o, precision] {
    o->vtk.precision = *precision == "float64" ? io::VtkPrecision::Float64 : io::VtkPrecision::Float32;
    std::printf("%s\n", convert_checkpoint(*o).c_str());
  });
}

}  // namespace shockfield::app
