// shockfield._core's atom analyses on numpy arrays (python/shockfield/analysis.py's `structure`
// and `voids` wrap them): coordination, conventional and adaptive CNA, centro-symmetry, bond
// pairs, diamond structure and defect clusters over one neighbour pass with the clusters' domain
// surfaces, the structure profiles along an axis, the voxel field and the Burgers circuits, and the
// voids — the functions `shockfield analyze atoms` calls per frame
// (analysis/atoms/structure_analysis.hpp, atom_surfaces.hpp). Positions are a C-contiguous (n, 3)
// float64 array and the box its lo/hi corners with a LAMMPS boundary code; they are copied once
// into the library's AtomFrame (a memcpy, with the GIL released, as is the analysis).
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "shockfield/analysis/atoms/atom_surfaces.hpp"
#include "shockfield/analysis/atoms/burgers_frame.hpp"
#include "shockfield/analysis/atoms/cluster_selection.hpp"
#include "shockfield/analysis/atoms/cluster_tracking.hpp"
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/analysis/atoms/structure_columns.hpp"
#include "shockfield/analysis/atoms/structure_profile.hpp"
#include "shockfield/analysis/atoms/voxel_field.hpp"
#include "shockfield/core/error.hpp"

namespace py = pybind11;
namespace aa = shockfield::analysis::atoms;

namespace shockfield::python {
namespace {

template <class Code>
py::array_t<std::uint8_t> codes(const std::vector<Code>& s) {
  py::array_t<std::uint8_t> out(static_cast<py::ssize_t>(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i) out.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<std::uint8_t>(s[i]);
  return out;
}

py::dict counts(const aa::StructureCounts& c) {
  py::dict d;
  for (aa::Structure s : aa::kStructures) d[py::str(std::string(aa::structure_name(s)))] = c.of(s);
  return d;
}

// The frame of `positions` (n, 3) in the box lo/hi/tilt (LAMMPS's restricted triclinic cell;
// tilt 0 0 0: orthogonal) with `boundary` ("ppp"), `types` (1-based)
// and `ids` (None: all type 1, ids 1..n); TypeError / ValueError for arrays of the wrong kind.
aa::AtomFrame make_frame(const py::array& positions, const std::vector<double>& lo,
                         const std::vector<double>& hi, const std::vector<double>& tilt,
                         const std::string& boundary, const py::object& types,
                         const py::object& ids) {
  if (positions.dtype().num() != py::dtype::of<double>().num())
    throw py::type_error("positions: expected dtype float64, got " + std::string(py::str(positions.dtype())));
  if (positions.ndim() != 2 || positions.shape(1) != 3)
    throw py::value_error("positions: expected an (n, 3) array, got shape " +
                          std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                              positions.shape(), positions.shape() + positions.ndim()))))));
  if (!(positions.flags() & py::array::c_style))
    throw py::value_error("positions: the array is not C-contiguous; pass numpy.ascontiguousarray(positions)");
  if (lo.size() != 3 || hi.size() != 3 || tilt.size() != 3)
    throw py::value_error("box: expected lo, hi and tilt of 3 values each");
  if (boundary.size() != 3) throw py::value_error("boundary: expected 3 letters p, f or s, got '" + boundary + "'");
  aa::AtomFrame frame;
  for (int d = 0; d < 3; ++d) {
    frame.box.lo[d] = lo[static_cast<std::size_t>(d)];
    frame.box.hi[d] = hi[static_cast<std::size_t>(d)];
    frame.box.boundary[static_cast<std::size_t>(d)] =
        geometry::parse_boundary(std::string(1, boundary[static_cast<std::size_t>(d)]), "boundary");
    frame.box.tilt[d] = tilt[static_cast<std::size_t>(d)];
  }
  if (frame.box.triclinic())
    frame.box.check_tilt("box");  // LAMMPS's limits, as the dump reader checks them
  const auto n = static_cast<std::size_t>(positions.shape(0));
  if (!types.is_none()) frame.types = types.cast<std::vector<int>>();
  if (!ids.is_none()) frame.ids = ids.cast<std::vector<std::int64_t>>();
  frame.positions.resize(n);
  py::gil_scoped_release release;
  if (n > 0) std::memcpy(static_cast<void*>(frame.positions.data()), positions.data(), n * sizeof(Vec3));  // 3 doubles each
  return frame;
}

