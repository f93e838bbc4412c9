#pragma once
// Structure-fraction profiles along an axis (`--profile AXIS:WIDTH`, OUTPUT/profiles.csv) and the
// per-atom excess energy (`--excess-energy`, dump column `excess`) of `shockfield analyze atoms`
// (analysis/atoms/structure_profile).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>

#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/analysis/atoms/structure_profile.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::app {

struct ProfileArgs {
  std::string profile;        ///< "z:5" (axis and bin width, Å); empty: none
  std::string excess_energy;  ///< "auto" (median pe of the crystal atoms) or a reference in eV; empty: none
  std::string crystal = "fcc";
  std::string pe_column;      ///< default: the first of pe, c_pe, c_peatom, c_pe_atom, v_pe
};

void add_profile_options(CLI::App& cmd, ProfileArgs& args);

class ProfileOutput {
 public:
  /// Parses the options (InputError naming the option); `analyses` says which structure methods run.
  ProfileOutput(const ProfileArgs& args, const analysis::atoms::StructureAnalyses& analyses);
  bool profiles() const { return profile_.has_value(); }
  bool excess() const { return excess_; }
  /// Opens OUTPUT/profiles.csv.
  void open(const std::filesystem::path& file);
  /// The frame's per-atom excess energy pe − e0 from the dump's pe column (e0 printed when it is
  /// the median of the crystal atoms); the source of StructureAnalyses::excess_energy.
  analysis::atoms::ExcessEnergy excess_energy(const analysis::atoms::AtomFrame& frame,
                                              const analysis::atoms::StructureAnalysisResult& result,
                                              const io::DumpFrame& dump) const;
  /// Writes the frame's profile rows.
  void add(std::size_t frame_index, const analysis::atoms::AtomFrame& frame,
           const analysis::atoms::StructureAnalysisResult& result);
  void close();

 private:
  ProfileArgs args_;
  std::optional<analysis::atoms::StructureProfile> profile_;
  bool excess_ = false;
  std::optional<double> reference_;
  analysis::atoms::Structure crystal_ = analysis::atoms::Structure::fcc;
  std::vector<std::string> methods_;  ///< structure methods on, in column order (cna, acna, bpa)
  io::CheckedOutput out_;
};

}  // namespace shockfield::app
