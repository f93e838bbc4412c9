// shockfield._core's field analysis on numpy arrays (python/shockfield/analysis.py wraps it):
// Minkowski functionals, dynamic similarity and field statistics, the same functions
// `shockfield analyze` calls. Arrays are float64 and C-contiguous, laid out (ny, nx) or
// (nz, ny, nx) so that x varies fastest as in analysis::GridField; anything else raises.
// The computation runs with the GIL released on OpenMP threads (`threads`, 0: the default).
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/analysis/field_statistics.hpp"
#include "shockfield/analysis/gaussian_random_field.hpp"
#include "shockfield/analysis/minkowski.hpp"
#include "shockfield/analysis/similarity.hpp"
#include "shockfield/analysis/spectral_statistics.hpp"
#include "shockfield/core/error.hpp"

namespace py = pybind11;
namespace sa = shockfield::analysis;

namespace shockfield::python {
namespace {

constexpr int kNumpyDouble = 12, kNumpyBool = 0, kNumpyUint8 = 2;  // NPY_DOUBLE, NPY_BOOL, NPY_UBYTE

// Raises TypeError / ValueError (never a crash) unless `array` is a C-contiguous 2D or 3D array
// of the numpy type number `dtype`.
void require_array(const py::array& array, int dtype, const char* dtype_name, const std::string& what) {
  if (array.dtype().num() != dtype)
    throw py::type_error(what + ": expected dtype " + dtype_name + ", got " +
                         std::string(py::str(array.dtype())) + " (convert with numpy.asarray(a, dtype=numpy." +
                         dtype_name + "))");
  if (array.ndim() != 2 && array.ndim() != 3)
    throw py::value_error(what + ": expected a 2D (ny, nx) or 3D (nz, ny, nx) array, got " +
                          std::to_string(array.ndim()) + " dimension(s)");
  if (!(array.flags() & py::array::c_style))
    throw py::value_error(what + ": the array is not C-contiguous (a transposed or strided view); pass "
                          "numpy.ascontiguousarray(a)");
  for (py::ssize_t k = 0; k < array.ndim(); ++k)
    if (array.shape(k) == 0) throw py::value_error(what + ": the array is empty");
}

// The field of `values` (and its void mask, None or a bool/uint8 array of the same shape), read in
// place: the view points into the numpy arrays, which the caller keeps alive for the call. Its
// values are checked by the analysis itself (analysis::validate, as in the C++ calls: one pass
// over the field, not two); `checked_view_of` checks them here to name one field among several.
sa::GridFieldView view_of(const py::array& values, const py::object& void_mask, const std::array<double, 3>& spacing,
                          int dimension, const std::string& what) {
  require_array(values, kNumpyDouble, "float64", what);
  if (dimension != 0 && dimension != 2 && dimension != 3)
    throw py::value_error("dimension: expected 2, 3 or None, got " + std::to_string(dimension));
  if (dimension == 2 && values.ndim() == 3 && values.shape(0) > 1)
    throw py::value_error(what + ": dimension=2 needs a 2D array (or a single z layer)");
  const py::ssize_t nd = values.ndim();
  sa::GridFieldView f;
  f.n = {std::size_t(values.shape(nd - 1)), std::size_t(values.shape(nd - 2)),
         nd == 3 ? std::size_t(values.shape(0)) : 1};
  f.spacing = spacing;
  f.single_layer_3d = dimension == 3 && f.n[2] == 1;
  f.values = {static_cast<const double*>(values.data()), f.size()};
  if (!void_mask.is_none()) {
    const auto mask = void_mask.cast<py::array>();
    require_array(mask, mask.dtype().num() == kNumpyBool ? kNumpyBool : kNumpyUint8, "bool", what + " void mask");
    if (mask.ndim() != nd || !std::equal(mask.shape(), mask.shape() + nd, values.shape()))
      throw py::value_error(what + ": the void mask's shape differs from the field's");
    f.is_void = {static_cast<const std::uint8_t*>(mask.data()), f.size()};
  }
  return f;
}

sa::GridFieldView checked_view_of(const py::array& values, const std::array<double, 3>& spacing, int dimension,
                                  const std::string& what) {
  const sa::GridFieldView f = view_of(values, py::none(), spacing, dimension, what);
  py::gil_scoped_release release;
  sa::validate(f, what);
  return f;
}

sa::MinkowskiOptions options_of(const std::string& boundary, int connectivity, int adjacency) {
  sa::MinkowskiOptions o;
  if (boundary != "periodic" && boundary != "open")
    throw py::value_error("boundary: expected 'periodic' or 'open', got '" + boundary + "'");
  if (connectivity != 4 && connectivity != 8)
    throw py::value_error("connectivity: expected 4 or 8, got " + std::to_string(connectivity));
  if (adjacency != 6 && adjacency != 26)
    throw py::value_error("adjacency: expected 6 or 26, got " + std::to_string(adjacency));
  o.boundary = boundary == "open" ? sa::Boundary::open : sa::Boundary::periodic;
  o.connectivity2d = connectivity == 4 ? sa::Connectivity2D::four : sa::Connectivity2D::eight;
  o.adjacency3d = adjacency == 6 ? sa::Adjacency3D::six_26 : sa::Adjacency3D::twentysix_6;
  return o;
}

// `shockfield analyze`'s rule: the given thresholds, else `count` evenly spaced over the range of
// all the fields.
std::vector<double> thresholds_of(const std::optional<std::vector<double>>& thresholds, std::size_t count,
                                  std::span<const sa::GridFieldView> fields) {
  if (thresholds && count > 0) throw InputError("give either thresholds or count, not both");
  if (thresholds) return *thresholds;
  return sa::linear_thresholds(fields, count > 0 ? count : 32);
}

// The functionals of every threshold as columns, with the morphology points for similarity.
struct Functionals {
  py::dict columns;
  std::vector<sa::MorphologyPoint> points;
};

Functionals functionals(const sa::GridFieldView& f, const std::vector<double>& thresholds, const sa::MinkowskiOptions& o) {
  Functionals out;
  std::vector<double> t, a, l, b, mc, e_n;
  std::vector<std::int64_t> euler;
  if (f.dimension() == 3) {
    std::vector<sa::Functionals3D> rows;
    {
      py::gil_scoped_release release;
      rows = sa::minkowski_3d(f, thresholds, o);
    }
    for (const auto& r : rows) {
      t.push_back(r.threshold), a.push_back(r.volume_fraction), l.push_back(r.surface_area);
      b.push_back(r.mean_breadth), mc.push_back(r.integral_mean_curvature), euler.push_back(r.euler);
      e_n.push_back(r.euler_per_black_node), out.points.push_back(sa::morphology_point(r, f));
    }
    out.columns["threshold"] = to_numpy(t), out.columns["V"] = to_numpy(a);
    out.columns["S"] = to_numpy(l), out.columns["b"] = to_numpy(b);
    out.columns["M"] = to_numpy(mc);
  } else {
    std::vector<sa::Functionals2D> rows;
    {
      py::gil_scoped_release release;
      rows = sa::minkowski_2d(f, thresholds, o);
    }
    for (const auto& r : rows) {
      t.push_back(r.threshold), a.push_back(r.area_fraction), l.push_back(r.boundary_length);
      euler.push_back(r.euler), e_n.push_back(r.euler_per_black_node);
      out.points.push_back(sa::morphology_point(r, f));
    }
    out.columns["threshold"] = to_numpy(t), out.columns["A"] = to_numpy(a);
    out.columns["L"] = to_numpy(l);
  }
  out.columns["chi"] = to_numpy(euler), out.columns["chi_per_black"] = to_numpy(e_n);
  return out;
}

std::array<double, 3> spacing_of(const std::vector<double>& spacing) {
  if (spacing.size() == 1) return {spacing[0], spacing[0], spacing[0]};
  if (spacing.size() == 3) return {spacing[0], spacing[1], spacing[2]};
  throw py::value_error("spacing: expected one number or three (hx, hy, hz)");
}

py::dict minkowski(const py::array& field, const std::optional<std::vector<double>>& thresholds, std::size_t count,
                   const std::string& boundary, int connectivity, int adjacency, int dimension,
                   const std::vector<double>& spacing, const py::object& void_mask, int threads) {
  const ThreadCount thread_count(threads);
  const auto o = options_of(boundary, connectivity, adjacency);
  const sa::GridFieldView f = view_of(field, void_mask, spacing_of(spacing), dimension, "field");
  return functionals(f, thresholds_of(thresholds, count, {&f, 1}), o).columns;
}

// A process: fields (one per time) at `thresholds`, as one process per threshold.
std::vector<sa::Process> processes(const std::vector<py::array>& fields, const std::vector<double>& times,
                                   const std::vector<double>& thresholds, const sa::MinkowskiOptions& o,
                                   const std::array<double, 3>& spacing, int dimension, const std::string& role) {
  if (fields.size() != times.size())
    throw InputError(role + ": " + std::to_string(fields.size()) + " fields for " + std::to_string(times.size()) +
                     " times; expected one field per time");
  std::vector<sa::Process> out(thresholds.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const auto f = checked_view_of(fields[i], spacing, dimension, role + " field " + std::to_string(i));
    const auto points = functionals(f, thresholds, o).points;
    for (std::size_t k = 0; k < thresholds.size(); ++k) {
      out[k].times.push_back(times[i]);
      out[k].points.push_back(points[k]);
    }
  }
  return out;
}

py::dict similarity(const std::vector<py::array>& reference, double reference_threshold,
                    const std::vector<py::array>& candidate, const std::vector<double>& times,
                    const std::optional<std::vector<double>>& thresholds, std::size_t count,
                    std::optional<double> t1, std::optional<double> t2, const std::string& boundary,
                    int connectivity, int adjacency, int dimension, const std::vector<double>& spacing, int threads) {
  const ThreadCount thread_count(threads);
  if (reference.empty() || candidate.empty()) throw InputError("similarity: no fields given");
  const auto o = options_of(boundary, connectivity, adjacency);
  const auto h = spacing_of(spacing);
  std::vector<sa::GridFieldView> fields;  // views of `candidate`'s arrays, alive for the call
  for (std::size_t k = 0; k < candidate.size(); ++k)
    fields.push_back(checked_view_of(candidate[k], h, dimension, "candidate field " + std::to_string(k)));
  const auto ts = thresholds_of(thresholds, count, fields);
  const auto ref = processes(reference, times, {reference_threshold}, o, h, dimension, "reference");
  const auto cand = processes(candidate, times, ts, o, h, dimension, "candidate");
  const auto match = sa::match_threshold(ref.front(), ts, cand, t1.value_or(times.front()), t2.value_or(times.back()));
  std::vector<double> s_d;
  for (const double d : match.distances) s_d.push_back(1.0 / d);
  py::dict out;
  out["thresholds"] = to_numpy(ts), out["d_P"] = to_numpy(match.distances), out["S_D"] = to_numpy(s_d);
  out["best_threshold"] = match.threshold, out["best_distance"] = match.distance;
  return out;
}

py::dict profile_dict(const sa::RadialProfile& p) {
  py::dict d;
  d["x"] = to_numpy(p.x), d["values"] = to_numpy(p.values), d["count"] = to_numpy(p.count);
  return d;
}

py::dict statistics(const py::array& field, std::size_t bins, int dimension, const std::vector<double>& spacing,
                    const py::object& void_mask, int threads) {
  const ThreadCount thread_count(threads);
  if (bins == 0) throw py::value_error("bins: expected at least 1");
  const sa::GridFieldView f = view_of(field, void_mask, spacing_of(spacing), dimension, "field");
  sa::Moments m;
  sa::Histogram hist;
  double size = 0.0;
  std::optional<sa::RadialProfile> sk, corr;
  {
    py::gil_scoped_release release;
    m = sa::moments(f);
    hist = sa::histogram(f, bins);
    if (m.std > 0.0) size = sa::characteristic_size(f), sk = sa::structure_factor(f), corr = sa::correlation_function(f);
  }
  py::dict out;
  out["cells"] = f.size(), out["void_cells"] = f.void_count(), out["mean"] = m.mean, out["std"] = m.std;
  out["skewness"] = m.skewness, out["kurtosis"] = m.kurtosis, out["domain_size_R"] = size;
  out["histogram_edges"] = to_numpy(hist.edges), out["histogram_counts"] = to_numpy(hist.counts);
  out["structure_factor"] = sk ? py::object(profile_dict(*sk)) : py::object(py::none());
  out["correlation"] = corr ? py::object(profile_dict(*corr)) : py::object(py::none());
  return out;
}

// A field file as (values, void mask or None, spacing, origin); values shaped (ny, nx) or
// (nz, ny, nx), void cells NaN in the values as well.
py::tuple read_field(const std::string& path, const std::string& array) {
  const sa::GridField f = sa::read_grid_field(path, array);
  std::vector<py::ssize_t> shape{py::ssize_t(f.n[1]), py::ssize_t(f.n[0])};
  if (f.n[2] > 1) shape.insert(shape.begin(), py::ssize_t(f.n[2]));
  py::array_t<double> values(shape);
  std::memcpy(values.mutable_data(), f.values.data(), f.size() * sizeof(double));
  py::object mask = py::none();
  if (!f.is_void.empty()) {
    py::array_t<bool> m(shape);
    for (std::size_t i = 0; i < f.size(); ++i) {
      m.mutable_data()[i] = f.is_void[i] != 0;
      if (f.is_void[i]) values.mutable_data()[i] = std::numeric_limits<double>::quiet_NaN();
    }
    mask = m;
  }
  return py::make_tuple(values, mask, py::make_tuple(f.spacing[0], f.spacing[1], f.spacing[2]),
                        py::make_tuple(f.origin[0], f.origin[1], f.origin[2]));
}

// analysis::gaussian_random_field's field (the benchmarks' and tests' reference) and its λ.
py::tuple gaussian_field(std::size_t nx, std::size_t ny, std::size_t nz, double correlation_length,
                         std::uint64_t seed) {
  if (nx == 0 || ny == 0 || nz == 0) throw py::value_error("gaussian_random_field: every count must be >= 1");
  sa::GaussianRandomField g;
  {
    py::gil_scoped_release release;
    g = sa::gaussian_random_field(nx, ny, nz, correlation_length, seed);
  }
  std::vector<py::ssize_t> shape{py::ssize_t(ny), py::ssize_t(nx)};
  if (nz > 1) shape.insert(shape.begin(), py::ssize_t(nz));
  py::array_t<double> values(shape);
  std::memcpy(values.mutable_data(), g.field.values.data(), g.field.size() * sizeof(double));
  return py::make_tuple(values, g.lambda);
}

py::list read_series(const std::string& path) {
  py::list out;
  for (const auto& e : sa::read_series(path)) out.append(py::make_tuple(e.time, e.file));
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  using namespace pybind11::literals;
  m.def("minkowski", &minkowski, "field"_a, "thresholds"_a = py::none(), "count"_a = 0, "boundary"_a = "periodic",
        "connectivity"_a = 8, "adjacency"_a = 26, "dimension"_a = 0, "spacing"_a = std::vector<double>{1.0},
        "void"_a = py::none(), "threads"_a = 0);
  m.def("similarity", &similarity, "reference"_a, "reference_threshold"_a, "candidate"_a, "times"_a,
        "thresholds"_a = py::none(), "count"_a = 0, "t1"_a = py::none(), "t2"_a = py::none(),
        "boundary"_a = "periodic", "connectivity"_a = 8, "adjacency"_a = 26, "dimension"_a = 0,
        "spacing"_a = std::vector<double>{1.0}, "threads"_a = 0);
  m.def("statistics", &statistics, "field"_a, "bins"_a = 64, "dimension"_a = 0,
        "spacing"_a = std::vector<double>{1.0}, "void"_a = py::none(), "threads"_a = 0);
  m.def("read_field", &read_field, "path"_a, "array"_a = "");
  m.def("read_series", &read_series, "path"_a);
  m.def("gaussian_random_field", &gaussian_field, "nx"_a, "ny"_a, "nz"_a, "correlation_length"_a, "seed"_a);
}

}  // namespace shockfield::python