// Columns of named values as a dict of numpy arrays (shockfield.analysis makes it a structured array).
py::dict columns_dict(const std::vector<std::string>& names, const std::vector<std::vector<double>>& rows) {
  py::dict out;
  for (std::size_t c = 0; c < names.size(); ++c) {
    py::array_t<double> column(static_cast<py::ssize_t>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) column.mutable_at(static_cast<py::ssize_t>(r)) = rows[r][c];
    out[py::str(names[c])] = column;
  }
  return out;
}

py::dict surface_set(const aa::SurfaceSet& s) {
  py::dict out;
  py::array_t<double> points({static_cast<py::ssize_t>(s.points.size()), py::ssize_t{3}});
  if (!s.points.empty()) std::memcpy(points.mutable_data(), s.points.data(), s.points.size() * sizeof(s.points[0]));
  py::array_t<std::int32_t> triangles({static_cast<py::ssize_t>(s.triangles.size()), py::ssize_t{3}});
  if (!s.triangles.empty())
    std::memcpy(triangles.mutable_data(), s.triangles.data(), s.triangles.size() * sizeof(s.triangles[0]));
  out["points"] = points;
  out["triangles"] = triangles;
  return out;
}

// domains.csv's columns after frame and timestep.
py::dict domains_dict(const aa::DomainResult& r) {
  std::vector<std::vector<double>> rows;
  for (const aa::Domain& d : r.domains)
    rows.push_back({double(d.cluster + 1), double(d.atoms), d.volume, d.area, aa::equivalent_radius(d.volume),
                    d.atoms_volume, aa::equivalent_radius(d.atoms_volume), d.centre.x(), d.centre.y(), d.centre.z(),
                    double(d.euler_characteristic), d.manifold ? 1.0 : 0.0});
  py::dict out = columns_dict(aa::domain_columns(), rows);
  out["surfaces"] = surface_set(r.surfaces);
  out["flat"] = r.flat;
  return out;
}

// profiles.csv's columns after frame and timestep: per bin its range, atoms and the fraction of
// each structure of each structure method.
py::dict profile_dict(const std::vector<std::pair<std::string, std::vector<aa::ProfileBin>>>& per_method, bool excess) {
  std::vector<std::string> methods;
  for (const auto& [method, bins] : per_method)
    if (!method.empty()) methods.push_back(method);
  const std::vector<std::string> names = aa::profile_columns(methods, excess);
  std::vector<std::vector<double>> rows;
  const auto& bins = per_method.front().second;
  for (std::size_t b = 0; b < bins.size(); ++b) {
    std::vector<double> row{double(b), bins[b].lo, bins[b].hi, 0.5 * (bins[b].lo + bins[b].hi), double(bins[b].counts.total)};
    for (const auto& [method, method_bins] : per_method)
      if (!method.empty())
        for (aa::Structure t : aa::kStructures) row.push_back(method_bins[b].counts.fraction(t));
    if (excess) row.push_back(bins[b].mean_value());
    rows.push_back(std::move(row));
  }
  return columns_dict(names, rows);
}

struct ClusterOptions {
  std::optional<double> cutoff;
  std::optional<std::string> select;
  std::size_t min_size = 1;
  std::optional<double> domains;  // probe, Å
  std::string domains_surface;
  std::size_t domains_min_atoms = 4;
  std::string profile_axis;  // "": no profile
  double profile_width = 0;  // Å
};

// The request of --burgers-* from shockfield.analysis.structure's burgers_* arguments (a dict with
// every key: lines [(centre, axis, radius)], ids [[id, ...]], clusters, orient, lattice, band,
// slab, spacing).
aa::BurgersRequest burgers_request(const py::dict& b, bool clusters_on) {
  aa::BurgersRequest r;
  r.orient_name = "burgers_orient";
  const auto orient = b["orient"].cast<std::vector<std::array<int, 3>>>();
  if (orient.size() != 3) throw py::value_error("burgers_orient: expected three (i, j, k) directions");
  for (std::size_t d = 0; d < 3; ++d) r.orient[d] = aa::Vec3i(orient[d][0], orient[d][1], orient[d][2]);
  r.lattice = b["lattice"].cast<std::optional<double>>();
  r.band = b["band"].cast<std::optional<double>>();
  r.slab = b["slab"].cast<std::optional<double>>();
  r.spacing = b["spacing"].cast<std::optional<double>>();
  r.around_clusters = b["clusters"].cast<bool>();
  if (r.around_clusters && !clusters_on)
    throw InputError("burgers_clusters needs clusters and cluster_select (which defect atoms form the lines)");
  const auto lines = b["lines"].cast<std::vector<std::tuple<std::array<double, 3>, std::array<double, 3>, double>>>();
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto& [c, a, radius] = lines[k];
    const Vec3 axis(a[0], a[1], a[2]);
    if (!(axis.norm() > 0)) throw InputError(fmt::format("burgers_lines[{}]: the axis is the zero vector", k));
    if (!(radius > 0)) throw InputError(fmt::format("burgers_lines[{}]: the radius must be > 0", k));
    r.lines.push_back({Vec3(c[0], c[1], c[2]), axis, radius});
  }
  for (const auto& ids : b["ids"].cast<std::vector<std::vector<std::int64_t>>>()) {
    if (ids.size() < 3) throw InputError("burgers_ids: a circuit needs at least 3 atoms");
    r.id_circuits.push_back(ids);
  }
  return r;
}

