#include "shockfield/pd/crystal_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"

namespace shockfield::pd {
namespace {

// Orientation k of stream `seed`, uniform over SO(3).
Mat3 random_orientation(std::uint64_t seed, std::uint64_t k) {
  const Vec3 a = materials::random_bunge_angles(seed, k);
  return materials::bunge_rotation(a[0], a[1], a[2]);
}

}  // namespace

CrystalSpec read_crystal(const Config& t, const materials::MaterialFile* file) {
  CrystalSpec s;
  CrystalMaterial& m = s.base;
  const std::string needed_by = "[material] model = \"crystal\"";
  m.density = materials::case_or_file(t, "density", file, {"elasticity.density", "eos.rho0"}, {}, Range::positive(),
                                      needed_by);
  materials::CrystalViscoplasticity& c = m.aggregate.crystal;
  const std::string systems = t.get_string_or("slip_systems", "fcc");
  try {
    c.systems = materials::slip_systems(systems);
  } catch (const InputError& e) {
    t.fail("slip_systems", e.what());
  }
  // From the case, else the material file, else Table 1 (with a material file, its elastic
  // constants are required: a file without them would silently run Table 1's copper).
  auto over = [&](std::string_view key, double& field, Range range, std::initializer_list<std::string_view> file_keys = {},
                  bool required_with_file = false) {
    const materials::MaterialFile* f = file_keys.size() ? file : nullptr;
    field = materials::case_or_file(t, key, f, file_keys, f && required_with_file ? std::nullopt : std::optional(field),
                                    range, needed_by);
  };
  over("reference_rate", c.reference_rate, Range::positive());  // γ̇0, eq. 37
  over("rate_sensitivity", c.rate_sensitivity, {0.0, 1.0, true, false});  // m
  over("g0", c.initial_resistance, Range::positive(), {"strength.g0"});  // eqs. 38-41
  over("g_s", c.saturation_resistance, Range::positive());
  over("h0", c.hardening, Range::non_negative());
  over("q", c.latent_ratio, Range::non_negative());
  c.hardening_law = t.get_choice_or("hardening_law", {"sech2", "power"}, "sech2") == "power"
                        ? materials::HardeningLaw::power
                        : materials::HardeningLaw::sech2;
  over("hardening_exponent", c.hardening_exponent, Range::positive());  // a (power law only)
  over("c11", c.c11, Range::positive(), {"elasticity.c11"}, true);  // eqs. 31-32
  over("c12", c.c12, {}, {"elasticity.c12"}, true);
  over("c44", c.c44, Range::positive(), {"elasticity.c44"}, true);
  over("substep_factor", c.substep_factor, {0.0, 2.0, true, true});
  try {
    c.validate("crystal");
  } catch (const InputError& e) {
    t.fail("g0", e.what());
  }
  m.slope = materials::case_or_file(t, "hugoniot_slope", file, {"eos.s"}, 0.0, Range::closed(0.0, 10.0), needed_by);
  const std::string kind =
      t.get_choice_or("orientation", {"direction", "euler", "random", "random_grains"}, "direction");
  const auto grains = static_cast<std::size_t>(t.get_int_or("taylor_grains", 1, Range::closed(1, 10000)));
  Mat3 g = Mat3::Identity();
  if (kind == "direction") {
    const auto d = t.get_doubles_or("direction", {1.0, 0.0, 0.0});
    const Vec3 axis(d.size() > 0 ? d[0] : 0.0, d.size() > 1 ? d[1] : 0.0, d.size() > 2 ? d[2] : 0.0);
    if (d.size() != 3 || !(axis.norm() > 0.0))
      t.fail("direction", "a non-zero crystal direction [h, k, l] to load along x");
    g = materials::rotation_loading_along(axis);
  } else if (kind == "euler") {
    const auto e = t.get_doubles("euler_angles_deg", 3);
    try {
      constexpr double deg = std::numbers::pi / 180.0;
      g = materials::bunge_rotation(e[0] * deg, e[1] * deg, e[2] * deg);
    } catch (const InputError& err) {
      t.fail("euler_angles_deg", fmt::format("{} (φ1, φ2 in [0, 360), Φ in [0, 180] degrees)", err.what()));
    }
  } else {
    s.seed = static_cast<std::uint64_t>(t.get_int_or("seed", 1, Range::non_negative()));
  }
  if (kind == "random_grains") {
    if (grains != 1)
      t.fail("taylor_grains", "orientation = \"random_grains\" gives each slab grain one orientation: "
                              "Taylor grains per point are for orientation = \"direction\", \"euler\" or \"random\"");
    s.polycrystal = true;
    const auto planes = t.get_ints("grain_planes", 2, Range::closed(1, 1e6));
    if (planes[0] > planes[1]) t.fail("grain_planes", "[lo, hi] with lo <= hi");
    s.grain_planes = {static_cast<int>(planes[0]), static_cast<int>(planes[1])};
  }
  // The N_g grains of every point (eqs. 42-43): copies of one orientation, or uniform draws.
  m.aggregate.orientations.clear();
  for (std::size_t k = 0; k < grains; ++k)
    m.aggregate.orientations.push_back(kind == "random" ? random_orientation(s.seed, k) : g);
  return s;
}

CrystalBody crystal_body(const CrystalSpec& spec, const PointCloud& cloud) {
  CrystalBody body;
  body.grain.assign(cloud.size(), 0);
  if (!spec.polycrystal) {
    body.materials = {spec.base};
    return body;
  }
  // Lattice planes across x in order; consecutive runs of grain_planes planes form a grain.
  std::map<double, int> plane;
  for (const Vec3& x : cloud.x) plane.emplace(x[0], 0);
  int grain = 0, left = 0;
  std::vector<Mat3> orientation;
  for (auto& [x, g] : plane) {
    if (left == 0) {
      const auto k = static_cast<std::uint64_t>(orientation.size());
      const int span = spec.grain_planes[1] - spec.grain_planes[0] + 1;
      left = spec.grain_planes[0] + std::min(span - 1, static_cast<int>(rng::uniform(spec.seed, k, 3) * span));
      orientation.push_back(random_orientation(spec.seed, k));
      grain = static_cast<int>(orientation.size()) - 1;
    }
    g = grain;
    --left;
  }
  body.grains = static_cast<int>(orientation.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    body.grain[i] = plane.at(cloud.x[i][0]);
    CrystalMaterial m = spec.base;
    m.aggregate.orientations = {orientation[static_cast<std::size_t>(body.grain[i])]};
    body.materials.push_back(m);
  }
  return body;
}

double schmid_factor_along_x(const CrystalMaterial& m) {
  double best = 0.0;
  const Mat3& g = m.aggregate.orientations.front();
  for (const auto& s : m.aggregate.crystal.systems)
    best = std::max(best, std::abs((g * s.direction)[0] * (g * s.normal)[0]));
  return best;
}

}  // namespace shockfield::pd
