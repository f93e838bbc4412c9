#pragma once
// The case of `method = "phasefield"` with `[model] kind = "sharp_front"` (docs/phasefield.md
// §"The sharp-front option"): [grid] (periodic), [model] law, c0, D (or a material file of
// bridge domain-growth --law paper with length_unit and time_unit), [time] dt, end_time, spheres
// in [[initial.sphere]] and [initial.random], [output]. What the option cannot represent
// (ellipsoids, slabs, a field file, walls, the field model's keys) is refused naming the key.
#include <memory>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"
#include "shockfield/core/output_schedule.hpp"
#include "shockfield/core/run_options.hpp"
#include "shockfield/phasefield/grid.hpp"
#include "shockfield/phasefield/sharp_front.hpp"

namespace shockfield::phasefield {

struct SharpFrontCase {
  Grid grid;
  SharpFrontLaw law;
  double dt = 0.0, end_time = 0.0;
  long long steps = 0;  ///< ceil(end_time / dt)
  std::vector<SharpDomain> domains;
  OutputIntervals output;
};

/// True when [model] kind = "sharp_front" (default "field").
bool is_sharp_front(const Config& root);

/// Reads and validates the whole case (InputError naming the file and key).
SharpFrontCase read_sharp_front_case(const Config& root);

/// The run driver's plug-in for the case (sharp_front_run.cpp).
std::unique_ptr<Method> make_sharp_front_method(const Config& root, const RunOptions& options);

}  // namespace shockfield::phasefield
