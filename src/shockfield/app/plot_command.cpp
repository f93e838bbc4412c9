// `shockfield plot KIND RUN_DIR`: PNG figures of a run folder or of an `analyze atoms` output,
// drawn by the Python helpers in shockfield_plot (md_plots.py, mpm_plots.py,
// macroparticle_plots.py, phasefield_plots.py, atoms_plots.py), found and run as
// app/python_helpers.hpp says.
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "shockfield/app/commands.hpp"
#include "shockfield/app/python_helpers.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {
namespace {

struct PlotOptions {
  std::string kind;
  std::string run;
  std::string out;
  std::string axis = "z";
  std::optional<double> at;  // slice: centre along the axis
  double thickness = 3.0;    // slice: Å
  std::string column;        // slice: structure column
  int frame = -1;            // slice: frame index in the dump, -1 the last
};

void plot(const PlotOptions& o) {
  const bool md = o.kind == "profiles" || o.kind == "thermo" || o.kind == "hugoniot";
  const bool atoms = o.kind == "structures" || o.kind == "slice";
  if (o.kind == "slice") {
    if (!std::filesystem::is_regular_file(o.run))
      throw InputError(fmt::format("'{}' is not a file: plot slice draws an annotated dump of analyze atoms", o.run));
    if (!(o.thickness > 0)) throw InputError(fmt::format("--thickness {}: expected a number > 0 (Å)", o.thickness));
  } else if (!std::filesystem::is_directory(o.run)) {
    throw InputError(fmt::format("'{}' is not a run folder", o.run));
  }
  const char* helper = md                          ? "md_plots"
                       : atoms                     ? "atoms_plots"
                       : o.kind == "stress-strain" ? "macroparticle_plots"
                       : o.kind == "phasefield"    ? "phasefield_plots"
                                                   : "mpm_plots";
  std::string args = fmt::format("-m shockfield_plot.{} {} {}", helper, o.kind, shell_quote(o.run));
  if (o.kind == "profiles" || o.kind == "slice") args += " --axis " + o.axis;
  if (o.kind == "slice") {
    args += fmt::format(" --thickness {} --frame {}", o.thickness, o.frame);
    if (o.at) args += fmt::format(" --at {}", *o.at);
    if (!o.column.empty()) args += " --column " + shell_quote(o.column);
  }
  if (!o.out.empty()) args += " --out " + shell_quote(o.out);
  const std::string cmd = python_command(args);
  if (std::system(cmd.c_str()) != 0)
    throw RunError("the plot helper failed (is python3-matplotlib installed? scripts/install-deps.sh installs it)");
}

}  // namespace

void add_plot_command(CLI::App& app) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw PNG figures of a run folder.\n"
      "  profiles  binned shock profiles along the axis (particle velocity, pressure, temperature,\n"
      "            density) at six times, from profiles.csv -> RUN/profiles.png\n"
      "  thermo    temperature, energies and pressure against time, from thermo.csv -> RUN/thermo.png\n"
      "  hugoniot  Us against Up of a `shockfield hugoniot` sweep folder with the fitted line and\n"
      "            the experimental one -> RUN/hugoniot.png\n"
      "  porous    MPM: bottom-window mean density, pressure, temperature, u_y against time beside\n"
      "            Xu et al.'s (2015) values, and particle temperatures at the last frame -> RUN/porous.png\n"
      "  cavity    MPM: particles around the cavity by temperature, cavity area and collapsibility\n"
      "            against time -> RUN/cavity.png\n"
      "  stress-strain  macroparticle: stress against strain of a loaded rod, from thermo.csv\n"
      "            -> RUN/stress-strain.png\n"
      "  phasefield  phase field: equivalent radius, principal semi-axes and growth speed against\n"
      "            time (series.csv), and the middle slice of the last frame -> RUN/phasefield.png\n"
      "  structures  structure fractions against time (one panel per method: cna, acna, bpa) from\n"
      "            structures.csv of an `analyze atoms` output folder or an MD run with [analysis]\n"
      "            -> RUN/structures.png\n"
      "  slice     the atoms of a slice of an annotated dump (RUN is the dump file written by\n"
      "            `analyze atoms`) coloured by structure type (acna, else cna, else bpa)\n"
      "            -> <dump without extension>_slice.png");
  cmd->add_option("kind", o->kind, "What to plot")
      ->required()
      ->check(CLI::IsMember({"profiles", "thermo", "hugoniot", "porous", "cavity", "stress-strain", "phasefield",
                             "structures", "slice"}));
  cmd->add_option("run", o->run, "Run folder (analysis folder for structures, annotated dump for slice)")->required();
  cmd->add_option("-o,--out", o->out, "PNG file (default RUN/<kind>.png)");
  cmd->add_option("--axis", o->axis, "Shock axis of MD profiles, normal of the slice (default z)")
      ->check(CLI::IsMember({"x", "y", "z"}));
  cmd->add_option("--at", o->at, "slice: its centre along --axis (Å; default the middle of the box)");
  cmd->add_option("--thickness", o->thickness, "slice: its thickness (Å)")->capture_default_str();
  cmd->add_option("--column", o->column, "slice: the structure column (default acna, else cna, else bpa)");
  cmd->add_option("--frame", o->frame, "slice: the frame of the dump, 0 the first, -1 the last")->capture_default_str();
  cmd->callback([o] { plot(*o); });
}

}  // namespace shockfield::app