// burgers.csv's columns after frame and timestep (source, b and kind as text).
py::dict burgers_dict(const aa::FrameBurgers& f) {
  std::vector<std::vector<double>> rows;
  py::list source, text, kind;
  for (std::size_t k = 0; k < f.circuits.size(); ++k) {
    const aa::BurgersResult& r = f.circuits[k].result;
    const auto& spec = f.circuits[k].spec;
    const Vec3 centre = spec ? spec->centre : Vec3::Constant(NAN), axis = spec ? Vec3(spec->axis.normalized()) : Vec3::Constant(NAN);
    rows.push_back({double(k + 1), double(r.circuit.size()), centre.x(), centre.y(), centre.z(), axis.x(), axis.y(),
                    axis.z(), spec ? spec->radius : NAN, double(r.sixths[0]), double(r.sixths[1]), double(r.sixths[2]),
                    r.lab.x(), r.lab.y(), r.lab.z(), r.max_step_error, r.reliable ? 1.0 : 0.0});
    source.append(f.circuits[k].source);
    text.append(r.text());
    kind.append(r.kind());
  }
  std::vector<std::string> numbers = aa::burgers_columns();
  std::erase_if(numbers, aa::is_text_column);
  py::dict out = columns_dict(numbers, rows);
  out["source"] = source;
  out["b"] = text;
  out["kind"] = kind;
  return out;
}

// The per-atom excess energy pe − e0 (--excess-energy): pe per atom (eV), e0 the median pe of the
// `crystal` atoms (auto) or the reference given.
struct ExcessOptions {
  std::optional<std::vector<double>> pe;
  bool automatic = false;
  std::optional<double> reference;
  std::string crystal = "fcc";
  bool on() const { return automatic || reference.has_value(); }
};

// The clusters of a series of frames followed in time (--track): each structure() call given
// the tracker adds its frame's clusters.
struct Tracker {
  aa::ClusterTracker tracker;
  std::size_t frames = 0;

  py::dict tracks(long long origin, double dt, bool time_in_ps) const {
    return columns_dict(aa::track_columns(time_in_ps), aa::track_rows(tracker.tracks(), origin, dt));
  }
  // growth.csv: the power laws of each track with 3 or more points at t > 0.
  py::dict growth(long long origin, double dt) const {
    std::vector<std::vector<double>> rows;
    py::list quantity;
    for (const aa::ClusterTrack& t : tracker.tracks())
      for (const aa::PowerLawFit& f : aa::fit_growth(t, origin, dt)) {
        rows.push_back({double(t.number), f.exponent, f.exponent_stderr, f.prefactor, double(f.points)});
        quantity.append(f.quantity);
      }
    py::dict out = columns_dict({"track", "exponent", "exponent_stderr", "prefactor", "points"}, rows);
    out["quantity"] = quantity;
    return out;
  }
};

// How a Python caller turns on the analysis a selection reads (parse_cluster_selection's `enabled_by`).
std::string python_option_of(const std::string& method) {
  return method == "excess" ? std::string("excess_energy and pe")
       : method == "bpa"    ? std::string("bond_pairs=CUTOFF")
       : method == "csp"    ? std::string("csp=N")
                            : method + "=CUTOFF";
}

