// `shockfield analyze minkowski|similarity|stats`: morphology and statistics of grid fields
// (Xu et al. 2015, §3.1, §4.1.2). Reads CSV grids and VTK image data (analysis/field_reader.hpp), writes
// CSV and, for minkowski and similarity, a PNG through shockfield_plot (app/python_helpers.hpp;
// skipped with a warning when that fails). Column names carry the input's units (the array's
// `units`, the grid's `length_units`, the .pvd's `time_units`; core/unit_names, docs/conventions.md).
// Docs: docs/analysis-minkowski.md.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <tuple>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/analysis/field_statistics.hpp"
#include "shockfield/analysis/minkowski.hpp"
#include "shockfield/analysis/particle_binning.hpp"
#include "shockfield/analysis/point_frame_reader.hpp"
#include "shockfield/analysis/similarity.hpp"
#include "shockfield/analysis/spectral_statistics.hpp"
#include "shockfield/app/commands.hpp"
#include "shockfield/app/python_helpers.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/unit_names.hpp"
#include "shockfield/io/checked_file.hpp"

namespace shockfield::app {
namespace {

namespace sa = shockfield::analysis;
namespace fs = std::filesystem;

struct Common {
  std::vector<std::string> files;
  std::vector<double> times;
  std::string time_units;  // empty: the .pvd's time_units
  std::string array;
  double bin_size = 0.0;  // particle frames: the side of the cells they are binned on
  std::string output = "analysis";
  int threads = 0;
  int dimension = 0;  // 0: from the grid (3D when it has more than one z layer)
  bool no_plot = false;
};

struct Morphology {
  std::vector<double> thresholds;
  std::size_t count = 0;  // evenly spaced over the first field's range when no list is given
  std::string boundary = "periodic";
  int connectivity = 8, adjacency = 26;
};

const char* kFormats =
    "Fields: .csv/.txt (one line per row, comma-separated, slices separated by a blank line, "
    "`void` marks a void cell, `# spacing = h`), .vtk (legacy ASCII STRUCTURED_POINTS), .vti "
    "(XML ImageData: ascii, binary or appended raw/base64, uncompressed or zlib), .pvti (its parallel "
    "pieces); a .pvd series or a run folder with one .pvd of .vti or .pvti fields stands for its fields "
    "at its times. Particle frames (.vtp, .pvtp, a .pvd of them) are binned with --bin-size H and --array "
    "NAME. See "
    "docs/analysis-minkowski.md.";

void add_common(CLI::App* cmd, Common& c, const char* files_help) {
  cmd->add_option("fields", c.files, files_help)->check(CLI::ExistingPath);
  cmd->add_option("--times", c.times,
                  "Time of each field, in order (default: the .pvd's times, else 0, 1, 2, ...); "
                  "strictly increasing")
      ->delimiter(',');
  cmd->add_option("--time-units", c.time_units,
                  "Unit of the times, named in the time column (time_s, time_ps; default: the "
                  ".pvd's time_units, else 'unknown')");
  cmd->add_option("--dimension", c.dimension,
                  "2 or 3 (default: 3 when the grid has more than one z layer); 3 analyses a grid "
                  "of a single z layer as one layer of voxels")
      ->check(CLI::IsMember({2, 3}));
  cmd->add_option("--array", c.array, "Data array to read from VTK files (default: the first)");
  cmd->add_option("--bin-size", c.bin_size,
                  "Particle frames (.vtp, .pvtp, a .pvd of them: MPM, PD, granular, macroparticle; MD's "
                  "LAMMPS dumps, one frame per file, --array a column): bin --array's values (mean per cell; "
                  "empty cells void) on cubic cells of this side, in the frames' length unit, one grid over "
                  "every frame's particles");
  cmd->add_option("-o,--output", c.output, "Output folder (created if missing)")
      ->capture_default_str();
  cmd->add_option("-j,--threads", c.threads, "OpenMP threads (default: OMP_NUM_THREADS, else all)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-plot", c.no_plot, "Write CSV only, no PNG");
}

void add_morphology(CLI::App* cmd, Morphology& m) {
  cmd->add_option("-t,--thresholds", m.thresholds,
                  "Thresholds Θ_th, comma-separated, strictly increasing (white = Θ >= Θ_th)")
      ->delimiter(',');
  cmd->add_option("-n,--count", m.count,
                  "Instead of --thresholds: this many thresholds evenly spaced over the value "
                  "range of all the fields together (default 32)");
  cmd->add_option("--boundary", m.boundary,
                  "periodic (the grid wraps; the surrounding region does not count, as in eq. 32) "
                  "or open (black outside the grid, scikit-image's convention)")
      ->capture_default_str()
      ->check(CLI::IsMember({"periodic", "open"}));
  cmd->add_option("--connectivity", m.connectivity, "2D connectivity of the white set: 4 or 8")
      ->capture_default_str()
      ->check(CLI::IsMember({4, 8}));
  cmd->add_option("--adjacency", m.adjacency,
                  "3D adjacency of the white set: 26 (pair (26,6)) or 6 (pair (6,26))")
      ->capture_default_str()
      ->check(CLI::IsMember({6, 26}));
}

// The inputs: field files, with .pvd series and run folders expanded into their fields, and the
// units their columns name (empty: the input does not say).
struct Inputs {
  std::vector<std::string> files;
  std::vector<double> times;
  std::vector<sa::GridField> fields;
  std::string time_units;

