#include "shockfield/md/run_output.hpp"

#include <fmt/format.h>

#include <algorithm>


#include "shockfield/analysis/atoms/cluster_selection.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/checked_file.hpp"
#include "shockfield/io/extxyz.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/md/decomposition.hpp"
#include "shockfield/md/diagnostics/profiles.hpp"
#include "shockfield/md/msst_report.hpp"
#include "shockfield/md/nphug_report.hpp"

namespace shockfield::md {

namespace fs = std::filesystem;
using units::metal::mvv2e;
using units::metal::nktv2p;

namespace {

const std::vector<std::string> kThermoColumns{
    "step", "time_ps", "temperature_K", "pe_eV", "ke_eV", "etotal_eV", "econserved_eV",
    "press_bar", "pxx_bar", "pyy_bar", "pzz_bar", "pxy_bar", "pxz_bar", "pyz_bar",
    "volume_A3", "lx_A", "ly_A", "lz_A", "neighbor_rebuilds"};
// With an msst stage in the case (nan in the rows of other stages): LAMMPS f_msst and f_msst[1..4].
const std::vector<std::string> kMsstColumns{"msst_energy_eV", "msst_dhugoniot_K", "msst_drayleigh_bar",
                                            "msst_lagrangian_speed_A_ps", "msst_lagrangian_position_A"};

// With an nphug stage: LAMMPS f_ID[1..3] of fix nphug and the thermostat's Hugoniot target.
const std::vector<std::string> kNphugColumns{"nphug_dhugoniot_K", "nphug_us_A_ps", "nphug_up_A_ps",
                                             "nphug_target_temperature_K"};

std::vector<std::string> thermo_columns(const OutputSpec& spec) {
  std::vector<std::string> c = kThermoColumns;
  if (spec.tilted) c.insert(c.end(), {"xy_A", "xz_A", "yz_A"});
  if (spec.msst_axis) c.insert(c.end(), kMsstColumns.begin(), kMsstColumns.end());
  if (spec.nphug) c.insert(c.end(), kNphugColumns.begin(), kNphugColumns.end());
  return c;
}

std::int64_t frame_step(const fs::path& file) {
  const std::string stem = file.stem().string();  // dump.<step>
  return std::stoll(stem.substr(stem.find('.') + 1));
}

// Per-atom columns computed from the force evaluation, in LAMMPS conventions: pe (eV), ke (eV),
// stress/atom s_ab = −(m v_a v_b + W_ab) in bar·Å³ (compute stress/atom, units "pressure*volume").
// `a`: sim.atoms, or a decomposed run's gathered atoms (then only "ke": no per-atom tallies).
std::vector<double> computed_column(const Simulation& sim, const Atoms& a, const std::string& field) {
  std::vector<double> out(a.nlocal, 0.0);
  const bool per_atom = sim.forces.per_atom && sim.forces.energy_atom.size() == a.nlocal;
  static const std::vector<std::string> stress{"sxx", "syy", "szz", "sxy", "sxz", "syz"};
  static const int comp[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (field == "pe") {
      out[i] = per_atom ? sim.forces.energy_atom[i] : NAN;
    } else if (field == "ke") {
      out[i] = 0.5 * mvv2e * a.mass_of(i) * a.v[i].squaredNorm();
    } else {
      const auto k = static_cast<std::size_t>(std::find(stress.begin(), stress.end(), field) - stress.begin());
      const double kin = mvv2e * a.mass_of(i) * a.v[i][comp[k][0]] * a.v[i][comp[k][1]];
      out[i] = per_atom ? -(kin + sim.forces.virial_atom[i][static_cast<int>(k)]) * nktv2p : NAN;
    }
  }
  return out;
}

bool is_computed(const std::string& f) {
  return f == "pe" || f == "ke" || (f.size() == 3 && f[0] == 's');
}

}  // namespace

RunOutput::RunOutput(const fs::path& folder, const OutputSpec& spec, std::optional<std::int64_t> resume_step,
                     bool writes)
    : folder_(folder), profiles_file_(folder / "profiles.csv"), spec_(spec), resume_step_(resume_step), writes_(writes) {
  if (resume_step) last_thermo_step_ = last_frame_step_ = *resume_step;
  if (!writes) return;
  const double* keep = nullptr;
  double keep_value = 0;
  if (resume_step) {
    keep_value = static_cast<double>(*resume_step);
    keep = &keep_value;
  }
  thermo_ = io::CsvWriter(folder / "thermo.csv", thermo_columns(spec), keep, spec.thermo_full_precision);
  if (spec.profile_every > 0) profiles_ = io::CsvWriter(profiles_file_, profile_columns(), keep);
  if (spec.analysis.every > 0) {
    structure_.emplace(spec.analysis);
    structures_ = io::CsvWriter(folder / "structures.csv", structure_->columns(), keep);
    if (structure_->clusters()) clusters_ = io::CsvWriter(folder / "clusters.csv", analysis::atoms::cluster_columns("step", "time_ps"), keep);
  }
  if (spec.dump_every > 0) {
    fs::create_directories(folder / "dumps");
    if (resume_step)
      for (const auto& entry : fs::directory_iterator(folder / "dumps"))
        if (frame_step(entry.path()) > *resume_step) fs::remove(entry.path());
  }
}

bool RunOutput::dump_needs_per_atom() const {
  for (const auto& f : spec_.dump_fields)
    if (f == "pe" || (f.size() == 3 && f[0] == 's')) return true;
  return false;
}

bool RunOutput::needs_per_atom(std::int64_t step) const {
  if (spec_.profile_every > 0 && step % spec_.profile_every == 0) return true;
  if (structure_ && structure_->excess_energy()) {  // the analysis of this step reads the per-atom energies
    if (step % spec_.analysis.every == 0) return true;
    if (spec_.analysis.dump_columns && spec_.dump_every > 0 && step % spec_.dump_every == 0) return true;
  }
  return spec_.dump_every > 0 && step % spec_.dump_every == 0 && dump_needs_per_atom();
}

void RunOutput::write(const Simulation& sim, bool force_thermo) {
  if ((sim.step % spec_.thermo_every == 0 || force_thermo) && sim.step != last_thermo_step_) write_thermo(sim);
  if (sim.step == last_frame_step_) return;
  last_frame_step_ = sim.step;
  if (spec_.profile_every > 0 && sim.step % spec_.profile_every == 0) {
    const Profile p = bin_profile(sim, spec_.profile_axis, spec_.profile_bin_width);
    for (std::size_t b = 0; b < p.bins.size(); ++b) profiles_.row(profile_row(p, b));
  }
  // [analysis]: one computation serves structures.csv and the dump's columns of this step.
  const bool analysis_due = structure_ && sim.step % spec_.analysis.every == 0;
  const bool dump_due = spec_.dump_every > 0 && sim.step % spec_.dump_every == 0;
  std::optional<analysis::atoms::StructureAnalysisResult> analysed;
  if (analysis_due || (structure_ && dump_due && spec_.analysis.dump_columns)) analysed = structure_->compute(sim);
  if (analysis_due) {
    structures_.row(structure_->row(sim, *analysed));
    if (analysed->clusters)
      for (const auto& row : analysis::atoms::cluster_rows(*analysed->clusters, static_cast<double>(sim.step), sim.time))
        clusters_.row(row);
  }
  if (dump_due) {
    const Atoms gathered = sim.domain ? gather_atoms(*sim.domain, sim.atoms) : Atoms{};  // collective
    if (writes_) write_dump(sim, sim.domain ? gathered : sim.atoms, spec_.analysis.dump_columns ? &*analysed : nullptr);
  }
  if (spec_.h5md_every > 0 && sim.step % spec_.h5md_every == 0) write_h5md(sim);
}

void RunOutput::write_h5md(const Simulation& sim) {
  const Atoms& a = sim.atoms;
  std::vector<std::size_t> order(a.nlocal);  // the file's particle order: by id
  for (std::size_t i = 0; i < a.nlocal; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return a.id[i] < a.id[j]; });
  if (!h5md_) {
    io::H5mdLayout layout;
    layout.particles = a.nlocal;
    for (int d = 0; d < 3; ++d) layout.boundary[d] = sim.box.periodic(d) ? "periodic" : "none";
    layout.elements = {{"position", "Angstrom"}, {"velocity", "Angstrom ps-1"}};
    // eV/Å is not among MDAnalysis's force units: it reads such a file with convert_units=False.
    if (spec_.h5md_forces) layout.elements.push_back({"force", "eV Angstrom-1"});
    for (std::size_t i : order) layout.species.push_back(a.type[i] + 1), layout.ids.push_back(a.id[i]);
    layout.creator_version = shockfield_version() + " (" + shockfield_git_commit() + ")";
    h5md_.emplace(folder_ / "trajectory.h5md", layout, resume_step_);
  }
  std::vector<std::vector<double>> values(spec_.h5md_forces ? 3 : 2);
  for (auto& v : values) v.reserve(3 * order.size());
  for (std::size_t i : order)
    for (int d = 0; d < 3; ++d) {
      values[0].push_back(a.x[i][d]);
      values[1].push_back(a.v[i][d]);
      if (spec_.h5md_forces) values[2].push_back(a.f[i][d]);
    }
  std::array<double, 9> vectors{};  // the edge vectors a, b, c as rows (a tilted cell's too)
  for (int d = 0; d < 3; ++d)
    for (int c = 0; c < 3; ++c) vectors[static_cast<std::size_t>(3 * d + c)] = sim.box.edge(d)[c];
  h5md_->append(sim.step, sim.time, vectors, values);
}

