#include "shockfield/materials/library.hpp"

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

SolidMaterial aluminium_seed000() {
  SolidMaterial m;
  m.name = "aluminium_seed000";
  m.eos = {2700.0, 5350.0, 1.34, 1.96};
  m.strength = J2Plasticity::from_young(69e9, 0.33, 120e6, 384e6);
  m.thermal = {880.0, 237.0, 300.0};
  return m;
}

SolidMaterial copper() {
  SolidMaterial m;
  m.name = "copper";
  m.eos = {8930.0, 3940.0, 1.489, 2.02};
  m.strength = J2Plasticity::from_young(2.0 * 47.7e9 * (1.0 + 0.34), 0.34, 120e6, 470e6);
  m.thermal = {385.0, 401.0, 300.0};
  return m;
}

SolidMaterial elastic_plastic(const std::string& name, double rho0, double young, double poisson,
                              double yield0, double tangent) {
  SolidMaterial m;
  m.name = name;
  m.strength = J2Plasticity::from_young(young, poisson, yield0, tangent);
  const double bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  m.eos = {rho0, std::sqrt(bulk / rho0), 0.0, 0.0};
  m.thermal = {900.0, 0.0, 300.0};
  m.validate();
  return m;
}

namespace {
struct Entry {
  const char* name;
  SolidMaterial (*make)();
};
constexpr Entry kMaterials[] = {{"aluminium_seed000", aluminium_seed000}, {"copper", copper}};
}  // namespace

std::vector<std::string> material_names() {
  std::vector<std::string> names;
  for (const Entry& e : kMaterials) names.emplace_back(e.name);
  return names;
}

SolidMaterial make_material(const std::string& name) {
  for (const Entry& e : kMaterials)
    if (name == e.name) return e.make();
  throw InputError(fmt::format("unknown material '{}' (expected one of: {})", name, fmt::join(material_names(), ", ")));
}

}  // namespace shockfield::materials