// The voxel field (--voxel) as numpy arrays shaped (nz, ny, nx), x fastest as in voxels_<timestep>.vti.
py::dict voxel_dict(const aa::VoxelField& v) {
  const std::vector<py::ssize_t> shape{py::ssize_t(v.n[2]), py::ssize_t(v.n[1]), py::ssize_t(v.n[0])};
  py::array_t<double> fraction(shape), density(shape);
  std::copy(v.fraction.begin(), v.fraction.end(), fraction.mutable_data());
  std::copy(v.density.begin(), v.density.end(), density.mutable_data());
  py::dict out;
  out["fraction"] = fraction;
  out["density"] = density;
  out["origin"] = py::make_tuple(v.origin[0], v.origin[1], v.origin[2]);
  out["spacing"] = v.spacing;
  out["stretch"] = py::make_tuple(v.stretch[0], v.stretch[1], v.stretch[2]);
  out["empty_nodes"] = v.empty_nodes;
  out["selected"] = v.selected;
  return out;
}

py::dict structure(const py::array& positions, const std::vector<double>& lo,
                   const std::vector<double>& hi, const std::vector<double>& tilt,
                   const std::string& boundary, const py::object& types, const py::object& ids,
                   std::optional<double> coordination, std::optional<double> cna, bool adaptive_cna,
                   const py::object& csp, std::optional<double> bond_pairs, bool diamond,
                   const ClusterOptions& c, const ExcessOptions& e, const py::object& burgers,
                   const py::object& voxel, Tracker* tracker, long long timestep, int threads) {
  const ThreadCount thread_count(threads);
  aa::AtomFrame frame = make_frame(positions, lo, hi, tilt, boundary, types, ids);
  frame.timestep = timestep;
  if (tracker && !c.cutoff) throw InputError("tracker needs clusters and cluster_select (the clusters it follows)");
  aa::StructureAnalyses analyses;
  if (coordination) analyses.coordination = aa::Coordination{*coordination};
  if (cna) analyses.cna = aa::ConventionalCna{*cna};
  if (adaptive_cna) analyses.adaptive_cna = aa::AdaptiveCna{};
  if (!csp.is_none())
    analyses.centro_symmetry = aa::CentroSymmetry{aa::CentroSymmetry::parse_neighbors(py::str(csp), "csp")};
  if (bond_pairs) analyses.bond_pairs = aa::BondPairAnalysis{*bond_pairs};
  if (diamond) analyses.diamond = aa::DiamondCna{};
  if (c.cutoff.has_value() != c.select.has_value())
    throw InputError("clusters and cluster_select go together: the cutoff and which atoms to cluster");
  if (c.cutoff) {
    analyses.select =
        aa::parse_cluster_selection(*c.select, analyses, e.on(), "cluster_select '" + *c.select + "'", python_option_of);
    analyses.clusters = aa::DefectClusters{*c.cutoff, c.min_size};
  }
  if (e.on()) {
    if (!e.pe) throw InputError("excess_energy needs the per-atom potential energies: pass pe (eV, one per atom)");
    if (e.pe->size() != frame.size())
      throw py::value_error(fmt::format("pe: expected {} values (one per atom), got {}", frame.size(), e.pe->size()));
    if (e.automatic && !analyses.cna && !analyses.adaptive_cna && !analyses.bond_pairs)
      throw InputError("excess_energy='auto' needs a structure method (adaptive_cna, cna or bond_pairs) to find the crystal atoms");
    const aa::Structure crystal = e.crystal == "hcp" ? aa::Structure::hcp : e.crystal == "bcc" ? aa::Structure::bcc : aa::Structure::fcc;
    analyses.excess_energy = [&e, crystal](const aa::StructureAnalysisResult& r) {
      return aa::excess_energy(*e.pe, r, crystal, e.reference ? &*e.reference : nullptr);
    };
  }
  std::optional<aa::VoxelOptions> voxel_options;
  aa::ClusterSelection voxel_select;
  if (!voxel.is_none()) {
    const py::dict v = voxel.cast<py::dict>();
    const auto spec = v["select"].cast<std::string>();
    voxel_select = aa::parse_cluster_selection(spec, analyses, e.on(), "voxel_select '" + spec + "'", python_option_of);
    voxel_options = aa::VoxelOptions{v["spacing"].cast<double>(), v["smoothing"].cast<double>()};
  }
  std::optional<aa::BurgersRequest> burgers_wanted;
  if (!burgers.is_none()) burgers_wanted = burgers_request(burgers.cast<py::dict>(), c.cutoff.has_value());
  if (c.domains && !c.cutoff)
    throw InputError("domains needs the clusters that form the domains: add clusters=CUTOFF and cluster_select "
                     "(e.g. clusters=3, cluster_select='acna:bcc')");
  std::optional<aa::StructureProfile> profile;
  if (!c.profile_axis.empty()) {
    if (c.profile_axis != "x" && c.profile_axis != "y" && c.profile_axis != "z")
      throw py::value_error("profile: expected (AXIS, WIDTH) with AXIS 'x', 'y' or 'z', got '" + c.profile_axis + "'");
    profile = aa::StructureProfile{static_cast<int>(std::string("xyz").find(c.profile_axis[0])), c.profile_width};
  }
  aa::StructureAnalysisResult r;
  std::optional<aa::DomainResult> domains;
  std::vector<std::pair<std::string, std::vector<aa::ProfileBin>>> profiles;
  std::optional<aa::FrameBurgers> circuits;
  std::optional<aa::VoxelField> voxels;
  {
    py::gil_scoped_release release;
    validate_frame(frame, "positions");
    r = analyze_structure(frame, analyses);
    if (profile) profiles = profile->per_method(frame, r, r.excess_energy);
    if (voxel_options) voxels = aa::voxel_fraction(frame, voxel_select(r), *voxel_options);
    if (burgers_wanted) circuits = aa::burgers_circuits(frame, r.clusters ? &*r.clusters : nullptr, *burgers_wanted);
    if (c.domains)
      domains = aa::domain_surfaces(frame, *r.clusters,
                                    aa::DomainSurfaces{*c.domains, c.domains_surface == "packing", c.domains_min_atoms});
  }
  py::dict out;
  py::dict counts_row;  // structures.csv's count and fraction columns
  const std::vector<std::string> count_names = aa::structure_count_columns(analyses);
  const std::vector<double> count_values = aa::structure_count_values(r);
  for (std::size_t k = 0; k < count_names.size(); ++k) counts_row[py::str(count_names[k])] = count_values[k];
  out["counts"] = counts_row;
  if (r.diamond) out["dia"] = codes(r.diamond->structure);
  if (r.clusters) {
    std::vector<std::int32_t> cluster(r.clusters->cluster_of.begin(), r.clusters->cluster_of.end());
    for (std::int32_t& k : cluster) ++k;  // the dump column: 1, 2, ... largest first; 0 none
    out["cluster"] = to_numpy(cluster);
    std::vector<std::string> names = aa::cluster_columns("frame", "timestep");
    std::vector<std::vector<double>> rows = aa::cluster_rows(*r.clusters, 0.0, 0.0);
    names.erase(names.begin(), names.begin() + 2);
    for (auto& row : rows) row.erase(row.begin(), row.begin() + 2);
    out["clusters"] = columns_dict(names, rows);
  }
  if (domains) out["domains"] = domains_dict(*domains);
  if (profile) out["profile"] = profile_dict(profiles, e.on());
  if (!r.excess_energy.empty()) out["excess"] = to_numpy(r.excess_energy);
  if (voxels) out["voxels"] = voxel_dict(*voxels);
  if (tracker) {
    tracker->tracker.add(tracker->frames++, frame.timestep, frame.ids, *r.clusters);
    std::vector<std::int32_t> track(frame.size(), 0);
    for (std::size_t i = 0; i < frame.size(); ++i)
      if (r.clusters->cluster_of[i] >= 0)
        track[i] = tracker->tracker.last_tracks()[static_cast<std::size_t>(r.clusters->cluster_of[i])];
    out["track"] = to_numpy(track);
  }
  if (circuits) {
    out["burgers"] = burgers_dict(*circuits);
    std::vector<std::int32_t> on(circuits->on_circuit.begin(), circuits->on_circuit.end());
    out["burgers_circuit"] = to_numpy(on);
    out["burgers_skipped"] = circuits->skipped;
  }
  if (!r.coordination.empty()) out["coord"] = to_numpy(r.coordination);
  for (const auto& [name, result] : {std::pair{"cna", &r.cna}, std::pair{"acna", &r.adaptive_cna}})
    if (*result) {
      out[name] = codes((*result)->structure);
      out[py::str(std::string(name) + "_counts")] = counts((*result)->counts);
    }
  if (!r.centro_symmetry.empty()) out["csp"] = to_numpy(r.centro_symmetry);
  if (r.bond_pairs) {
    out["bpa"] = codes(r.bond_pairs->structure);
    out["bpa_counts"] = counts(r.bond_pairs->counts);
    out["bond_offset"] = to_numpy(r.bond_pairs->offset);
    out["bond_partner"] = to_numpy(r.bond_pairs->partner);
    out["bond_index"] = to_numpy(r.bond_pairs->index);
  }
  return out;
}