  const std::string& units() const { return fields.front().units; }
  const std::string& length_units() const { return fields.front().length_units; }
  std::string time_column() const { return units::column_name("time", time_units); }
};

// Every field of one analysis in the same units: a table names one unit per column.
void require_same_units(const sa::GridField& a, const sa::GridField& b, const std::string& file_a,
                        const std::string& file_b) {
  for (const auto& [what, ua, ub] : {std::tuple{"units", &a.units, &b.units},
                                     std::tuple{"length_units", &a.length_units, &b.length_units}})
    if (*ua != *ub)
      throw InputError(fmt::format("{}: {} '{}' but {} has '{}'; expected every field in the same units", file_b,
                                   what, *ub, file_a, *ua));
}

// Times: --times, else the series' times (every input a series), else 0, 1, 2, ...; as many as
// fields, finite and strictly increasing.
std::vector<double> times_of(const Common& c, const std::vector<std::string>& files,
                             const std::vector<double>& series_times, const char* role) {
  std::vector<double> t = c.times;
  if (t.empty() && series_times.size() == files.size()) t = series_times;
  if (t.empty() && !series_times.empty())
    throw InputError(
        fmt::format("{} fields: .pvd series mixed with single files; give --times", role));
  if (t.empty())
    for (std::size_t i = 0; i < files.size(); ++i) t.push_back(double(i));
  if (t.size() != files.size())
    throw InputError(fmt::format("--times: {} times for {} {} fields; expected one per field",
                                 t.size(), files.size(), role));
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k]))
      throw InputError(fmt::format("--times: value {} at position {} is not finite", t[k], k + 1));
    if (k > 0 && !(t[k] > t[k - 1]))
      throw InputError(
          fmt::format("times out of order: {} at position {} follows {}; expected "
                      "strictly increasing times (one field per time)",
                      t[k], k + 1, t[k - 1]));
  }
  return t;
}

