#include "shockfield/app/analyze_atoms_burgers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "shockfield/analysis/atoms/line_stations.hpp"
#include "shockfield/app/option_values.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {
namespace {

namespace aa = shockfield::analysis::atoms;

Vec3 vector3(const std::string& text, const std::string& what) {
  const auto parts = split_fields(text, ',');
  if (parts.size() != 3) throw InputError(fmt::format("{}: expected three numbers x,y,z, got '{}'", what, text));
  return {finite_number(parts[0], what), finite_number(parts[1], what), finite_number(parts[2], what)};
}

// The median nearest-neighbour distance × √2: the fcc lattice constant of a mostly fcc frame.
double estimated_lattice_constant(const aa::AtomFrame& frame) {
  const aa::NeighborTable table(frame, {aa::density_cutoff(frame, 12), 1});
  std::vector<double> nearest;
  for (std::size_t i = 0; i < frame.size(); ++i)
    if (!table.of(i).empty()) nearest.push_back(table.delta(i, table.of(i).front()).norm());
  if (nearest.empty()) throw InputError("--burgers: the frame has no pairs of atoms to estimate the lattice constant from");
  std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2), nearest.end());
  return nearest[nearest.size() / 2] * std::numbers::sqrt2;
}

const char* kColumns =
    "frame,timestep,circuit,source,atoms,centre_x,centre_y,centre_z,axis_x,axis_y,axis_z,radius,b,kind,b_h6,b_k6,b_l6,"
    "bx,by,bz,max_step_error,reliable\n";

}  // namespace

void add_burgers_options(CLI::App& cmd, BurgersArgs& a) {
  cmd.add_option("--burgers-line", a.lines,
                 "Burgers circuit around a dislocation line: CENTRE:AXIS:RADIUS as x,y,z:ax,ay,az:r (Å; AXIS is the "
                 "line sense ξ); the circuit is the shortest closed path of nearest-neighbour bonds within "
                 "--burgers-band of the cylinder and --burgers-slab of the plane through CENTRE, winding once "
                 "right-handed about ξ (FS/RH). Repeatable; writes OUTPUT/burgers.csv")
      ->take_all();
  cmd.add_option("--burgers-ids", a.id_circuits,
                 "Burgers circuit through these atoms in order, id,id,id,... (closed: the last steps back to the "
                 "first; consecutive atoms must be nearest neighbours). Repeatable")
      ->take_all();
  cmd.add_flag("--burgers-clusters", a.around_clusters,
               "Burgers circuits around the line of each cluster of --clusters (defect atoms of a dislocation core or "
               "of a stacking-fault ribbon with its partials). A straight cluster gets one circuit: axis its longest "
               "principal axis, centre its centre, radius its second semi-axis plus one bond cutoff. A curved one "
               "(a loop, a bowed partial) gets one circuit per station every --burgers-spacing along it, about the "
               "local line direction of the atoms within one spacing");
  cmd.add_option("--burgers-spacing", a.spacing,
                 "Distance (Å) between the circuits along a curved cluster, and the radius of the neighbourhood that "
                 "gives each its line direction; default 2 a")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--burgers-orient", a.orient,
                 "Crystal directions of the box x, y, z axes, as LAMMPS lattice orient: 'i j k,i j k,i j k' "
                 "(orthogonal, right-handed)")
      ->capture_default_str();
  cmd.add_option("--burgers-lattice", a.lattice,
                 "fcc lattice constant a (Å) of the step set a/2<110>; default: sqrt(2) x the median "
                 "nearest-neighbour distance of the frame")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--burgers-band", a.band, "Half-width (Å) of the circuits' annulus; default 0.5 a")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--burgers-slab", a.slab, "Half-thickness (Å) of the circuits' slab along the line; default 0.66 a")
      ->check(CLI::PositiveNumber);
}

BurgersAnalysis::BurgersAnalysis(const BurgersArgs& args, bool clusters_on) : args_(args) {
  if (args.around_clusters && !clusters_on)
    throw InputError("--burgers-clusters needs --clusters and --cluster-select (which defect atoms form the lines)");
  const auto rows = split_fields(args.orient, ',');
  if (rows.size() != 3) throw InputError(fmt::format("--burgers-orient: expected 'i j k,i j k,i j k', got '{}'", args.orient));
  for (int d = 0; d < 3; ++d) {
    std::istringstream in(rows[static_cast<std::size_t>(d)]);
    aa::Vec3i v;
    std::string extra;
    if (!(in >> v[0] >> v[1] >> v[2]) || (in >> extra))
      throw InputError(fmt::format("--burgers-orient: '{}' is not three integers", rows[static_cast<std::size_t>(d)]));
    orient_[static_cast<std::size_t>(d)] = v;
  }
  aa::CrystalFrame::from_orient(orient_, args.lattice.value_or(1.0), "--burgers-orient");  // validates now
  for (const std::string& line : args.lines) {
    const std::string what = fmt::format("--burgers-line '{}'", line);
    const auto parts = split_fields(line, ':');
    if (parts.size() != 3) throw InputError(what + ": expected x,y,z:ax,ay,az:radius");
    const Vec3 axis = vector3(parts[1], what);
    const double radius = finite_number(parts[2], what);
    if (!(axis.norm() > 0)) throw InputError(what + ": the axis is the zero vector");
    if (!(radius > 0)) throw InputError(what + ": the radius must be > 0");
    line_points_.emplace_back(vector3(parts[0], what), axis);
    line_radii_.push_back(radius);
  }
  for (const std::string& ids : args.id_circuits) {
    std::vector<std::int64_t> circuit;
    for (const std::string& id : split_fields(ids, ',')) {
      const double v = finite_number(id, fmt::format("--burgers-ids '{}'", ids));
      if (v != std::floor(v) || std::abs(v) > 9e15) throw InputError(fmt::format("--burgers-ids '{}': '{}' is not an atom id", ids, id));
      circuit.push_back(static_cast<std::int64_t>(v));
    }
    if (circuit.size() < 3) throw InputError(fmt::format("--burgers-ids '{}': a circuit needs at least 3 atoms", ids));
    id_circuits_.push_back(std::move(circuit));
  }
}

