#include "shockfield/app/analyze_atoms_profiles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shockfield/app/option_values.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {

namespace aa = shockfield::analysis::atoms;

void add_profile_options(CLI::App& cmd, ProfileArgs& a) {
  cmd.add_option("--profile", a.profile,
                 "Structure fractions in bins along an axis, AXIS:WIDTH (e.g. z:5 for 5 Å bins along z, the shock "
                 "axis): writes OUTPUT/profiles.csv (per frame and bin: the fraction of each structure of each "
                 "method, and the mean excess energy with --excess-energy)");
  cmd.add_option("--excess-energy", a.excess_energy,
                 "Per-atom excess energy pe - e0 (eV) from the dump's potential-energy column, as column excess: "
                 "'auto' takes e0 as the median pe of the atoms of --excess-crystal structure, a number gives e0 "
                 "(eV, e.g. the perfect crystal's cohesive energy)");
  cmd.add_option("--excess-crystal", a.crystal, "Structure whose median pe is e0 for --excess-energy auto")
      ->capture_default_str()
      ->check(CLI::IsMember({"fcc", "hcp", "bcc"}));
  cmd.add_option("--pe-column", a.pe_column,
                 "Dump column holding the per-atom potential energy (default: the first of pe, c_pe, c_peatom, "
                 "c_pe_atom, v_pe)");
}

ProfileOutput::ProfileOutput(const ProfileArgs& args, const aa::StructureAnalyses& analyses) : args_(args) {
  if (analyses.cna) methods_.push_back("cna");
  if (analyses.adaptive_cna) methods_.push_back("acna");
  if (analyses.bond_pairs) methods_.push_back("bpa");
  if (!args.profile.empty()) {
    const std::string what = fmt::format("--profile '{}'", args.profile);
    const auto colon = args.profile.find(':');
    const std::string axis = args.profile.substr(0, colon);
    if (colon == std::string::npos || axis.size() != 1 || std::string("xyz").find(axis[0]) == std::string::npos)
      throw InputError(what + ": expected AXIS:WIDTH with AXIS x, y or z (e.g. z:5)");
    const double width = finite_number(args.profile.substr(colon + 1), what);
    if (!(width > 0)) throw InputError(what + ": the bin width must be a number > 0 (Å)");
    profile_ = aa::StructureProfile{static_cast<int>(std::string("xyz").find(axis[0])), width};
  }
  if (!args.excess_energy.empty()) {
    excess_ = true;
    if (args.excess_energy != "auto") {
      const double e0 = finite_number(args.excess_energy, "--excess-energy (expected auto or a reference energy in eV)");
      reference_ = e0;
    } else if (methods_.empty()) {
      throw InputError("--excess-energy auto needs a structure method (--adaptive-cna, --cna or --bond-pairs) to find the crystal atoms");
    }
    crystal_ = args.crystal == "hcp" ? aa::Structure::hcp : args.crystal == "bcc" ? aa::Structure::bcc : aa::Structure::fcc;
  }
}

void ProfileOutput::open(const std::filesystem::path& file) {
  out_ = io::CheckedOutput(file);
  out_.write(aa::csv_header(aa::profile_columns(methods_, excess_)));
}

aa::ExcessEnergy ProfileOutput::excess_energy(const aa::AtomFrame& frame, const aa::StructureAnalysisResult& r,
                                                 const io::DumpFrame& dump) const {
  std::string column = args_.pe_column;
  if (column.empty())
    for (const char* name : {"pe", "c_pe", "c_peatom", "c_pe_atom", "v_pe"})
      if (dump.has(name)) {
        column = name;
        break;
      }
  if (column.empty() || !dump.has(column))
    throw InputError(fmt::format("{}: --excess-energy needs a per-atom potential energy column ({}); dump pe (LAMMPS: "
                                 "compute pe/atom) or name the column with --pe-column",
                                 dump.where(), column.empty() ? "none of pe, c_pe, c_peatom, c_pe_atom, v_pe" : column));
  aa::ExcessEnergy e = aa::excess_energy(dump.column(column), r, crystal_, reference_ ? &*reference_ : nullptr);
  if (!reference_)
    std::printf("timestep %lld: excess energy reference e0 = %.10g eV (median pe of %s atoms)\n", frame.timestep,
                e.reference, args_.crystal.c_str());
  return e;
}

void ProfileOutput::add(std::size_t frame_index, const aa::AtomFrame& frame, const aa::StructureAnalysisResult& r) {
  const std::vector<double>& excess = r.excess_energy;
  if (!profile_) return;
  const auto per_method = profile_->per_method(frame, r, excess);  // methods_' order
  const auto& bins = per_method.front().second;
  for (std::size_t b = 0; b < bins.size(); ++b) {
    std::string row = fmt::format("{},{},{},{:.10g},{:.10g},{:.10g},{}", frame_index, frame.timestep, b, bins[b].lo,
                                  bins[b].hi, 0.5 * (bins[b].lo + bins[b].hi), bins[b].counts.total);
    for (const auto& [method, method_bins] : per_method)
      if (!method.empty())
        for (aa::Structure t : aa::kStructures) row += fmt::format(",{:.6g}", method_bins[b].counts.fraction(t));
    if (excess_) row += fmt::format(",{:.10g}", bins[b].mean_value());
    out_.write(row + "\n");
  }
  out_.flush();
}

void ProfileOutput::close() {
  if (out_.is_open()) out_.close();
}

}  // namespace shockfield::app
