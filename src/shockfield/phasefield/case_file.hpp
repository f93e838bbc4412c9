#pragma once
// The case file of `method = "phasefield"` (docs/phasefield.md): [grid], [model], [time],
// [[initial.sphere]] / [[initial.ellipsoid]] / [[initial.slab]] / [initial.random] and [output].
// Every key through core/config's typed getters; a time step beyond the explicit diffusion limit
// or the reaction limit is refused with the key named.
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/phasefield/grid.hpp"
#include "shockfield/phasefield/initial.hpp"
#include "shockfield/phasefield/model.hpp"
#include "shockfield/phasefield/solver.hpp"

namespace shockfield::phasefield {

struct PhasefieldCase {
  Grid grid;
  Model model;
  Scheme scheme = Scheme::spectral;
  double dt = 0.0;
  double end_time = 0.0;
  long long steps = 0;             ///< ceil(end_time / dt)
  std::vector<Domain> domains;     ///< the listed domains and the random nuclei
  FieldFile field_file;            ///< [initial] file, array: the starting field under the domains
  PressureDependence pressure;     ///< [model.pressure]: D(p); no file: uniform D
  OutputIntervals output;          ///< series_interval, field_interval (frames), checkpoint_every, thermo_every
};

/// [grid] (dimensions, nodes, spacing, [grid.boundary]).
Grid read_phasefield_grid(const Config& grid);
/// The domains of [initial]: spheres, ellipsoids, slabs and the random nuclei (spheres).
std::vector<Domain> read_phasefield_domains(const Config& initial, const Grid& grid);

/// The largest dt that keeps the explicit reaction step monotone about both wells, 1/max(a, 1 − a).
double reaction_step_limit(const Model& model);

/// Reads and validates the whole case (InputError naming the file and key).
PhasefieldCase read_phasefield_case(const Config& root);

}  // namespace shockfield::phasefield
