// `shockfield analyze geometry`: the Delaunay division and clusters of a point set (Xu et al.
// 2015 §3.2.3) from a CSV/XYZ file, a LAMMPS dump or a particle frame (.vtp, .pvtp, a .pvd of
// them: analysis/point_frame_reader), and its rolling-ball or packing-sculpting surface. Writes OUTPUT/delaunay.vtu (ParaView), OUTPUT/clusters.csv, OUTPUT/surface.vtp and
// OUTPUT/summary.txt. Docs: docs/geometry-giso.md.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/analysis/point_frame_reader.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/unit_names.hpp"
#include "shockfield/geometry/delaunay.hpp"
#include "shockfield/geometry/delaunay_clusters.hpp"
#include "shockfield/geometry/delaunay_output.hpp"
#include "shockfield/geometry/point_file.hpp"
#include "shockfield/geometry/point_set_surface.hpp"
#include "shockfield/io/checked_file.hpp"

namespace shockfield::app {
namespace {

namespace sg = shockfield::geometry;
namespace fs = std::filesystem;

struct GeometryArgs {
  std::string input;
  std::string output = "geometry";
  int dimension = 3;
  int frame = 0;
  double cluster_distance = 0.0;  // 0: no clusters
  double ball_radius = 0.0;       // 0: no rolling-ball surface (3D only)
  double sculpt_depth = 0.0;      // 0: no packing-sculpting surface (3D only)
  std::string rule = "both";
  std::string surface_method = "delaunay";
  std::string length_units;  // of a file that names none; "" unknown
  bool check = false;
  bool no_mesh = false;
};

// The points of the input and the unit of their coordinates ("" when unknown). A particle frame
// (.vtp, .pvtp) gives its Points' units, a LAMMPS dump its ITEM: UNITS style's length unit; a .pvd
// its frame number `frame` (0-based, −1 the last) in time order. `--length-units` names the unit of
// a file that names none (CSV, XYZ, a dump without ITEM: UNITS, read as Å otherwise: metal units).
template <int N>
std::pair<std::vector<std::array<double, N>>, std::string> input_points(const GeometryArgs& a) {
  const std::string ext = fs::path(a.input).extension().string();
  const auto with_unit = [&](std::vector<std::array<double, N>> points, const std::string& named,
                             const std::string& fallback) {
    if (!named.empty() && !a.length_units.empty() && named != a.length_units)
      throw InputError(fmt::format("{}: its coordinates are in '{}'; --length-units says '{}'", a.input, named,
                                   a.length_units));
    return std::pair{std::move(points), !named.empty() ? named : !a.length_units.empty() ? a.length_units : fallback};
  };
  if (ext != ".vtp" && ext != ".pvtp" && ext != ".pvd") {
    auto set = sg::read_points<N>(a.input, a.frame);
    return with_unit(std::move(set.points), set.length_unit, set.lammps_dump ? "A" : "");
  }
  std::string file = a.input;
  if (ext == ".pvd") {
    const auto series = analysis::read_series(a.input);
    const long long k = a.frame < 0 ? static_cast<long long>(series.size()) + a.frame : a.frame;
    if (k < 0 || k >= static_cast<long long>(series.size()))
      throw InputError(fmt::format("{}: --frame {}; the series has {} frames (0 … {}, or −1 for the last)", a.input,
                                   a.frame, series.size(), series.size() - 1));
    file = series[static_cast<std::size_t>(k)].file;
    if (const std::string e = fs::path(file).extension().string(); e != ".vtp" && e != ".pvtp")
      throw InputError(fmt::format("{}: its frames are {} files; expected particle frames (.vtp, .pvtp)", a.input, e));
  }
  const analysis::PointFrame frame = analysis::read_point_frame(file);
  std::vector<std::array<double, N>> points(frame.xyz.size() / 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int d = 0; d < N; ++d) points[i][static_cast<std::size_t>(d)] = frame.xyz[3 * i + static_cast<std::size_t>(d)];
  return with_unit(std::move(points), frame.position_units, "");
}

template <int N>
void run_geometry(const GeometryArgs& a) {
  auto [points, length_unit] = input_points<N>(a);
  units::column_suffix(length_unit);  // a --length-units no column name can spell stops here (InputError)
  // The VTK files spell an unknown unit "unknown", as the column names do (core/unit_names).
  const std::string vtk_units = length_unit.empty() ? "unknown" : length_unit;
  const auto division = sg::delaunay_division<N>(std::move(points), a.input);
  if (a.check) {
    if (const std::string e = sg::check_delaunay<N>(division); !e.empty())
      throw RunError(fmt::format("{}: the division failed its check: {}", a.input, e));
  }
  std::vector<std::pair<std::string, sg::PointClusters>> clusterings;
  if (a.cluster_distance > 0.0) {
    if (a.rule == "xu2015" || a.rule == "both")
      clusterings.emplace_back("seed_rule", sg::seed_rule_clusters<N>(division, a.cluster_distance));
    if (a.rule == "single-linkage" || a.rule == "both")
      clusterings.emplace_back("single_linkage",
                               sg::single_linkage_clusters<N>(division, a.cluster_distance));
  }
  std::optional<sg::TriangleSurface> surface;
  if (a.ball_radius > 0.0 || a.sculpt_depth > 0.0) {
    if constexpr (N == 3) {
      surface = sg::point_set_surface(division, a.surface_method,
                                      a.surface_method == "packing" ? a.sculpt_depth : a.ball_radius);
    } else {
      throw InputError("--ball-radius/--sculpt-depth: surfaces need --dimension 3");
    }
  }
  // Everything is computed: only now create the output folder.
  fs::create_directories(a.output);
  const fs::path out(a.output);
  sg::PointArrays arrays;
  for (const auto& [name, c] : clusterings)
    arrays.emplace_back(name, std::vector<double>(c.label.begin(), c.label.end()));
  if (!a.no_mesh) sg::write_delaunay_vtu<N>(out / "delaunay.vtu", division, arrays, vtk_units);
  std::vector<std::pair<std::string, const sg::PointClusters*>> refs;
  for (const auto& [name, c] : clusterings) refs.emplace_back(name, &c);
  if (!clusterings.empty()) sg::write_clusters_csv<N>(out / "clusters.csv", division, refs, length_unit);
  // summary.txt names the unit of each length, area and volume as a CSV column would
  // (docs/conventions.md): total_volume_m3, surface_area_A2, total_area_unknown.
  const auto name = [&](const char* quantity, int power) { return units::column_name(quantity, length_unit, power); };
  std::string summary = fmt::format("points {}\nduplicates {}\nsimplices {}\n{} {:.12g}\n", division.points.size(),
                                    division.duplicates, division.simplices.size(),
                                    name(N == 2 ? "total_area" : "total_volume", N), sg::total_volume<N>(division));
  if (a.check) summary += "check passed\n";
  if (surface) {
    sg::write_surface_vtp(out / "surface.vtp", surface->points, surface->triangles, vtk_units);
    summary += fmt::format(
        "surface_triangles {}\n{} {:.12g}\n{} {:.12g}\nsurface_euler_characteristic {}\nsurface_manifold {}\n",
        surface->triangles.size(), name("surface_area", 2), surface->area, name("surface_volume", 3), surface->volume,
        surface->euler_characteristic,
        surface->manifold ? "yes" : "no");
  }
  for (const auto& [name, c] : clusterings) {
    std::size_t largest = 0;
    for (std::size_t s : c.size) largest = std::max(largest, s);
    summary += fmt::format("{}_clusters {}\n{}_largest {}\n", name, c.count, name, largest);
    if (name == "seed_rule") summary += fmt::format("seed_rule_shared_points {}\n", c.shared_points);
  }
  io::replace_file(out / "summary.txt", summary);
  std::fputs(summary.c_str(), stdout);
  std::printf("wrote %s%s%ssummary.txt in %s\n", a.no_mesh ? "" : "delaunay.vtu, ",
              clusterings.empty() ? "" : "clusters.csv, ", surface ? "surface.vtp, " : "",
              a.output.c_str());
}

}  // namespace

void add_analyze_geometry_command(CLI::App& analyze) {
  auto a = std::make_shared<GeometryArgs>();
  CLI::App* cmd = analyze.add_subcommand(
      "geometry",
      "Delaunay division (triangles in 2D, tetrahedra in 3D) and clusters of a point set, by the\n"
      "incremental algorithm of Xu et al. (2015) §3.2.3 with exact predicates (degenerate input\n"
      "such as lattices is triangulated validly; duplicate points are merged). Writes\n"
      "OUTPUT/delaunay.vtu (ParaView; cell data volume, point data cluster labels),\n"
      "OUTPUT/clusters.csv (index, coordinates, one label column per rule) when\n"
      "--cluster-distance is given, OUTPUT/surface.vtp with --ball-radius (rolling-ball\n"
      "surface) or --sculpt-depth (packing-sculpting surface), and OUTPUT/summary.txt.\n"
      "Input: CSV/text (x,y[,z] by header name or the first columns), .xyz (count, comment, 'species x y z' lines), a LAMMPS text\n"
      "dump, or a particle frame of a run (.vtp, .pvtp, or a .pvd of them with --frame: MPM, PD, granular,\n"
      "macroparticle). The outputs name the points' length unit: a frame's, a dump's ITEM: UNITS (A\n"
      "without it), else --length-units, else 'unknown'. See docs/geometry-giso.md.");
  cmd->add_option("points", a->input, "Point file (.csv/.txt, .xyz, a LAMMPS dump, .vtp, .pvtp or a .pvd of them)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "Output folder (created if missing)")
      ->capture_default_str();
  cmd->add_option("--dimension", a->dimension, "2 (x, y) or 3 (x, y, z)")
      ->capture_default_str()
      ->check(CLI::IsMember({2, 3}));
  cmd->add_option("--frame", a->frame, "Frame of a LAMMPS dump or a .pvd, 0-based; -1 = the last")
      ->capture_default_str();
  cmd->add_option("-d,--cluster-distance", a->cluster_distance,
                  "Critical distance d of the clusters (same length unit as the points); "
                  "no clusters without it")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--cluster-rule", a->rule,
                  "xu2015 (the rule of Xu et al. 2015: remove simplices whose shortest edge is longer than d, "
                  "face-connected sets), single-linkage (Delaunay edges shorter than d), or both")
      ->capture_default_str()
      ->check(CLI::IsMember({"xu2015", "single-linkage", "both"}));
  cmd->add_option("-r,--ball-radius", a->ball_radius,
                  "Radius of the rolling ball (3D): writes surface.vtp, the closed, outward "
                  "oriented surface the ball touches rolled from outside, with its area, "
                  "enclosed volume and Euler characteristic in summary.txt")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--surface-method", a->surface_method,
                  "How the rolling-ball surface is found: delaunay (from the Delaunay division: "
                  "every component the ball touches) or pivot (the paper's pivoting ball, steps "
                  "I-III with the searchers MS1/MS3/CS1: the component on the point of largest x), "
                  "or packing (the packing-sculpting surface of Xu et al. 2015 to --sculpt-depth)")
      ->capture_default_str()
      ->check(CLI::IsMember({"delaunay", "pivot", "packing"}));
  cmd->add_option("--length-units", a->length_units,
                  "Unit of the coordinates of a file that names none (CSV/text, XYZ, a dump without ITEM: UNITS), "
                  "e.g. A or m: the column names and VTK units of the outputs say it (default: unknown; A for a dump)");
  cmd->add_flag("--check", a->check,
                "Check the division exactly (orientation, neighbour links, empty circumspheres) "
                "before writing");
  cmd->add_flag("--no-mesh", a->no_mesh, "Do not write delaunay.vtu");
  cmd->add_option("-s,--sculpt-depth", a->sculpt_depth,
                  "Sculpting depth s of --surface-method packing (3D): the convex hull, then "
                  "every tetrahedron behind a surface face whose sphere through the face, shrinking "
                  "from outside, meets its fourth point at a radius above s is removed; writes "
                  "surface.vtp and the same summary lines as --ball-radius")
      ->check(CLI::PositiveNumber);
  cmd->callback([a] {
    // Each method takes its own length: refuse a mismatch rather than ignore it.
    const bool packing = a->surface_method == "packing";
    if (packing && a->sculpt_depth <= 0.0)
      throw InputError("--surface-method packing needs --sculpt-depth S (a positive length)");
    if (packing && a->ball_radius > 0.0)
      throw InputError("--surface-method packing takes --sculpt-depth, not --ball-radius");
    if (!packing && a->sculpt_depth > 0.0)
      throw InputError("--sculpt-depth is the depth of --surface-method packing (the method is " + a->surface_method + ")");
    if (a->dimension == 2)
      run_geometry<2>(*a);
    else
      run_geometry<3>(*a);
  });
}

}  // namespace shockfield::app
