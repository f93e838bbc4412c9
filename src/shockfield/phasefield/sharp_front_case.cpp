#include "shockfield/phasefield/sharp_front_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "shockfield/materials/material_file.hpp"
#include "shockfield/phasefield/case_file.hpp"

namespace shockfield::phasefield {
namespace {

constexpr const char* kWhy = "the sharp-front option (model.kind = \"sharp_front\") evolves spheres only: any other shape "
                             "is unstable under the paper's law (docs/theory/phasefield.md)";

// [model]: law, c0, D from the case, else from the material file in the case's units.
SharpFrontLaw read_law(const Config& model, int dim) {
  for (const char* key : {"a", "anisotropy", "pressure"})
    if (model.has(key))
      model.fail(key, "a key of the field model (kind = \"field\"); the sharp-front option takes law, c0 and D");
  SharpFrontLaw law;
  law.dim = dim;
  const auto material = materials::open_material_file(model);
  const std::vector<std::string> laws{"paper", "allen_cahn"};
  if (!material) {
    law.law = front_law_from_name(model.get_choice("law", laws));
    law.c0 = model.get_double("c0");
    law.D = model.get_double("D", Range::positive());
    return law;
  }
  // c0 = c0_SI T/ℓ, D = D_SI T/ℓ² in the case's units (ℓ = length_unit, T = time_unit).
  const double length = model.get_double("length_unit", Range::positive());
  const double time = model.get_double("time_unit", Range::positive());
  model.derive("time_unit_s", time);
  const std::string alternative = fmt::format("law, c0 and D in {}'s [model]", model.file());
  const auto file_law = material->get_string("phasefield.law");
  if (!model.has("law") && !file_law) material->missing("phasefield.law", "the sharp-front model", alternative);
  law.law = front_law_from_name(model.get_choice_or("law", laws, file_law.value_or("paper")));
  const auto value = [&](const char* key, const char* file_key, Range range, double scale) {
    if (model.has(key)) return model.get_double(key, range);
    const auto v = material->get(file_key);
    if (!v) material->missing(file_key, "the sharp-front model", alternative);
    return materials::file_default(model, key, *material, file_key, *v, range, scale);
  };
  law.c0 = value("c0", "phasefield.front_speed", {}, length / time);
  law.D = value("D", "phasefield.curvature_coefficient", Range::positive(), length * length / time);
  return law;
}

}  // namespace

bool is_sharp_front(const Config& root) {
  const auto model = root.optional_table("model");
  return model && model->get_choice_or("kind", {"field", "sharp_front"}, "field") == "sharp_front";
}

SharpFrontCase read_sharp_front_case(const Config& root) {
  SharpFrontCase c;
  const Config grid = root.table("grid");
  if (grid.has("boundary")) grid.fail("boundary", std::string("not allowed: ") + kWhy + ", in a periodic box");
  c.grid = read_phasefield_grid(grid);
  c.law = read_law(root.table("model"), c.grid.dim);
  const Config time = root.table("time");
  if (time.has("scheme"))
    time.fail("scheme", "not with model.kind = \"sharp_front\": each radius follows its law by RK4 in R^2 (no grid scheme)");
  c.dt = time.get_double("dt", Range::positive());
  c.end_time = time.get_double("end_time", Range::positive());
  c.steps = static_cast<long long>(std::ceil(c.end_time / c.dt - 1e-9));
  const auto initial = root.optional_table("initial");
  if (initial) {
    for (const char* key : {"ellipsoid", "slab", "file"})
      if (initial->has(key)) initial->fail(key, std::string("not allowed: ") + kWhy + "; use [[initial.sphere]] or [initial.random]");
    c.domains = sharp_domains(read_phasefield_domains(*initial, c.grid));
  }
  if (c.domains.empty()) root.fail("initial", "at least one [[initial.sphere]] or [initial.random] (the sharp-front domains)");
  c.output = read_output_intervals(root.optional_table("output"), c.end_time, {.profiles = false, .fields = true, .vtk = true});
  return c;
}

}  // namespace shockfield::phasefield
