#pragma once
// What a `method = "dbm"` run writes while it runs: series.csv (domain means with the TNE
// strength, or the GLS columns, plus the reactive columns of a [reaction] case), profiles/ (line
// profiles along x at row profile_row with the TNE measures, indexed by profiles/index.csv) and
// fields/ with grid.pvd. A resumed run keeps what was written up to its checkpoint and rewrites
// the rest.
#include <cstdint>
#include <filesystem>
#include <optional>

#include "shockfield/dbm/case_file.hpp"
#include "shockfield/dbm/checkpoint.hpp"
#include "shockfield/dbm/gls_run.hpp"
#include "shockfield/dbm/reaction.hpp"
#include "shockfield/io/csv_writer.hpp"
#include "shockfield/io/vtk_xml.hpp"

namespace shockfield::dbm {

/// ρ, u and T of every cell, `macro_at(i, j)`, as cell data on the (nx + 1) × (ny + 1) points of
/// the cell corners, in model units (units="1"): the run's frames and `shockfield convert`.
template <class MacroAt>
io::VtkImage macro_cell_image(const Lattice& l, const MacroAt& macro_at) {
  const std::size_t n = static_cast<std::size_t>(l.nx) * static_cast<std::size_t>(l.ny);
  io::VtkImage img;
  img.points = {static_cast<std::size_t>(l.nx) + 1, static_cast<std::size_t>(l.ny) + 1, 1};
  img.origin = {l.x(0) - 0.5 * l.dx, l.y(0) - 0.5 * l.dy, 0.0};
  img.spacing = {l.dx, l.dy, 1.0};
  std::vector<double> rho(n), u(3 * n, 0.0), T(n);
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const Macro m = macro_at(i, j);
      const std::size_t c = static_cast<std::size_t>(i) + static_cast<std::size_t>(l.nx) * static_cast<std::size_t>(j);
      rho[c] = m.rho, u[3 * c] = m.ux, u[3 * c + 1] = m.uy, T[c] = m.T;
    }
  img.cell_data = {{"rho", 1, std::move(rho), "1"}, {"velocity", 3, std::move(u), "1"}, {"T", 1, std::move(T), "1"}};
  return img;
}

class RunOutput {
 public:
  /// `resumed`: the simulation restored from a checkpoint with `counters`, or null for a fresh
  /// run; `reaction`: the reactive DBM of a [reaction] case (extra columns), or null; `gls`: the
  /// liquid–vapour part of a kind = "gls" case (its own series columns), or null.
  RunOutput(const std::filesystem::path& folder, const DbmOutputSpec& spec, const Simulation* resumed,
            const OutputCounters& counters, const ReactiveFlow* reaction,
            const std::optional<ReactionSpec>& spec_reaction, GlsRunPart* gls);

  void write_series(const Simulation& sim);
  /// profiles/profile_<index>.csv and its row in profiles/index.csv.
  void write_profile(const Simulation& sim, std::int64_t index);
  /// ρ, u, T and the TNE strength D (or the GLS fields) on the cell centres.
  void write_fields(const Simulation& sim);

 private:
  std::filesystem::path folder_;
  int row_;
  io::VtkFormat vtk_;
  const ReactiveFlow* reaction_;
  const std::optional<ReactionSpec>& spec_reaction_;
  GlsRunPart* gls_;
  io::CsvWriter series_, index_;
  io::PvdSeries grid_pvd_;
};

}  // namespace shockfield::dbm