Inputs read_all(const Common& c, const std::vector<std::string>& paths, const char* role) {
  if (paths.empty()) throw InputError(fmt::format("analyze: no {} field files given", role));
  Inputs in;
  std::vector<double> series_times;
  std::vector<std::string> series_units;
  for (const auto& p : paths) {
    if (fs::is_directory(p) || fs::path(p).extension() == ".pvd") {
      for (const auto& e : sa::read_series(p))
        in.files.push_back(e.file), series_times.push_back(e.time), series_units.push_back(e.time_units);
    } else {
      in.files.push_back(p);
    }
  }
  in.times = times_of(c, in.files, series_times, role);
  const bool one_series_unit = series_units.size() == in.files.size() &&
                               std::all_of(series_units.begin(), series_units.end(),
                                           [&](const std::string& u) { return u == series_units.front(); });
  in.time_units = !c.time_units.empty() ? c.time_units
                  : c.times.empty() && one_series_unit ? series_units.front() : "";
  const auto frames = std::count_if(in.files.begin(), in.files.end(), sa::is_point_frame_file);
  if (frames > 0 && frames < static_cast<std::ptrdiff_t>(in.files.size()))
    throw InputError(fmt::format("{} fields: particle frames (.vtp, .pvtp, LAMMPS dumps) mixed with grids; give one kind",
                                 role));
  if (frames > 0 && (c.bin_size <= 0.0 || c.array.empty()))
    throw InputError(fmt::format("{}: a particle frame; give --bin-size H (the cell side, in the frame's length "
                                 "unit) and --array NAME (the point array to bin)", in.files.front()));
  if (frames == 0 && c.bin_size > 0.0)
    throw InputError(fmt::format("--bin-size bins particle frames (.vtp, .pvtp, LAMMPS dumps); {} is a grid",
                                 in.files.front()));
  if (frames > 0) in.fields = sa::bin_point_frames(in.files, c.array, c.bin_size);
  for (std::size_t k = 0; k < in.files.size(); ++k) {
    const std::string& f = in.files[k];
    auto& field = frames > 0 ? in.fields[k] : in.fields.emplace_back(sa::read_grid_field(f, c.array));
    if (c.dimension == 2 && field.n[2] > 1)
      throw InputError(
          fmt::format("{}: {} z layers; --dimension 2 needs a single layer", f, field.n[2]));
    field.single_layer_3d = c.dimension == 3;
    sa::require_same_grid(in.fields.front(), field, in.files.front(), f);
    require_same_units(in.fields.front(), field, in.files.front(), f);
  }
  try {  // a unit the column names cannot spell stops here, naming the file
    (void)units::column_suffix(in.units()), (void)units::column_suffix(in.length_units()), (void)in.time_column();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", in.files.front(), e.what()));
  }
  return in;
}

sa::MinkowskiOptions options_of(const Morphology& m) {
  sa::MinkowskiOptions o;
  o.boundary = m.boundary == "open" ? sa::Boundary::open : sa::Boundary::periodic;
  o.connectivity2d = m.connectivity == 4 ? sa::Connectivity2D::four : sa::Connectivity2D::eight;
  o.adjacency3d = m.adjacency == 6 ? sa::Adjacency3D::six_26 : sa::Adjacency3D::twentysix_6;
  return o;
}

std::vector<double> thresholds_of(const Morphology& m, const std::vector<sa::GridField>& fields) {
  if (!m.thresholds.empty() && m.count > 0)
    throw InputError("give either --thresholds or --count, not both");
  if (!m.thresholds.empty()) return m.thresholds;
  const std::vector<sa::GridFieldView> views(fields.begin(), fields.end());
  return sa::linear_thresholds(views, m.count > 0 ? m.count : 32);
}

// Functionals of every field at every threshold, as morphology points and as CSV text rows.
struct Table {
  std::string header;
  std::vector<std::vector<std::string>> rows;            // [field][threshold]
  std::vector<std::vector<sa::MorphologyPoint>> points;  // [field][threshold]
};

