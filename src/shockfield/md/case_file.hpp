#pragma once
// The MD case file, read and validated completely before anything runs. Keys are documented in
// docs/md.md; each value is read through Config so an error names the file, key and line.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/md/fixes/msst.hpp"
#include "shockfield/md/fixes/nphug.hpp"
#include "shockfield/md/minimize.hpp"

namespace shockfield::md {

struct PistonSpec {
  int axis = 2;
  int side = +1;                   ///< +1: from the low face towards +axis; −1: from the high face
  double speed = 0;                ///< Å/ps
  std::optional<double> position;  ///< Å; default: the box face at the stage start
};

struct StageSpec {
  std::string name;
  long long steps = 0;
  std::string ensemble = "nve";    ///< nve | langevin | nvt | npt | msst | nphug | minimize
  std::string group = "all";
  double temperature = 0;          ///< K (langevin, nvt, npt)
  double damping = 0.1;            ///< ps (langevin, nvt, npt)
  int chain = 3;                   ///< Nosé–Hoover chain length
  double pressure = 0;             ///< bar (npt)
  double pressure_damping = 1.0;   ///< ps (npt)
  bool couple_iso = false;         ///< npt couple = "iso" (else "aniso" or "tri")
  std::optional<std::array<bool, 3>> pressure_dims;  ///< npt barostatted dimensions; default: the periodic ones
  std::array<bool, 3> pressure_tilts{false, false,
                                     false};  ///< npt barostatted tilt factors xy, xz, yz
  Vec3 shear_pressure = Vec3::Zero();  ///< npt target P_xy, P_xz, P_yz, bar (LAMMPS xy Pstart ...)
  std::optional<PistonSpec> piston;
  std::optional<Vec3> deform_rate; ///< 1/ps per dimension
  std::optional<Vec3> deform_tilt_rate;  ///< 1/ps per tilt factor xy, xz, yz (LAMMPS fix deform xy erate ...)
  bool flip = true;                ///< npt, deform: flip a cell whose tilt passes its limit (LAMMPS flip yes)
  MinimizeSettings minimize;
  MsstSettings msst;               ///< ensemble = "msst": the [stage.msst] table
  NphugSettings nphug;             ///< ensemble = "nphug": the [stage.nphug] table
};

struct VelocityAdd {
  std::string group;
  Vec3 velocity = Vec3::Zero();    ///< Å/ps
};

/// [analysis]: per-atom structure analysis during the run (analysis/atoms; docs/md.md), every
/// `every` steps, into structures.csv and optionally the dumps.
struct AnalysisSpec {
  long long every = 0;                       ///< steps; 0: no [analysis] table
  std::vector<std::string> methods{"acna"};  ///< of acna, cna, csp, coordination, bpa, diamond
  double cutoff = 0;                         ///< Å: cna, coordination, bpa
  int csp_neighbors = 12;                    ///< N of the centro-symmetry parameter
  bool dump_columns = false;                 ///< the per-atom columns in every dump frame
  double clusters = 0;                       ///< Å: cluster the selected atoms (0: no clusters.csv)
  std::string cluster_select;                ///< which atoms, as analyze atoms --cluster-select
  std::size_t cluster_min_size = 1;          ///< smaller clusters are dropped
  bool excess_energy = false;                ///< per-atom excess energy pe − e0 (column excess)
  std::optional<double> excess_reference;    ///< e0, eV; none: the median pe of excess_crystal atoms
  std::string excess_crystal = "fcc";        ///< fcc | hcp | bcc
};

struct OutputSpec {
  long long thermo_every = 100;
  long long checkpoint_every = 0;  ///< 0: only when a run ends or is stopped
  long long dump_every = 0;
  std::vector<std::string> dump_fields;
  std::string dump_format = "lammps";  ///< lammps | extxyz
  bool dump_full_precision = false;
  bool thermo_full_precision = false;  ///< thermo.csv values that read back bit for bit
  bool dump_time = false;              ///< ITEM: TIME / Time= (LAMMPS dump_modify time yes)
  int dump_pad = 0;                    ///< digits of the step in frame names (dump_modify pad)
  long long h5md_every = 0;            ///< trajectory.h5md frame interval (0: none)
  bool h5md_forces = false;            ///< the H5MD frames also carry the forces (eV/Å)
  long long profile_every = 0;
  int profile_axis = 2;
  double profile_bin_width = 5.0;  ///< Å
  AnalysisSpec analysis;           ///< the [analysis] table (not [output]'s keys)
  /// Not a key: the shock axis of the first msst stage, when the case has one (the thermo table
  /// and thermo.csv then carry the MSST columns).
  std::optional<int> msst_axis;
  /// Not a key: the case has an nphug stage (the thermo table and thermo.csv then carry the
  /// Hugoniostat columns).
  bool nphug = false;
  /// Not a key: the box is triclinic or a stage tilts it (thermo.csv then carries the tilt
  /// factors xy_A xz_A yz_A after neighbor_rebuilds).
  bool tilted = false;
};

struct MdCase {
  double timestep = 0.001;         ///< ps
  double skin = 2.0;               ///< Å
  int neighbor_every = 1;          ///< LAMMPS neigh_modify every
  int neighbor_delay = 0;          ///< LAMMPS neigh_modify delay
  bool neighbor_check = true;      ///< LAMMPS neigh_modify check
  std::uint64_t seed = 12345;
  std::optional<double> temperature;   ///< initial velocities, K
  std::vector<VelocityAdd> velocity_adds;
  OutputSpec output;
  std::vector<StageSpec> stages;
};

/// Reads [md], [velocity], [output] and [[stage]] (not [system] or [potential]).
MdCase read_md_case(const Config& root);

/// "x" | "y" | "z" → 0 | 1 | 2 for `key` of `table`.
int read_axis(const Config& table, std::string_view key, const std::string& fallback);

/// Per-atom dump fields shockfield knows (LAMMPS names plus pe, ke, sxx..syz).
const std::vector<std::string>& known_dump_fields();

}  // namespace shockfield::md
