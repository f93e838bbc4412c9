// The MD run's case read and checked, and a stage's fixes (run_prepare.hpp).
#include "shockfield/md/run_prepare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "shockfield/core/error.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/md/fixes/deform.hpp"
#include "shockfield/md/fixes/langevin.hpp"
#include "shockfield/md/fixes/msst.hpp"
#include "shockfield/md/fixes/nose_hoover.hpp"
#include "shockfield/md/fixes/nose_hoover_npt.hpp"
#include "shockfield/md/fixes/nphug.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/fixes/piston.hpp"
#include "shockfield/md/potentials/registry.hpp"

namespace shockfield::md {

namespace fs = std::filesystem;

namespace {

// What does not handle a tilted cell yet: the shock methods that move a face along an axis or
// compress the cell along one and the box relaxation of the minimiser. msst along z does: its
// remap (z about the centre, x and y kept) is the uniaxial strain diag(1, 1, e), which keeps c's
// tilts xz and yz, as LAMMPS's fractional remap does; along x or y a tilt would have to follow.
// nphug with style z likewise (its barostat scales xz and yz with lz, LAMMPS's scalexz/scaleyz).
void refuse_with_tilt(const StageSpec& s, const Config& stage, const geometry::Box& box) {
  const std::string tilt = fmt::format("a triclinic box (tilt {} {} {})", box.tilt[0], box.tilt[1], box.tilt[2]);
  if (s.ensemble == "msst" && s.msst.axis != 2)
    stage.table("msst").fail("axis", fmt::format("\"z\" in {}: msst compresses a tilted cell along z only", tilt));
  const bool nphug_z = s.nphug.npt.dims == std::array<bool, 3>{false, false, true} && !s.nphug.npt.iso;
  if (s.ensemble == "nphug" && !nphug_z)
    stage.table("nphug").fail("style", fmt::format("\"z\" in {}: nphug compresses a tilted cell along z only", tilt));
  if (s.ensemble == "minimize" && s.minimize.relax_box != std::array<bool, 3>{false, false, false})
    stage.fail("relax_box", fmt::format("relaxing the box is not supported in {} yet", tilt));
  if (s.piston) stage.fail("piston", fmt::format("a piston is not supported in {} yet", tilt));
}

// An npt stage's barostatted tilts (LAMMPS fix nh's checks): the shear's second dimension
// periodic (xy: y; xz, yz: z), and no fix deform on a barostatted component.
void check_barostatted_tilts(const StageSpec& s, const Config& stage, const geometry::Box& box) {
  const char* key = stage.has("pressure_dims") ? "pressure_dims" : "couple";
  static constexpr std::array<const char*, 3> names{"xy", "xz", "yz"};
  static constexpr std::array<int, 3> second{1, 2, 2};
  for (std::size_t t = 0; t < 3; ++t) {
    if (!s.pressure_tilts[t]) continue;
    if (!box.periodic(second[t]))
      stage.fail(key, fmt::format("npt can only change the {} tilt when {} is periodic", names[t],
                                  "xyz"[second[t]]));
    if (s.deform_tilt_rate && (*s.deform_tilt_rate)[static_cast<int>(t)] != 0)
      stage.fail(
          "deform_tilt_rate",
          fmt::format(
              "the {} tilt is barostatted by npt and deformed at once (LAMMPS: Cannot use fix "
              "npt and fix deform on same component of stress tensor)",
              names[t]));
  }
  for (int d = 0; d < 3; ++d)
    if ((*s.pressure_dims)[d] && s.deform_rate && (*s.deform_rate)[d] != 0)
      stage.fail(
          "deform_rate",
          fmt::format(
              "{} is barostatted by npt and deformed at once (LAMMPS: Cannot use fix npt and "
              "fix deform on same component of stress tensor)",
              "xyz"[d]));
}

// Masses and element names of the atom types. A mass: the case's masses = [...] (LAMMPS `mass`
// after pair_coeff), else the potential file's (pair_coeff sets it, after read_data), else the
// data file's; a data-file mass that differs from the potential's is reported. An element name:
// the case's or the data file's, else the one the potential file gives the type.
void settle_types(const Config& root, Prepared& p) {
  Atoms& atoms = p.system.atoms;
  const auto& file_masses = p.system.file_masses;
  for (int t = 0; t < atoms.ntypes(); ++t) {
    const auto ut = static_cast<std::size_t>(t);
    if (atoms.type_names[ut].empty())
      atoms.type_names[ut] = potentials::potential_type_element(*p.potential, t).value_or("");
    if (atoms.mass[ut] > 0) continue;
    const double file = ut < file_masses.size() ? file_masses[ut] : 0.0;
    const auto m = potentials::potential_type_mass(*p.potential, t);
    if (!m && !(file > 0)) root.table("system").fail("masses", fmt::format("no mass for atom type {} (give masses = [...])", t + 1));
    atoms.mass[ut] = m ? *m : file;
    // 5e-6 relative: the 6 significant digits LAMMPS write_data prints masses with.
    if (m && file > 0 && std::abs(file - *m) > 5e-6 * *m)
      p.notes.push_back(fmt::format("atom type {}: the data file's mass {} amu differs from the potential file's {} amu, "
                                    "which is used (as LAMMPS pair_coeff does); [system] masses = [...] chooses another",
                                    t + 1, file, *m));
  }
}

}  // namespace

// Everything is read and checked here, before the run folder exists.
Prepared prepare(const Config& root, const RunOptions& options) {
  Prepared p;
  const fs::path case_dir = options.case_file.parent_path();
  p.system = build_system(root.table("system"), options.validate_only);
  p.potential = potentials::make_potential(root.table("potential"), case_dir, p.system.atoms.ntypes());
  Atoms& atoms = p.system.atoms;
  settle_types(root, p);
  p.potential->check_types(atoms);
  p.md = read_md_case(root);
  const auto& fields = p.md.output.dump_fields;
  if (p.md.output.dump_every > 0 && std::find(fields.begin(), fields.end(), "element") != fields.end())
    for (int t = 0; t < atoms.ntypes(); ++t)
      if (atoms.type_names[static_cast<std::size_t>(t)].empty())
        root.table("output").fail("dump_fields", fmt::format("the element column needs an element name for atom type {}: "
                                                             "give [system] elements = [...] (or use a potential file that names them)", t + 1));
  if (options.piston_speed) {  // `shockfield hugoniot --speeds`: one run per piston speed
    for (StageSpec& s : p.md.stages)
      if (s.piston) s.piston->speed = *options.piston_speed;
    root.derive("piston_speed_override_A_ps", *options.piston_speed);
  }
  const auto stages = root.tables("stage");
  // A box that is tilted, or that a stage will tilt (deform_tilt_rate, an npt barostat on a tilt).
  const bool tilted = p.system.box.triclinic() ||
                      std::any_of(p.md.stages.begin(), p.md.stages.end(), [](const StageSpec& s) {
                        return s.deform_tilt_rate.has_value() ||
                               std::any_of(s.pressure_tilts.begin(), s.pressure_tilts.end(),
                                           [](bool on) { return on; });
                      });
  p.md.output.tilted = tilted;
  for (std::size_t k = 0; k < p.md.stages.size(); ++k) {
    try {
      p.stage_groups.push_back(p.system.groups.find(p.md.stages[k].group));
    } catch (const InputError& e) {
      stages[k].fail("group", e.what());
    }
    StageSpec& s = p.md.stages[k];
    if (tilted) refuse_with_tilt(s, stages[k], p.system.box);
    if (s.ensemble == "msst")  // LAMMPS: "Fix msst requires a periodic box"
      for (int d = 0; d < 3; ++d)
        if (!p.system.box.periodic(d))
          stages[k].fail("ensemble", fmt::format("msst needs a box periodic in x, y and z; {} is not periodic", "xyz"[d]));
    if (s.ensemble == "nphug")  // as npt below: a barostat changes only periodic dimensions
      for (int d = 0; d < 3; ++d)
        if (s.nphug.npt.dims[d] && !p.system.box.periodic(d))
          stages[k].fail("nphug.style", fmt::format("nphug can only change periodic dimensions; {} is not periodic", "xyz"[d]));
    if (s.ensemble != "npt") continue;
    const geometry::Box& box = p.system.box;
    // couple = "tri" sets the dimensions without pressure_dims
    const char* key = stages[k].has("pressure_dims") ? "pressure_dims"
                      : s.pressure_dims              ? "couple"
                                                     : "ensemble";
    if (!s.pressure_dims) s.pressure_dims = std::array<bool, 3>{box.periodic(0), box.periodic(1), box.periodic(2)};
    for (int d = 0; d < 3; ++d)
      if ((*s.pressure_dims)[d] && !box.periodic(d))
        stages[k].fail(key, fmt::format("npt can only change periodic dimensions; {} is not periodic", "xyz"[d]));
    check_barostatted_tilts(s, stages[k], box);
    if (*s.pressure_dims == std::array<bool, 3>{false, false, false} &&
        s.pressure_tilts == std::array<bool, 3>{false, false, false})
      stages[k].fail(key, "npt needs at least one periodic dimension to barostat");
  }
  for (const auto& add : p.md.velocity_adds)
    p.add_groups.push_back(p.system.groups.find(add.group));
  root.check_unknown_keys();

  const Vec3 l = p.system.box.length();
  root.derive("atoms", static_cast<long long>(p.system.atom_count()));
  root.derive("atom_types", static_cast<long long>(atoms.ntypes()));
  root.derive("box_lengths_A", fmt::format("{} {} {}", l.x(), l.y(), l.z()));
  root.derive("potential_cutoff_A", p.potential->cutoff());
  root.derive("density_g_cc", p.system.total_mass() / p.system.box.volume() * units::metal::amu_per_A3_to_g_per_cc);
  long long total = 0;
  for (const auto& s : p.md.stages) total += s.steps;
  root.derive("total_steps", total);
  return p;
}

void add_stage_fixes(Simulation& sim, const StageSpec& s, std::uint32_t group, std::uint64_t seed) {
  sim.fixes.clear();
  if (s.ensemble == "langevin") sim.fixes.push_back(std::make_unique<FixLangevin>(s.temperature, s.damping, seed, group));
  else if (s.ensemble == "nvt") sim.fixes.push_back(std::make_unique<FixNoseHoover>(s.temperature, s.damping, s.chain, group));
  else if (s.ensemble == "npt")
    sim.fixes.push_back(std::make_unique<FixNoseHooverNpt>(
        NptSettings{s.temperature, s.damping, s.pressure, s.pressure_damping, *s.pressure_dims,
                    s.couple_iso, s.chain, std::nullopt, false, s.pressure_tilts,
                    s.shear_pressure, s.flip},
        group));
  else if (s.ensemble == "msst") sim.fixes.push_back(std::make_unique<FixMsst>(s.msst, group));
  else if (s.ensemble == "nphug") sim.fixes.push_back(std::make_unique<FixNphug>(s.nphug, group));
  else sim.fixes.push_back(std::make_unique<FixNve>(group));
  if (s.piston) {
    const PistonSpec& p = *s.piston;
    const double start = p.position.value_or(p.side > 0 ? sim.box.lo[p.axis] : sim.box.hi[p.axis]);
    sim.fixes.push_back(std::make_unique<FixPiston>(p.axis, p.side, p.speed, start, sim.time));
  }
  if (s.deform_rate || s.deform_tilt_rate)
    sim.fixes.push_back(std::make_unique<FixDeform>(s.deform_rate.value_or(Vec3::Zero()),
                                                    s.deform_tilt_rate.value_or(Vec3::Zero()), sim.box, sim.time,
                                                    s.flip));
}

}  // namespace shockfield::md