Table functionals(const std::vector<sa::GridField>& fields, std::span<const double> thresholds,
                  const sa::MinkowskiOptions& o) {
  Table t;
  const bool three = fields.front().dimension() == 3;
  const std::string& length = fields.front().length_units;
  t.header = three ? fmt::format("V,{},{},{},chi,chi_per_black", units::column_name("S", length, 2),
                                 units::column_name("b", length), units::column_name("M", length))
                   : fmt::format("A,{},chi,chi_per_black", units::column_name("L", length));
  for (const auto& f : fields) {
    auto& rows = t.rows.emplace_back();
    auto& points = t.points.emplace_back();
    if (three) {
      for (const auto& m : sa::minkowski_3d(f, thresholds, o)) {
        rows.push_back(fmt::format("{},{:.10g},{:.10g},{:.10g},{:.10g},{},{:.10g}", m.threshold,
                                   m.volume_fraction, m.surface_area, m.mean_breadth,
                                   m.integral_mean_curvature, m.euler, m.euler_per_black_node));
        points.push_back(sa::morphology_point(m, f));
      }
    } else {
      for (const auto& m : sa::minkowski_2d(f, thresholds, o)) {
        rows.push_back(fmt::format("{},{:.10g},{:.10g},{},{:.10g}", m.threshold, m.area_fraction,
                                   m.boundary_length, m.euler, m.euler_per_black_node));
        points.push_back(sa::morphology_point(m, f));
      }
    }
  }
  return t;
}

// Every write checked: a full disk stops the command with exit 3 naming the file.
io::CheckedOutput open_output(const Common& c, const std::string& name) {
  fs::create_directories(c.output);
  return io::CheckedOutput(fs::path(c.output) / name);
}

void plot(const Common& c, const char* kind, const std::string& csv) {
  if (c.no_plot) return;
  const fs::path dir(c.output);
  const fs::path png = dir / (std::string(kind) + ".png");
  if (plot_csv(kind, dir / csv, png)) std::printf("wrote %s\n", png.string().c_str());
}

void set_threads(const Common& c) {
  if (c.threads > 0) omp_set_num_threads(c.threads);
}

void run_minkowski(const Common& c, const Morphology& m) {
  set_threads(c);
  const Inputs in = read_all(c, c.files, "input");
  const auto thresholds = thresholds_of(m, in.fields);
  const Table t = functionals(in.fields, thresholds, options_of(m));
  auto out = open_output(c, "minkowski.csv");
  out << "file," << in.time_column() << "," << units::column_name("threshold", in.units()) << "," << t.header << "\n";
  for (std::size_t i = 0; i < in.fields.size(); ++i)
    for (const auto& row : t.rows[i])
      out << in.files[i] << "," << in.times[i] << "," << row << "\n";
  out.close();
  std::printf("wrote %s (%zu fields x %zu thresholds)\n",
              (fs::path(c.output) / "minkowski.csv").c_str(), in.fields.size(), thresholds.size());
  plot(c, "minkowski", "minkowski.csv");
}

struct SimilarityArgs {
  std::vector<std::string> reference;
  double reference_threshold = 0.0;
  double t1 = std::numeric_limits<double>::quiet_NaN(), t2 = t1;
};

