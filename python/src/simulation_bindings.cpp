// shockfield._core.Simulation: a case run in-process (python/shockfield/simulation.py wraps it).
// The method comes from the same registry and runs through the same RunDriver as `shockfield
// run` (run folder, log, thermo, outputs, checkpoints, summary.json), stepped from Python; between
// steps its state arrays (Method::state_arrays: per particle, or a grid's field) are numpy
// arrays over the method's own storage: views, not copies, kept alive by the Simulation they
// belong to.
//
// Views stay valid: the method reserves its arrays' largest size when they are first asked for
// (md: the most ghost entries the box can give), so a neighbour rebuild does not move them. The
// Simulation checks that after every step() call; if an array moved or changed length anyway
// (a box compressed past another ghost layer), step() raises StaleViewError and the arrays must
// be taken again.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "shockfield/core/config.hpp"
#include "shockfield/core/derived_arrays.hpp"
#include "shockfield/core/run_driver.hpp"
#include "shockfield/registry/method_registry.hpp"

namespace py = pybind11;

namespace shockfield::python {
namespace {

py::dtype dtype_of(StateArray::Type type) {
  switch (type) {
    case StateArray::Type::f64: return py::dtype::of<double>();
    case StateArray::Type::i32: return py::dtype::of<std::int32_t>();
    case StateArray::Type::i64: return py::dtype::of<std::int64_t>();
  }
  return py::dtype::of<double>();
}

std::size_t item_size(StateArray::Type type) { return type == StateArray::Type::i32 ? 4 : 8; }

class InProcessRun {
 public:
  InProcessRun(const std::string& case_file, const std::vector<std::string>& overrides, const std::string& output,
               int threads, bool overwrite, bool quiet, bool resume)
      : threads_(threads) {
    RunOptions options;
    options.case_file = case_file;
    if (!output.empty()) options.output = output;
    options.overwrite = overwrite;
    options.resume = resume;
    options.threads = threads;
    options.quiet = quiet;
    options.overrides = overrides;
    options.command_line = {"python: shockfield.Simulation", case_file};
    for (const std::string& o : overrides) options.command_line.insert(options.command_line.end(), {"--set", o});
    if (resume) options.command_line.push_back("--resume");
    const ThreadCount thread_count(threads);
    py::gil_scoped_release release;
    const Config root = Config::load(options.case_file, options.overrides);
    driver_ = std::make_unique<RunDriver>(root, options, method_factory(root));
    // The embedding interpreter keeps its own Ctrl-C (KeyboardInterrupt between steps).
    open_ = driver_->open(/*stop_handlers=*/false);
  }

  std::string method_name() const { return driver_->method().name(); }
  std::int64_t step_number() const { return driver_->method().step(); }
  double time() const { return driver_->method().time(); }
  std::string time_unit() const { return driver_->method().time_unit(); }
  std::int64_t steps_left() const { return open_ ? driver_->method().steps_left() : 0; }
  bool finished() const { return !open_ || driver_->finished(); }
  bool closed() const { return finished_; }
  std::string folder() const { return driver_->context().folder.string(); }

  py::dict thermo() const {
    const Method& m = driver_->method();
    const std::vector<std::string> names = m.thermo_columns();
    const std::vector<double> values = m.thermo_values();
    py::dict row;
    for (std::size_t k = 0; k < names.size() && k < values.size(); ++k) row[py::str(names[k])] = values[k];
    return row;
  }

  /// Advances up to `n` steps (fewer when the run ends first); returns the steps made.
  std::int64_t step(std::int64_t n) {
    if (n < 0) throw py::value_error(fmt::format("step({}): expected a number of steps >= 0", n));
    require_running(fmt::format("step({})", n));
    if (driver_->finished())
      throw py::value_error(fmt::format("step({}): the run has no step left (at step {}); call finish() to write "
                                        "its final outputs and summary.json",
                                        n, step_number()));
    const ThreadCount thread_count(threads_);
    std::int64_t made = 0;
    {
      py::gil_scoped_release release;
      while (made < n && !driver_->finished()) {
        driver_->step();
        ++made;
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      }
    }
    check_views();
    return made;
  }

  void finish() {
    require_running("finish()");
    if (!driver_->finished())
      throw py::value_error(fmt::format("finish(): {} step(s) left; step(n) them first", driver_->method().steps_left()));
    const ThreadCount thread_count(threads_);
    {
      py::gil_scoped_release release;
      driver_->finish();
    }
    finished_ = true;
    check_views();
  }

  /// Stops the run as Ctrl-C does (a checkpoint; summary.json "stopped"): a Simulation with
  /// resume=True continues it. Returns the message saying how.
  std::string stop() {
    require_running("stop()");
    const ThreadCount thread_count(threads_);
    std::string message;
    {
      py::gil_scoped_release release;
      message = driver_->stop();
    }
    finished_ = true;
    return message;
  }