void RunOutput::write_thermo(const Simulation& sim) {
  last_thermo_step_ = sim.step;
  const ThermoState t = sim.thermo();
  double added = 0;
  for (const auto& fix : sim.fixes) added += fix->energy_added();  // the same on every rank
  if (!writes_) return;  // a decomposed run's rank other than 0 took its part in the sums
  const Vec3 l = sim.box.length();
  std::vector<double> row{static_cast<double>(sim.step), sim.time, t.temperature, t.potential, t.kinetic,
                          t.potential + t.kinetic, t.potential + t.kinetic - added, t.pressure, t.pressure_tensor[0],
                          t.pressure_tensor[1], t.pressure_tensor[2], t.pressure_tensor[3], t.pressure_tensor[4],
                          t.pressure_tensor[5], t.volume, l.x(), l.y(), l.z(), static_cast<double>(sim.rebuilds)};
  if (spec_.tilted) row.insert(row.end(), {sim.box.tilt[0], sim.box.tilt[1], sim.box.tilt[2]});
  if (spec_.msst_axis) {
    const FixMsst* msst = find_msst(sim);
    const MsstQuantities q = msst ? msst->quantities(sim) : MsstQuantities{NAN, NAN, NAN, NAN, NAN, NAN, NAN};
    row.insert(row.end(), {q.energy, q.dhugoniot, q.drayleigh, q.lagrangian_speed, q.lagrangian_position});
  }
  if (spec_.nphug) {
    const std::vector<double> h = nphug_thermo_values(sim);  // PHug dHug Us Up TTarget
    row.insert(row.end(), h.begin() + 1, h.end());
  }
  thermo_.row(row);
}

void RunOutput::write_dump(const Simulation& sim, const Atoms& atoms,
                           const analysis::atoms::StructureAnalysisResult* analysed) const {
  std::vector<std::string> basic;
  for (const auto& f : spec_.dump_fields)
    if (!is_computed(f)) basic.push_back(f);
  io::DumpFrame frame = io::make_dump_frame(sim.step, sim.box, atoms, basic);
  if (spec_.dump_time) frame.time = sim.time;
  for (const auto& f : spec_.dump_fields)
    if (is_computed(f)) frame.set_column(f, computed_column(sim, atoms, f));
  if (analysed) analysis::atoms::append_structure_columns(frame, *analysed, atoms.nlocal);
  const std::string ext = spec_.dump_format == "extxyz" ? "xyz" : "lammpstrj";
  const fs::path file = folder_ / "dumps" / fmt::format("dump.{:0{}}.{}", sim.step, spec_.dump_pad, ext);
  io::CheckedOutput out(file);
  const io::DumpWriteOptions options{spec_.dump_full_precision};
  if (spec_.dump_format == "extxyz") io::write_extxyz_frame(out.stream(), frame, atoms.type_names, options);
  else io::write_dump_frame(out.stream(), frame, options);
  out.close();
}

}  // namespace shockfield::md
