#pragma once
// The case file of `method = "macroparticle"` (docs/macroparticle.md): the atoms ([material]),
// the pair law ([pair]), the specimen ([specimen]: an fcc packing cut to a cylinder by division
// numbers, or a box), the loading ([loading]), the optional Langevin bath ([langevin]), the time
// step ([run]) and the outputs ([output]). Values are SI (e0 in eV per atom, atomic mass in u, as
// tabulated); read_macroparticle_case() validates everything and records the derived values.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/macroparticle/parameters.hpp"
#include "shockfield/macroparticle/plastic_bonds.hpp"

namespace shockfield::macroparticle {

struct SpecimenSpec {
  enum class Shape { cylinder, box } shape = Shape::cylinder;
  double diameter = 0;       ///< m (cylinder)
  long long n_phi = 0;       ///< cubic cells of the packing across the diameter (Table 2, Fig 3)
  long long n_h = 0;         ///< cubic cells along the axis
  std::array<long long, 3> cells{0, 0, 0};  ///< box: cubic cells along x, y, z
  double perturbation = 0;   ///< RMS random displacement per component of the free particles, in r0
  std::uint64_t perturbation_seed = 1;
};

struct LoadingSpec {
  enum class Mode { none, tension, compression } mode = Mode::none;
  double strain_rate = 0;    ///< 1/s, > 0
  double final_strain = 0;   ///< engineering strain of the loaded layers at the end
  bool clamped = false;      ///< ends = "clamped": the loaded layers' x, y held
};

struct LangevinSpec {
  double temperature = 0;    ///< K
  double friction = 0;       ///< γ = α^macro, kg/s (eq 22)
  double pair_viscosity = 0; ///< μ of eq 8, kg/s
  double eta_cg = 1;         ///< η_CG of eq 21
  std::uint64_t seed = 1;
};

struct OutputSpec {
  long long thermo_every = 0;     ///< 0: about ten rows
  long long dump_every = 0;       ///< LAMMPS text dumps, 0: none
  int dump_pad = 1;               ///< digits of the dumps' step in their names (those of the last step, as MD's)
  long long vtk_every = 0;        ///< VTK particles, 0: none
  int vtk_pieces = 1;             ///< pieces per VTK frame (io/vtk_pieces), 1: one .vtp
  long long checkpoint_every = 0;
};

struct MacroparticleCase {
  PairLaw law;
  double cutoff = 0;         ///< in units of r0
  SpecimenSpec specimen;
  LoadingSpec loading;
  std::optional<LangevinSpec> langevin;
  std::optional<PlasticRoute> plasticity;  ///< [plasticity]: the bond law of eq 16
  double dt = 0;             ///< s
  long long steps = 0;
  OutputSpec output;
  std::vector<std::string> material_notes;  ///< the material file's path, hash and provenance, for log.txt
};

MacroparticleCase read_macroparticle_case(const Config& root);

}  // namespace shockfield::macroparticle