void run_similarity(const Common& c, const Morphology& m, const SimilarityArgs& s) {
  set_threads(c);
  const Inputs ref = read_all(c, s.reference, "reference"), in = read_all(c, c.files, "candidate");
  sa::require_same_grid(ref.fields.front(), in.fields.front(), "reference fields",
                        "candidate fields");
  if (ref.times != in.times)
    throw InputError(
        fmt::format("similarity: the reference ({} fields) and the candidate ({} "
                    "fields) must be sampled at the same times",
                    ref.fields.size(), in.fields.size()));
  const auto& times = in.times;
  const auto thresholds = thresholds_of(m, in.fields);
  const auto o = options_of(m);
  const std::vector<double> one{s.reference_threshold};
  const Table rt = functionals(ref.fields, one, o), ct = functionals(in.fields, thresholds, o);
  sa::Process reference;
  std::vector<sa::Process> candidates(thresholds.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    reference.times.push_back(times[i]);
    reference.points.push_back(rt.points[i][0]);
    for (std::size_t k = 0; k < thresholds.size(); ++k) {
      candidates[k].times.push_back(times[i]);
      candidates[k].points.push_back(ct.points[i][k]);
    }
  }
  const double t1 = std::isnan(s.t1) ? times.front() : s.t1;
  const double t2 = std::isnan(s.t2) ? times.back() : s.t2;
  const auto match = sa::match_threshold(reference, thresholds, candidates, t1, t2);
  auto out = open_output(c, "similarity.csv");
  out << "# reference threshold " << s.reference_threshold << ", interval [" << t1 << ", " << t2
      << "], best candidate threshold " << match.threshold << " (d_P = " << match.distance << ")\n";
  out << "candidate," << units::column_name("threshold", in.units()) << ",d_P,S_D\n";
  for (std::size_t k = 0; k < thresholds.size(); ++k)
    out << "c," << thresholds[k] << "," << match.distances[k] << ","
        << (match.distances[k] > 0 ? 1.0 / match.distances[k] : INFINITY) << "\n";
  out.close();
  std::printf("best candidate threshold %g: process distance d_P = %g, S_D = %g\n", match.threshold,
              match.distance, 1.0 / match.distance);
  if (thresholds.size() > 1 &&
      (match.threshold == thresholds.front() || match.threshold == thresholds.back()))
    std::fprintf(stderr,
                 "warning: the best threshold %g is at the edge of the candidate range [%g, %g]: the "
                 "minimum of d_P may lie outside it; widen --thresholds\n",
                 match.threshold, thresholds.front(), thresholds.back());
  plot(c, "similarity", "similarity.csv");
}

void run_stats(const Common& c, std::size_t bins) {
  set_threads(c);
  const Inputs in = read_all(c, c.files, "input");
  const auto& fields = in.fields;
  const auto& times = in.times;
  auto stats = open_output(c, "stats.csv");
  auto hist = open_output(c, "histogram.csv");
  auto sk = open_output(c, "structure_factor.csv");
  auto corr = open_output(c, "correlation.csv");
  using units::column_name;
  const std::string time = in.time_column(), &u = in.units(), &length = in.length_units();
  stats << fmt::format("file,{},cells,void_cells,{},{},skewness,kurtosis,{}\n", time, column_name("mean", u),
                       column_name("std", u), column_name("domain_size_R", length));
  hist << fmt::format("file,{},{},{},count\n", time, column_name("lo", u), column_name("hi", u));
  // S(k) = |Σ δΘ e^{−ik·x}|² / N carries the values' unit squared; k is a reciprocal length.
  sk << fmt::format("file,{},{},{},shell_points\n", time, column_name("k", length, -1), column_name("S", u, 2));
  corr << fmt::format("file,{},{},C,shell_points\n", time, column_name("r", length));
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const auto& f = fields[i];
    const auto m = sa::moments(f);
    const double r = m.std > 0.0 ? sa::characteristic_size(f) : 0.0;
    stats << fmt::format("{},{},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", in.files[i],
                         times[i], f.size(), f.void_count(), m.mean, m.std, m.skewness, m.kurtosis,
                         r);
    const auto h = sa::histogram(f, bins);
    for (std::size_t b = 0; b < bins; ++b)
      hist << fmt::format("{},{},{:.10g},{:.10g},{}\n", in.files[i], times[i], h.edges[b],
                          h.edges[b + 1], h.counts[b]);
    if (m.std == 0.0) continue;
    for (const auto& [profile, stream] :
         {std::pair{sa::structure_factor(f), &sk}, std::pair{sa::correlation_function(f), &corr}})
      for (std::size_t j = 0; j < profile.x.size(); ++j)
        *stream << fmt::format("{},{},{:.10g},{:.10g},{}\n", in.files[i], times[i], profile.x[j],
                               profile.values[j], profile.count[j]);
  }
  for (auto* out : {&stats, &hist, &sk, &corr}) out->close();
  std::printf("wrote stats.csv, histogram.csv, structure_factor.csv, correlation.csv in %s\n",
              c.output.c_str());
}

}  // namespace