// voids.csv's columns after frame and timestep, and the voids' surfaces.
py::dict voids(const py::array& positions, const std::vector<double>& lo,
               const std::vector<double>& hi, const std::vector<double>& tilt,
               const std::string& boundary, const py::object& types, const py::object& ids,
               double probe, std::optional<double> atomic_volume, std::optional<double> margin,
               double min_volume) {
  const aa::AtomFrame frame = make_frame(positions, lo, hi, tilt, boundary, types, ids);
  aa::VoidResult r;
  {
    py::gil_scoped_release release;
    validate_frame(frame, "positions");
    r = aa::find_voids(frame, aa::VoidSearch{probe, atomic_volume, margin, min_volume});
  }
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < r.voids.size(); ++k) {
    const aa::Void& v = r.voids[k];
    rows.push_back({double(k + 1), double(v.cells), v.volume, v.area, aa::equivalent_radius(v.volume), v.missing_volume,
                    aa::equivalent_radius(v.missing_volume), v.centre.x(), v.centre.y(), v.centre.z(),
                    double(v.surface_atoms), double(v.euler_characteristic), v.manifold ? 1.0 : 0.0});
  }
  py::dict out = columns_dict(aa::void_columns(), rows);
  out["surfaces"] = surface_set(r.surfaces);
  return out;
}

}  // namespace