  /// The method's state arrays (per particle, or a grid's field) as numpy views whose base is `self`.
  static py::dict arrays(py::object self) {
    InProcessRun& run = self.cast<InProcessRun&>();
    if (!run.open_) throw py::value_error("arrays(): the resumed run had nothing left to do");
    py::dict views;
    run.given_ = run.driver_->method().state_arrays();
    for (const StateArray& a : run.given_) {
      const std::size_t size = item_size(a.type);
      std::vector<py::ssize_t> shape;
      for (std::size_t extent : a.shape) shape.push_back(static_cast<py::ssize_t>(extent));
      if (shape.empty()) shape.push_back(static_cast<py::ssize_t>(a.rows));
      if (a.shape.empty() && a.columns > 1) shape.push_back(static_cast<py::ssize_t>(a.columns));
      std::vector<py::ssize_t> strides(shape.size(), static_cast<py::ssize_t>(size));  // row-major
      for (std::size_t d = shape.size() - 1; d > 0; --d) strides[d - 1] = strides[d] * shape[d];
      if (!a.strides.empty()) strides.assign(a.strides.begin(), a.strides.end());  // a member of structs
      views[py::str(a.name)] = py::array(dtype_of(a.type), shape, strides, a.data, self);
    }
    return views;
  }

  /// The fields the method computes from its state (DerivedArrays), as numpy copies.
  py::dict fields() const {
    const auto* derived = dynamic_cast<const DerivedArrays*>(&driver_->method());
    if (!derived)
      throw py::value_error(fmt::format("fields(): the {} method computes no fields from its state; its state "
                                        "arrays are arrays()", method_name()));
    std::vector<DerivedArray> arrays;
    {
      py::gil_scoped_release release;
      arrays = derived->derived_arrays();
    }
    if (arrays.empty()) throw py::value_error("fields(): a decomposed (MPI) run offers no fields: its state lives in the ranks' blocks");
    py::dict out;
    for (const DerivedArray& a : arrays) {
      const std::vector<py::ssize_t> shape(a.shape.begin(), a.shape.end());
      py::array_t<double> copy(shape);
      std::copy(a.values.begin(), a.values.end(), copy.mutable_data());
      out[py::str(a.name)] = copy;
    }
    return out;
  }

  static py::dict units(const InProcessRun& run) {
    py::dict u;
    for (const StateArray& a : run.driver_->method().state_arrays()) u[py::str(a.name)] = a.unit;
    return u;
  }

 private:
  void require_running(const std::string& what) const {
    if (finished_) throw py::value_error(what + ": the run was closed by finish() or stop()");
    if (!open_) throw py::value_error(what + ": the resumed run had nothing left to do");
  }

  // The arrays handed out must still be where they were, with as many rows (see the top).
  void check_views() {
    if (given_.empty()) return;
    const std::vector<StateArray> now = driver_->method().state_arrays();
    std::string moved;
    for (const StateArray& before : given_)
      for (const StateArray& a : now)
        if (a.name == before.name && (a.data != before.data || a.rows != before.rows))
          moved += fmt::format("{}{} ({} rows, now {})", moved.empty() ? "" : ", ", a.name, before.rows, a.rows);
    if (moved.empty()) return;
    given_.clear();
    static PyObject* stale = py::module_::import("shockfield.errors").attr("StaleViewError").ptr();
    PyErr_SetString(stale, fmt::format("at step {}: the storage of {} moved or changed size; arrays taken before "
                                       "no longer show the simulation: take them again with arrays()",
                                       step_number(), moved)
                               .c_str());
    throw py::error_already_set();
  }

  int threads_ = 0;
  std::unique_ptr<RunDriver> driver_;
  bool open_ = false, finished_ = false;
  std::vector<StateArray> given_;  ///< the arrays as last handed out
};

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<InProcessRun>(m, "Simulation", "A case run in-process; use shockfield.Simulation")
      .def(py::init<const std::string&, const std::vector<std::string>&, const std::string&, int, bool, bool, bool>(),
           py::arg("case_file"), py::arg("overrides"), py::arg("output"), py::arg("threads"), py::arg("overwrite"),
           py::arg("quiet"), py::arg("resume"))
      .def_property_readonly("method", &InProcessRun::method_name, "The method's name: md, mpm, pd, ...")
      .def_property_readonly("step_number", &InProcessRun::step_number, "The step counter")
      .def_property_readonly("time", &InProcessRun::time, "Simulated time, in time_unit")
      .def_property_readonly("time_unit", &InProcessRun::time_unit, "ps, s or 1 (lattice units)")
      .def_property_readonly("steps_left", &InProcessRun::steps_left, "Steps left (an estimate for adaptive steps)")
      .def_property_readonly("finished", &InProcessRun::finished, "True when no step is left")
      .def_property_readonly("closed", &InProcessRun::closed, "True after finish() or stop()")
      .def_property_readonly("folder", &InProcessRun::folder, "The run folder")
      .def("thermo", &InProcessRun::thermo, "The thermo columns at this step, by name")
      .def("step", &InProcessRun::step, "Makes up to n steps; returns the steps made", py::arg("n") = 1)
      .def("finish", &InProcessRun::finish, "Writes the end of the run (final outputs, summary.json)")
      .def("stop", &InProcessRun::stop, "Stops the run as Ctrl-C does; returns the command line's message")
      .def("arrays", &InProcessRun::arrays, "Numpy views of the state arrays, by name")
      .def("fields", &InProcessRun::fields, "Copies of the fields computed from the state, by name")
      .def("units", &InProcessRun::units, "The unit of each array, by name");
}

}  // namespace shockfield::python
