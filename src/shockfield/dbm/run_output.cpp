#include "shockfield/dbm/run_output.hpp"

#include <fmt/format.h>

#include "shockfield/core/units.hpp"
#include "shockfield/dbm/detonation.hpp"
#include "shockfield/dbm/tne.hpp"
#include "shockfield/io/vtk_pieces.hpp"

namespace shockfield::dbm {

namespace fs = std::filesystem;

namespace {
// Indices of Δ*_2 xx and Δ*_(3,1) x in TneFields (order of kTneNames).
constexpr int kD2xx = 0, kD31x = 7;
}  // namespace

RunOutput::RunOutput(const fs::path& folder, const DbmOutputSpec& spec, const Simulation* resumed,
                     const OutputCounters& counters, const ReactiveFlow* reaction,
                     const std::optional<ReactionSpec>& spec_reaction, GlsRunPart* gls)
    : folder_(folder), row_(spec.profile_row), vtk_(spec.vtk), reaction_(reaction), spec_reaction_(spec_reaction), gls_(gls) {
  const double keep_step = resumed ? static_cast<double>(resumed->steps()) : 0.0;
  const double keep_profile = static_cast<double>(counters.profiles) - 1.0;
  std::vector<std::string> series_columns =
      gls ? gls->series_columns() : std::vector<std::string>{"step", "time", "rho", "vx", "vy", "T", "D"};
  const std::string per = units::model::per_missing_dimensions_column(Lattice::dim);
  if (reaction_)
    series_columns.insert(series_columns.end(), {"lambda", "chemical_energy" + per, "total_energy" + per, "front_x"});
  series_ = io::CsvWriter(folder / "series.csv", series_columns, resumed ? &keep_step : nullptr);
  fs::create_directories(folder / "profiles");
  index_ = io::CsvWriter(folder / "profiles" / "index.csv", {"profile", "step", "time"},
                         resumed ? &keep_profile : nullptr);
  if (spec.field_interval > 0.0) {
    fs::create_directories(folder / "fields");
    const double keep_time = resumed ? resumed->time() : 0.0;
    grid_pvd_ = io::PvdSeries(folder / "grid.pvd", resumed ? &keep_time : nullptr, "1");  // model time units
  }
}

void RunOutput::write_series(const Simulation& sim) {
  if (gls_) return series_.row(gls_->series_row(sim));
  const Lattice& l = sim.lattice();
  double rho = 0, ux = 0, uy = 0, T = 0;
  for (int j = 0; j < l.ny; ++j)
    for (int i = 0; i < l.nx; ++i) {
      const Macro m = sim.macro(i, j);
      rho += m.rho, ux += m.ux, uy += m.uy, T += m.T;
    }
  const double n = static_cast<double>(l.nx) * l.ny;
  std::vector<double> row{static_cast<double>(sim.steps()), sim.time(), rho / n, ux / n, uy / n, T / n,
                          tne_measures(sim).mean_strength};
  if (reaction_) {  // [reaction]: mean λ, Q·Σφ, E + Q·Σφ and the tracked front (detonation.hpp)
    double lambda = 0.0;
    for (int j = 0; j < l.ny; ++j)
      for (int i = 0; i < l.nx; ++i) lambda += reaction_->lambda(i, j);
    const double chemical = reaction_->chemical_energy();
    row.insert(row.end(), {lambda / n, chemical, sim.totals()[3] + chemical,
                           pressure_front(sim, row_, spec_reaction_->front_pressure())});
  }
  series_.row(row);
}

void RunOutput::write_profile(const Simulation& sim, std::int64_t index) {
  const TneFields tne = tne_measures(sim);
  const Lattice& l = sim.lattice();
  std::vector<std::string> columns{"x", "rho", "vx", "vy", "p", "T", "D2xx", "D31x"};
  if (reaction_) columns.insert(columns.end(), {"lambda", "omega"});
  io::CsvWriter csv(folder_ / "profiles" / fmt::format("profile_{}.csv", index), columns);
  for (int i = 0; i < l.nx; ++i) {
    const Macro m = sim.macro(i, row_);
    const std::size_t cell = static_cast<std::size_t>(i) + static_cast<std::size_t>(l.nx) * row_;
    std::vector<double> row{l.x(i), m.rho, m.ux, m.uy, m.rho * m.T, m.T, tne.central[kD2xx][cell], tne.central[kD31x][cell]};
    if (reaction_) row.insert(row.end(), {reaction_->lambda(i, row_), reaction_->consumption(i, row_)});
    csv.row(row);
  }
  index_.row({static_cast<double>(index), static_cast<double>(sim.steps()), sim.time()});
}

void RunOutput::write_fields(const Simulation& sim) {
  io::VtkImage img = macro_cell_image(sim.lattice(), [&](int i, int j) { return sim.macro(i, j); });
  img.length_units = "1";  // lengths in the model's units, as every DBM quantity
  if (gls_) {
    for (io::VtkArray& a : gls_->field_arrays()) img.cell_data.push_back(std::move(a));
  } else {
    img.cell_data.push_back({"D", 1, tne_measures(sim).strength, "1"});
  }
  grid_pvd_.add(sim.time(), io::write_image_frame(folder_, fmt::format("fields/grid_{:09d}", sim.steps()), img, vtk_));
}

}  // namespace shockfield::dbm