void bind_atoms(py::module_& m) {
  m.def(
      "atoms_structure",
      [](const py::array& positions, const std::vector<double>& lo, const std::vector<double>& hi,
         const std::vector<double>& tilt, const std::string& boundary, const py::object& types,
         const py::object& ids, std::optional<double> coordination, std::optional<double> cna,
         bool adaptive_cna, const py::object& csp, std::optional<double> bond_pairs, bool diamond,
         std::optional<double> clusters, std::optional<std::string> cluster_select,
         std::size_t cluster_min_size, std::optional<double> domains,
         const std::string& domains_surface, std::size_t domains_min_atoms,
         const std::string& profile_axis, double profile_width,
         std::optional<std::vector<double>> pe, bool excess_auto,
         std::optional<double> excess_reference, const std::string& excess_crystal,
         const py::object& burgers, const py::object& voxel, Tracker* tracker, long long timestep,
         int threads) {
        return structure(
            positions, lo, hi, tilt, boundary, types, ids, coordination, cna, adaptive_cna, csp,
            bond_pairs, diamond,
            ClusterOptions{clusters, cluster_select, cluster_min_size, domains, domains_surface,
                           domains_min_atoms, profile_axis, profile_width},
            ExcessOptions{std::move(pe), excess_auto, excess_reference, excess_crystal}, burgers,
            voxel, tracker, timestep, threads);
      },
      py::arg("positions"), py::arg("lo"), py::arg("hi"), py::arg("tilt"), py::arg("boundary"),
      py::arg("types"), py::arg("ids"), py::arg("coordination"), py::arg("cna"),
      py::arg("adaptive_cna"), py::arg("csp"), py::arg("bond_pairs"), py::arg("diamond"),
      py::arg("clusters"), py::arg("cluster_select"), py::arg("cluster_min_size"),
      py::arg("domains"), py::arg("domains_surface"), py::arg("domains_min_atoms"),
      py::arg("profile_axis"), py::arg("profile_width"), py::arg("pe"), py::arg("excess_auto"),
      py::arg("excess_reference"), py::arg("excess_crystal"), py::arg("burgers"), py::arg("voxel"),
      py::arg("tracker").none(true), py::arg("timestep"), py::arg("threads"));
  py::class_<Tracker>(m, "ClusterTracker", "Clusters followed through frames; use shockfield.analysis.ClusterTracker")
      .def(py::init<>())
      .def_readonly("frames", &Tracker::frames, "Frames added so far")
      .def("tracks", &Tracker::tracks, "tracks.csv's columns, by name", py::arg("origin"), py::arg("dt"), py::arg("time_in_ps"))
      .def("growth", &Tracker::growth, "growth.csv's columns, by name", py::arg("origin"), py::arg("dt"));
  m.def("atoms_voids", &voids, py::arg("positions"), py::arg("lo"), py::arg("hi"), py::arg("tilt"),
        py::arg("boundary"), py::arg("types"), py::arg("ids"), py::arg("probe"),
        py::arg("atomic_volume"), py::arg("margin"), py::arg("min_volume"));
}

}  // namespace shockfield::python
