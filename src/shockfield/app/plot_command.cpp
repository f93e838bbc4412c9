// `shockfield plot profiles|thermo RUN_DIR`: PNG figures of a run folder, drawn by the Python
// helper python/shockfield_plot/md_plots.py with Debian's matplotlib (/usr/bin/python3).
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {
namespace {

struct PlotOptions {
  std::string kind;
  std::string run;
  std::string out;
  std::string axis = "z";
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void plot(const PlotOptions& o) {
  const std::filesystem::path script =
      std::filesystem::path(SHOCKFIELD_SOURCE_DIR) / "python" / "shockfield_plot" / "md_plots.py";
  if (!std::filesystem::exists(script))
    throw InputError(fmt::format("plot helper not found at {}", script.string()));
  if (!std::filesystem::is_directory(o.run)) throw InputError(fmt::format("'{}' is not a run folder", o.run));
  std::string cmd = fmt::format("/usr/bin/python3 {} {} {} --axis {}", quote(script.string()), o.kind,
                                quote(o.run), o.axis);
  if (!o.out.empty()) cmd += " --out " + quote(o.out);
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
      "  thermo    temperature, energies and pressure against time, from thermo.csv -> RUN/thermo.png");
  cmd->add_option("kind", o->kind, "What to plot")->required()->check(CLI::IsMember({"profiles", "thermo"}));
  cmd->add_option("run", o->run, "Run folder")->required();
  cmd->add_option("-o,--out", o->out, "PNG file (default RUN/<kind>.png)");
  cmd->add_option("--axis", o->axis, "Shock axis of the profiles (default z)")->check(CLI::IsMember({"x", "y", "z"}));
  cmd->callback([o] { plot(*o); });
}

}  // namespace shockfield::app