void add_analyze_command(CLI::App& app) {
  CLI::App* analyze = app.add_subcommand(
      "analyze",
      "Analyse what a run produces. Grid fields (temperature, density, pressure, ...): Minkowski\n"
      "functionals against threshold and time, morphological similarity of two processes, field\n"
      "statistics (Xu et al. 2015, §3.1 and §4.1.2; docs/analysis-minkowski.md). Atoms: per-atom\n"
      "structure and defect clusters (analyze atoms; docs/analysis-atoms.md). Point sets: Delaunay\n"
      "division, clusters and surfaces (analyze geometry; docs/geometry-giso.md).");
  analyze->require_subcommand(1);

  auto mc = std::make_shared<Common>();
  auto mm = std::make_shared<Morphology>();
  CLI::App* mink = analyze->add_subcommand(
      "minkowski",
      "Minkowski functionals of {Θ >= Θ_th} for every field and threshold, all thresholds in one\n"
      "pass: 2D fractional area A, boundary length L (Crofton estimator), Euler characteristic\n"
      "χ = N_W − N_B (eq. 32) and χ/N (eq. 33); 3D volume fraction V, surface area S, mean\n"
      "breadth b, integral mean curvature M = 2πb, χ. Writes OUTPUT/minkowski.csv (file, time,\n"
      "threshold, functionals) and OUTPUT/minkowski.png (functionals against time per threshold,\n"
      "or against threshold for one field).\n" +
          std::string(kFormats));
  add_common(mink, *mc, "Field files, one per time (same grid)");
  add_morphology(mink, *mm);
  mink->callback([mc, mm] { run_minkowski(*mc, *mm); });

  auto sc = std::make_shared<Common>();
  auto sm = std::make_shared<Morphology>();
  auto sargs = std::make_shared<SimilarityArgs>();
  CLI::App* sim = analyze->add_subcommand(
      "similarity",
      "Dynamic similarity (§3.1, Figs. 42-45): for a reference process (its fields at\n"
      "--reference-threshold) find the threshold of a candidate process (FIELDS) that minimises\n"
      "the process distance d_P = mean over [t1, t2] of d(t), d the distance in (A, L/(N h), χ/N)\n"
      "space (3D: (V, S/(N h²), b/(N h), χ/N)); S_D = 1/d_P. Both processes are sampled at the "
      "same\n"
      "--times. Writes OUTPUT/similarity.csv (d_P and S_D per candidate threshold) and\n"
      "OUTPUT/similarity.png.\n" +
          std::string(kFormats));
  add_common(sim, *sc, "Candidate process's field files, one per time");
  add_morphology(sim, *sm);
  sim->add_option("-r,--reference", sargs->reference,
                  "Reference process's field files, one per time")
      ->required()
      ->check(CLI::ExistingPath);
  sim->add_option("--reference-threshold", sargs->reference_threshold,
                  "Threshold T_th1 of the reference process")
      ->required();
  sim->add_option("--t1", sargs->t1, "Start of the time interval (default: first time)");
  sim->add_option("--t2", sargs->t2, "End of the time interval (default: last time)");
  sim->callback([sc, sm, sargs] { run_similarity(*sc, *sm, *sargs); });

  auto tc = std::make_shared<Common>();
  auto bins = std::make_shared<std::size_t>(64);
  CLI::App* stats = analyze->add_subcommand(
      "stats",
      "Field statistics over non-void cells: mean, std, skewness, kurtosis (3 for a Gaussian),\n"
      "histogram, structure factor S(k), correlation function C(r) and the domain size\n"
      "R = 2π/k1 from the first moment of S(k) (field taken as periodic). Writes "
      "OUTPUT/stats.csv,\n"
      "histogram.csv, structure_factor.csv, correlation.csv.\n" +
          std::string(kFormats));
  add_common(stats, *tc, "Field files, one per time");
  stats->add_option("--bins", *bins, "Histogram bins over the value range")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  stats->callback([tc, bins] { run_stats(*tc, *bins); });
  add_analyze_atoms_command(*analyze);
  add_analyze_geometry_command(*analyze);
}

}  // namespace shockfield::app
