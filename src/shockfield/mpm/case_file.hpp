#pragma once
// The MPM case file (method = "mpm"), read and validated completely before anything runs. Keys
// are documented in docs/mpm.md; each value is read through Config so an error names the file,
// key and line. SI units throughout. The shock axis is the last one (y in 2D, z in 3D).
#include <optional>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/io/vtk_xml.hpp"
#include "shockfield/materials/solid_material.hpp"
#include "shockfield/mpm/grid.hpp"
#include "shockfield/mpm/sample_builders.hpp"
#include "shockfield/mpm/shock_front.hpp"
#include "shockfield/mpm/simulation.hpp"

namespace shockfield::mpm {

/// How the bodies are set in motion (Xu et al. 2015, §4.1 and §4.2).
enum class LoadingKind {
  Wall,       ///< bodies move at −speed onto a rigid wall at the low face of the shock axis
  Symmetric,  ///< the bodies at +speed hit their mirror image above at −speed
  Tensile,    ///< bodies bonded to a stick wall at the low face move away at +speed (§4.2.2)
  None        ///< each body keeps its own `velocity`; walls as given in [grid]
};

struct CavitySpec {
  double depth = 0.0;   ///< centre above the body's low face along the shock axis [m]
  double radius = 0.0;  ///< [m]
};

struct BodySpec {
  Body body;                          ///< box, spacing, velocity, material index
  std::optional<VoidSpec> pores;      ///< porous body with random voids
  std::optional<CavitySpec> cavity;   ///< single cavity
};

struct WindowSpec {
  double bottom = 0.0;              ///< y1: low edge of the bottom windows [m]
  std::vector<double> heights;      ///< h of each bottom/top window pair [m]
};

struct DiagnosticsSpec {
  WindowSpec windows;
  std::vector<double> histogram_times;  ///< [s]
  int histogram_bins = 50;
  bool histogram_all = false;           ///< all particles instead of the first bottom window
  bool ejecta = true;
  double ejecta_threshold = 0.0;        ///< height above the free surface that counts as ejected [m]
};

/// Intervals in seconds; field frames are .vti (grid) and .vtp (particles).
struct OutputSpec : OutputIntervals {
  bool particles = true;           ///< write particle .vtp with each field frame
};

struct MpmCase {
  GridSpec grid;
  SimulationOptions options;
  std::optional<double> time_step;  ///< fixed Δt [s]; checked against the CFL limit every step
  double end_time = 0.0;            ///< [s]
  std::vector<materials::SolidMaterial> materials;
  std::vector<std::string> material_names;  ///< the case's names, parallel to `materials`
  std::vector<std::string> material_notes;  ///< material files used: path, SHA-256, provenance (for the log)
  std::vector<BodySpec> bodies;
  LoadingKind loading = LoadingKind::None;
  double speed = 0.0;                ///< loading speed [m/s]
  DiagnosticsSpec diagnostics;
  OutputSpec output;
  std::optional<ShockFrontSpec> shock_front;  ///< [shock_front]: the front and Hugoniot tool, when on

  int axis() const { return grid.dim - 1; }
};

/// Reads [grid], [solver], [[material]], [[body]], [loading], [diagnostics], [output] and [shock_front].
/// Geometric consistency (bodies inside the grid, packable porosity, cavity inside its body)
/// is checked when the sample is built (case_builder).
MpmCase read_mpm_case(const Config& root);

}  // namespace shockfield::mpm