void BurgersAnalysis::open(const std::filesystem::path& file) {
  out_ = io::CheckedOutput(file);
  out_.write(kColumns);
}

std::vector<BurgersAnalysis::Line> BurgersAnalysis::lines_of(const aa::AtomFrame& frame, const aa::ClusterResult* clusters,
                                                             const aa::CrystalFrame& crystal) const {
  const double a = crystal.lattice_constant, bond = crystal.bond_cutoff();
  const double band = args_.band.value_or(0.5 * a), slab = args_.slab.value_or(0.66 * a);
  std::vector<Line> lines;
  for (std::size_t k = 0; k < line_points_.size(); ++k)
    lines.push_back({{line_points_[k].first, line_points_[k].second, line_radii_[k], band, slab, bond},
                     fmt::format("line {}", k + 1)});
  if (!args_.around_clusters || !clusters) return lines;
  std::vector<std::vector<std::size_t>> members(clusters->clusters.size());
  for (std::size_t i = 0; i < clusters->cluster_of.size(); ++i)
    if (clusters->cluster_of[i] >= 0) members[static_cast<std::size_t>(clusters->cluster_of[i])].push_back(i);
  for (std::size_t k = 0; k < clusters->clusters.size(); ++k) {
    const aa::Cluster& c = clusters->clusters[k];
    const double radius = c.semi_axes[1] + bond;
    auto stations = aa::line_stations(frame, members[k], args_.spacing.value_or(2 * a));
    if (c.semi_axes[0] >= 1.5 * c.semi_axes[1] && aa::stations_are_straight(stations, frame.box, c.centre, c.axes.col(0), radius)) {
      lines.push_back({{c.centre, c.axes.col(0), radius, band, slab, bond}, fmt::format("cluster {}", k + 1), true});
      continue;
    }
    aa::orient_circulation(stations, frame.box, c.centre, c.axes.col(2));  // a loop's sense from its normal
    for (std::size_t j = 0; j < stations.size(); ++j)
      lines.push_back({{stations[j].centre, stations[j].tangent, stations[j].half_width + bond, band, slab, bond},
                       fmt::format("cluster {} station {}", k + 1, j + 1), true});
  }
  return lines;
}

void BurgersAnalysis::analyze(std::size_t frame_index, const aa::AtomFrame& frame, const aa::ClusterResult* clusters,
                              io::DumpFrame& dump) {
  const aa::CrystalFrame crystal =
      aa::CrystalFrame::from_orient(orient_, args_.lattice ? *args_.lattice : estimated_lattice_constant(frame), "--burgers-orient");
  const aa::NeighborTable table(frame, {crystal.bond_cutoff(), 0});
  std::vector<double> on_circuit(frame.size(), 0.0);
  std::size_t number = 0;
  auto write = [&](const aa::BurgersResult& r, const std::string& source, const aa::AxisCircuit* spec) {
    ++number;
    for (std::size_t i : r.circuit) on_circuit[i] = double(number);
    const Vec3 centre = spec ? spec->centre : Vec3::Constant(NAN), axis = spec ? Vec3(spec->axis.normalized()) : Vec3::Constant(NAN);
    out_ << fmt::format("{},{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{},{},{},{},{:.10g},{:.10g},{:.10g},{:.4g},{}\n",
                        frame_index, frame.timestep, number, source, r.circuit.size(), centre.x(), centre.y(), centre.z(),
                        axis.x(), axis.y(), axis.z(), spec ? spec->radius : NAN, r.text(), r.kind(), r.sixths[0],
                        r.sixths[1], r.sixths[2], r.lab.x(), r.lab.y(), r.lab.z(), r.max_step_error, r.reliable ? 1 : 0);
  };
  for (const Line& line : lines_of(frame, clusters, crystal)) {
    try {
      write(aa::burgers_vector(frame, aa::circuit_around(frame, table, line.spec), crystal), line.source, &line.spec);
    } catch (const InputError& e) {
      if (!line.automatic) throw;  // a circuit the user placed: its failure is an input error
      // One cluster without a closed circuit must not stop the others.
      if (skipped_++ == 0) first_skip_ = fmt::format("frame {}, {}: {}", frame_index, line.source, e.what());
    }
  }
  for (std::size_t k = 0; k < id_circuits_.size(); ++k)
    write(aa::burgers_vector(frame, aa::circuit_of_ids(frame, id_circuits_[k]), crystal), fmt::format("ids {}", k + 1), nullptr);
  circuits_ += number;
  out_.flush();
  if (!frame.positions.empty()) dump.set_column("burgers_circuit", std::move(on_circuit));
}

}  // namespace shockfield::app
