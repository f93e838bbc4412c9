#include "in_process.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <string>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/analysis/point_frame_reader.hpp"
#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/expression.hpp"
#include "shockfield/geometry/point_file.hpp"
#include "shockfield/granular/case_file.hpp"
#include "shockfield/io/extxyz.hpp"
#include "shockfield/io/checkpoint_file.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/md/case_file.hpp"
#include "shockfield/materials/material_file.hpp"
#include "shockfield/md/potentials/eam_file.hpp"
#include "shockfield/md/potentials/pair_table_file.hpp"
#include "shockfield/pd/point_cloud.hpp"
#include "shockfield/pd/velocity_file.hpp"
#include "shockfield/phasefield/case_file.hpp"

namespace shockfield::fuzz {

namespace fs = std::filesystem;

void parse_dump(const fs::path& file) {
  for (const auto& frame : io::read_dump(file)) {
    if (frame.has("id")) frame.ids();
    if (frame.has("type")) frame.types();
    frame.positions();
  }
}

void parse_extxyz(const fs::path& file) {
  for (const auto& frame : io::read_extxyz(file)) {
    frame.ids();
    if (frame.has("type")) frame.types();
    frame.positions();
  }
}

void parse_field(const fs::path& file) { analysis::read_grid_field(file.string()); }

void parse_eam(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name.ends_with(".adp")) md::potentials::read_adp(file);
  else if (name.ends_with(".eam.alloy")) md::potentials::read_setfl(file, false);
  else if (name.ends_with(".eam.fs")) md::potentials::read_setfl(file, true);
  else md::potentials::read_funcfl(file);
}

void parse_pair_table(const fs::path& file) {
  for (const char* keyword : {"M11", "M22", "M12"}) md::potentials::read_pair_table(file, keyword);
}

void parse_data(const fs::path& file) { io::read_data(file); }

void parse_point_frame(const fs::path& file) {
  double sum = 0.0;
  const analysis::PointFrame frame = analysis::read_point_frame(file.string(), "radius");  // the fixtures' grains
  for (const double v : frame.xyz) sum += v;
  for (const double v : frame.values) sum += v;
  if (!std::isfinite(sum)) throw InputError(fmt::format("{}: the reader returned a non-finite coordinate", file.string()));
}

void parse_points(const fs::path& file) {
  if (file.extension() == ".txt") geometry::read_points<2>(file);
  else geometry::read_points<3>(file);
}

void parse_case(const fs::path& file) {
  const Config root = Config::load(file);
  const std::string method = root.get_string("method");
  if (method == "md") md::read_md_case(root);
  else if (method == "granular") granular::read_granular_case(root);
  else if (method == "phasefield") phasefield::read_phasefield_case(root);
  else return;  // mpm, pd, dbm: their case readers build the simulation (the binary fuzzers' part)
  root.check_unknown_keys();
}

void parse_pd_cloud(const fs::path& file) {
  const std::string name = file.filename().string();
  const int dim = name.find("_1d") != std::string::npos ? 1 : name.find("_2d") != std::string::npos ? 2 : 3;
  pd::read_cloud(file, dim, 1e-3).bounds();
}

void parse_formulas(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    try {
      const Expression e = Expression::parse(line);
      for (const Vec3& p : {Vec3(0.0, 0.0, 0.0), Vec3(1e-3, -2.5, 7.0), Vec3(1e300, -1e-300, 0.5)}) (void)e(p);
    } catch (const ExpressionError& e) {
      throw InputError(fmt::format("{}:{}: {}", file.string(), number, e.what()));
    }
  }
}

void parse_pd_velocities(const fs::path& file) {
  const pd::PointCloud body = pd::lattice_cloud(2, {3, 2, 1}, 1e-3);
  pd::read_point_velocities(file, 2, body.x, 1e-3);
}

void parse_material(const fs::path& file) {
  const materials::MaterialFile m = materials::MaterialFile::load(file);
  for (const materials::MaterialKey& k : materials::material_keys()) m.get(k.name);
}

void parse_checkpoint(const fs::path& file) { io::CheckpointReader(file).count("step"); }

}  // namespace shockfield::fuzz
