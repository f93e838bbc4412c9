#include "shockfield/app/analyze_atoms_burgers.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "shockfield/app/option_values.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::app {
namespace {

namespace aa = shockfield::analysis::atoms;

Vec3 vector3(const std::string& text, const std::string& what) {
  const auto parts = split_fields(text, ',');
  if (parts.size() != 3) throw InputError(fmt::format("{}: expected three numbers x,y,z, got '{}'", what, text));
  return {finite_number(parts[0], what), finite_number(parts[1], what), finite_number(parts[2], what)};
}


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

BurgersAnalysis::BurgersAnalysis(const BurgersArgs& args, bool clusters_on) {
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
    request_.orient[static_cast<std::size_t>(d)] = v;
  }
  aa::CrystalFrame::from_orient(request_.orient, args.lattice.value_or(1.0), "--burgers-orient");  // validates now
  request_.lattice = args.lattice;
  request_.band = args.band;
  request_.slab = args.slab;
  request_.spacing = args.spacing;
  request_.around_clusters = args.around_clusters;
  for (const std::string& line : args.lines) {
    const std::string what = fmt::format("--burgers-line '{}'", line);
    const auto parts = split_fields(line, ':');
    if (parts.size() != 3) throw InputError(what + ": expected x,y,z:ax,ay,az:radius");
    const Vec3 axis = vector3(parts[1], what);
    const double radius = finite_number(parts[2], what);
    if (!(axis.norm() > 0)) throw InputError(what + ": the axis is the zero vector");
    if (!(radius > 0)) throw InputError(what + ": the radius must be > 0");
    request_.lines.push_back({vector3(parts[0], what), axis, radius});
  }
  for (const std::string& ids : args.id_circuits) {
    std::vector<std::int64_t> circuit;
    for (const std::string& id : split_fields(ids, ',')) {
      const double v = finite_number(id, fmt::format("--burgers-ids '{}'", ids));
      if (v != std::floor(v) || std::abs(v) > 9e15) throw InputError(fmt::format("--burgers-ids '{}': '{}' is not an atom id", ids, id));
      circuit.push_back(static_cast<std::int64_t>(v));
    }
    if (circuit.size() < 3) throw InputError(fmt::format("--burgers-ids '{}': a circuit needs at least 3 atoms", ids));
    request_.id_circuits.push_back(std::move(circuit));
  }
}

void BurgersAnalysis::open(const std::filesystem::path& file) {
  out_ = io::CheckedOutput(file);
  out_.write(analysis::atoms::csv_header(analysis::atoms::burgers_columns()));
}

void BurgersAnalysis::analyze(std::size_t frame_index, const aa::AtomFrame& frame, const aa::ClusterResult* clusters,
                              io::DumpFrame& dump) {
  aa::FrameBurgers f = aa::burgers_circuits(frame, clusters, request_);
  for (std::size_t k = 0; k < f.circuits.size(); ++k) {
    const aa::BurgersResult& r = f.circuits[k].result;
    const std::optional<aa::AxisCircuit>& spec = f.circuits[k].spec;
    const Vec3 centre = spec ? spec->centre : Vec3::Constant(NAN), axis = spec ? Vec3(spec->axis.normalized()) : Vec3::Constant(NAN);
    out_ << fmt::format("{},{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{},{},{},{},{:.10g},{:.10g},{:.10g},{:.4g},{}\n",
                        frame_index, frame.timestep, k + 1, f.circuits[k].source, r.circuit.size(), centre.x(), centre.y(),
                        centre.z(), axis.x(), axis.y(), axis.z(), spec ? spec->radius : NAN, r.text(), r.kind(),
                        r.sixths[0], r.sixths[1], r.sixths[2], r.lab.x(), r.lab.y(), r.lab.z(), r.max_step_error,
                        r.reliable ? 1 : 0);
  }
  if (!f.skipped.empty() && skipped_ == 0) first_skip_ = fmt::format("frame {}, {}", frame_index, f.skipped.front());
  skipped_ += f.skipped.size();
  circuits_ += f.circuits.size();
  out_.flush();
  if (!frame.positions.empty()) dump.set_column("burgers_circuit", std::move(f.on_circuit));
}

}  // namespace shockfield::app
