// shockfield._core's atom structure analysis on numpy arrays (python/shockfield/analysis.py's
// `structure` wraps it): coordination, conventional and adaptive CNA, centro-symmetry and bond
// pairs over one neighbour pass, the function `shockfield analyze atoms` calls per frame
// (analysis/atoms/structure_analysis.hpp). Positions are a C-contiguous (n, 3) float64 array and
// the box its lo/hi corners with a LAMMPS boundary code; they are copied once into the library's
// AtomFrame (a memcpy, with the GIL released, as is the analysis).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "shockfield/analysis/atoms/structure_analysis.hpp"
#include "shockfield/core/error.hpp"

namespace py = pybind11;
namespace aa = shockfield::analysis::atoms;

namespace shockfield::python {
namespace {

py::array_t<std::uint8_t> codes(const std::vector<aa::Structure>& s) {
  py::array_t<std::uint8_t> out(static_cast<py::ssize_t>(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i) out.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<std::uint8_t>(s[i]);
  return out;
}

py::dict counts(const aa::StructureCounts& c) {
  py::dict d;
  for (aa::Structure s : aa::kStructures) d[py::str(std::string(aa::structure_name(s)))] = c.of(s);
  return d;
}

// The frame of `positions` (n, 3) in the box lo/hi with `boundary` ("ppp"), `types` (1-based)
// and `ids` (None: all type 1, ids 1..n); TypeError / ValueError for arrays of the wrong kind.
aa::AtomFrame make_frame(const py::array& positions, const std::vector<double>& lo, const std::vector<double>& hi,
                         const std::string& boundary, const py::object& types, const py::object& ids) {
  if (positions.dtype().num() != py::dtype::of<double>().num())
    throw py::type_error("positions: expected dtype float64, got " + std::string(py::str(positions.dtype())));
  if (positions.ndim() != 2 || positions.shape(1) != 3)
    throw py::value_error("positions: expected an (n, 3) array, got shape " +
                          std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                              positions.shape(), positions.shape() + positions.ndim()))))));
  if (!(positions.flags() & py::array::c_style))
    throw py::value_error("positions: the array is not C-contiguous; pass numpy.ascontiguousarray(positions)");
  if (lo.size() != 3 || hi.size() != 3) throw py::value_error("box: expected lo and hi of 3 values each");
  if (boundary.size() != 3) throw py::value_error("boundary: expected 3 letters p, f or s, got '" + boundary + "'");
  aa::AtomFrame frame;
  for (int d = 0; d < 3; ++d) {
    frame.box.lo[d] = lo[static_cast<std::size_t>(d)];
    frame.box.hi[d] = hi[static_cast<std::size_t>(d)];
    frame.box.boundary[static_cast<std::size_t>(d)] =
        geometry::parse_boundary(std::string(1, boundary[static_cast<std::size_t>(d)]), "boundary");
  }
  const auto n = static_cast<std::size_t>(positions.shape(0));
  if (!types.is_none()) frame.types = types.cast<std::vector<int>>();
  if (!ids.is_none()) frame.ids = ids.cast<std::vector<std::int64_t>>();
  frame.positions.resize(n);
  py::gil_scoped_release release;
  if (n > 0) std::memcpy(static_cast<void*>(frame.positions.data()), positions.data(), n * sizeof(Vec3));  // 3 doubles each
  return frame;
}

py::dict structure(const py::array& positions, const std::vector<double>& lo, const std::vector<double>& hi,
                   const std::string& boundary, const py::object& types, const py::object& ids,
                   std::optional<double> coordination, std::optional<double> cna, bool adaptive_cna,
                   const py::object& csp, std::optional<double> bond_pairs, int threads) {
  const ThreadCount thread_count(threads);
  const aa::AtomFrame frame = make_frame(positions, lo, hi, boundary, types, ids);
  aa::StructureAnalyses analyses;
  if (coordination) analyses.coordination = aa::Coordination{*coordination};
  if (cna) analyses.cna = aa::ConventionalCna{*cna};
  if (adaptive_cna) analyses.adaptive_cna = aa::AdaptiveCna{};
  if (!csp.is_none())
    analyses.centro_symmetry = aa::CentroSymmetry{aa::CentroSymmetry::parse_neighbors(py::str(csp), "csp")};
  if (bond_pairs) analyses.bond_pairs = aa::BondPairAnalysis{*bond_pairs};
  aa::StructureAnalysisResult r;
  {
    py::gil_scoped_release release;
    validate_frame(frame, "positions");
    r = analyze_structure(frame, analyses);
  }
  py::dict out;
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

}  // namespace

void bind_atoms(py::module_& m) {
  m.def("atoms_structure", &structure, py::arg("positions"), py::arg("lo"), py::arg("hi"), py::arg("boundary"),
        py::arg("types"), py::arg("ids"), py::arg("coordination"), py::arg("cna"), py::arg("adaptive_cna"),
        py::arg("csp"), py::arg("bond_pairs"), py::arg("threads"));
}

}  // namespace shockfield::python
