#pragma once
// The peridynamics case file (method = "pd"), read and validated completely before anything runs.
// Keys are documented in docs/pd.md; every value goes through Config so that an error names the
// file, the key and its line. SI units. The body is a regular lattice (Liu et al. 2025, §1) or a
// point cloud from a file (`points_file`), loaded by the impact of its left half on its right half
// (Liu et al. 2025, Fig. 2) and/or by regions with initial or prescribed velocities or
// displacements, and cut by pre-cracks.
#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/pd/bond_models.hpp"
#include "shockfield/pd/correspondence.hpp"
#include "shockfield/pd/crystal_case.hpp"
#include "shockfield/pd/family.hpp"
#include "shockfield/pd/influence.hpp"
#include "shockfield/pd/precrack.hpp"
#include "shockfield/pd/regions.hpp"

namespace shockfield::pd {

struct BodySpec {
  int dim = 1;
  std::array<int, 3> counts{1, 1, 1};  ///< points along x, y, z (1 beyond dim; all 1 for a cloud)
  /// The points of `points_file` or of the [[body.points]] files in order (positions and volumes),
  /// else none: the lattice of `counts`.
  std::optional<PointCloud> cloud;
  /// Per point of a cloud from [[body.points]]: the index of its file, a body of its own (no bonds
  /// to the other files' points); empty for one body.
  std::vector<int> part;
  double spacing = 0.0;                ///< ΔX [m]
  Vec3 origin = Vec3::Zero();          ///< the lattice's first point [m] (`origin`; a cloud has none)
  double horizon_factor = 3.0;         ///< m of δ = m·ΔX
  Influence influence;
  VolumeCorrection correction = VolumeCorrection::linear;
  double horizon() const { return horizon_factor * spacing; }
  /// The body's points as the case reader walks them (regions.hpp).
  BodyPoints points() const { return {counts, spacing, cloud ? &*cloud : nullptr, origin}; }
};

struct SolverSpec {
  CorrespondenceOptions options;     ///< Riemann correction, zero-energy penalty coefficient
  double end_time = 0.0;             ///< [s]
  std::optional<double> time_step;   ///< fixed Δt [s]; else safety × the stable-step estimate
  double safety = 0.5;               ///< fraction of the stable step when no time_step is given
};

/// Intervals in seconds; profiles are profiles/profile_<k>.csv.
using OutputSpec = OutputIntervals;

/// An ordinary bond law (model = "pmb" or "lps", LAMMPS peri/pmb and peri/lps) with its density and
/// critical-stretch damage.
template <class Law>
struct BondSpec {
  Law law;
  double density = 0.0;  ///< [kg/m^3]
  CriticalStretch damage;
  bool contact = true;   ///< the short-range contact force of LAMMPS's PERI package (contact.hpp)
};
using PmbSpec = BondSpec<PmbModel>;
using LpsSpec = BondSpec<LpsModel>;

struct PdCase {
  BodySpec body;
  /// model = "j2" (Liu et al. 2025, §3.1), "crystal", "pmb" or "lps"
  std::variant<SmallStrainJ2, CrystalSpec, PmbSpec, LpsSpec> material;
  SolverSpec solver;
  double impact_speed = 0.0;  ///< [loading] impact: left half at +v, right half at rest [m/s] (0: none)
  std::vector<LoadRegion> regions;  ///< [[region]]: initial or prescribed velocities, after the impact
  std::vector<Crack> cracks;  ///< [[crack]]: bonds cut before the first step
  OutputSpec output;
  std::vector<std::string> material_notes;  ///< the material file used: path, SHA-256, provenance (for the log)
};

/// Reads [body], [material], [solver], [loading], [[region]], [[crack]] and [output]. [loading] may
/// be left out when some [[region]] loads the body.
PdCase read_pd_case(const Config& root);

}  // namespace shockfield::pd
