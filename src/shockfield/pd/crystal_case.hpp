#pragma once
// [material] model = "crystal" of a PD case file (docs/pd.md): the crystal viscoplastic law of
// Liu et al. (2025) eqs. 18-41 with Table 1 (OFHC copper) defaults, and the orientation of the body: a
// single crystal loaded along a crystal direction or given Bunge Euler angles, a polycrystal
// whose grains are slabs of 8-12 lattice planes across x with random orientations (Liu et al. 2025, §4.2),
// or N_g grains per point under the Taylor assumption (eqs. 42-43), copies of one orientation or
// random ones shared by every point.
#include <array>
#include <cstdint>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/materials/material_file.hpp"
#include "shockfield/pd/crystal_material.hpp"
#include "shockfield/pd/point_cloud.hpp"

namespace shockfield::pd {

struct CrystalSpec {
  CrystalMaterial base;                  ///< parameters and the N_g grains of every point
  bool polycrystal = false;              ///< slab grains (each point then has one of them)
  std::array<int, 2> grain_planes{8, 12};  ///< lattice planes per grain, drawn uniformly in [lo, hi]
  std::uint64_t seed = 1;                ///< stream of the grain sizes and orientations
};

/// Reads the crystal keys of [material] (model = "crystal" already read); density, c11, c12, c44,
/// g0 and hugoniot_slope not given in the case come from `file` when it has them.
CrystalSpec read_crystal(const Config& t, const materials::MaterialFile* file = nullptr);

struct CrystalBody {
  std::vector<CrystalMaterial> materials;  ///< one for a single crystal, else one per point
  std::vector<int> grain;                  ///< grain of each point (all 0 for a single crystal)
  int grains = 1;
};
/// The per-point materials of the body.
CrystalBody crystal_body(const CrystalSpec& spec, const PointCloud& cloud);

/// Largest Schmid factor |(g m0)·x (g n0)·x| of uniaxial stress along the sample x axis, of the
/// point's first grain.
double schmid_factor_along_x(const CrystalMaterial& m);

}  // namespace shockfield::pd
