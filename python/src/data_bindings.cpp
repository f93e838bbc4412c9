// shockfield._core's LAMMPS data-file reader (python/shockfield/run.py's `read_lammps_data` wraps
// it): the library's io::read_data — the parser `[system] data_file` uses, with its checks and
// error messages (file, line, what was expected) — returning numpy copies of the atoms and the
// box, tilt included (LAMMPS's restricted triclinic cell).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "shockfield/io/lammps_data.hpp"

namespace py = pybind11;

namespace shockfield::python {
namespace {

// An (n, 3) numpy copy of per-atom triples.
template <class T, class Triple>
py::array_t<T> triples(const std::vector<Triple>& rows, std::size_t n) {
  py::array_t<T> out({static_cast<py::ssize_t>(n), py::ssize_t{3}});
  auto a = out.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (py::ssize_t d = 0; d < 3; ++d)
      a(static_cast<py::ssize_t>(i), d) = static_cast<T>(rows[i][d]);
  return out;
}

py::tuple vec3(const Vec3& v) {
  return py::make_tuple(v.x(), v.y(), v.z());
}

py::dict read_data(const std::string& path, const std::string& boundary) {
  if (boundary.size() != 3)
    throw py::value_error("boundary: expected 3 letters p, f or s, got '" + boundary + "'");
  std::array<geometry::Boundary, 3> codes{};
  for (std::size_t d = 0; d < 3; ++d)
    codes[d] = geometry::parse_boundary(std::string(1, boundary[d]), "boundary");
  io::DataFile data;
  {
    py::gil_scoped_release release;
    data = io::read_data(path, codes);
  }
  const md::Atoms& a = data.atoms;
  const std::size_t n = a.nlocal;
  py::array_t<std::int32_t> types(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) types.mutable_at(static_cast<py::ssize_t>(i)) = a.type[i] + 1;
  py::dict out;
  out["title"] = data.title;
  out["lo"] = vec3(data.box.lo);
  out["hi"] = vec3(data.box.hi);
  out["tilt"] = vec3(data.box.tilt);
  out["boundary"] = data.box.boundary_codes();
  out["ids"] = to_numpy(
      std::vector<std::int64_t>(a.id.begin(), a.id.begin() + static_cast<std::ptrdiff_t>(n)));
  out["types"] = types;
  out["positions"] = triples<double>(a.x, n);
  out["images"] = triples<std::int32_t>(a.image, n);
  out["velocities"] =
      data.has_velocities ? py::object(triples<double>(a.v, n)) : py::object(py::none());
  out["masses"] = to_numpy(a.mass);
  out["elements"] = a.type_names;
  return out;
}

}  // namespace

void bind_data(py::module_& m) {
  m.def("read_lammps_data", &read_data, py::arg("path"), py::arg("boundary"));
}

}  // namespace shockfield::python
