#pragma once
// The parts of shockfield._core, one function per file (docs/python.md).
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace shockfield::python {

void bind_analysis(pybind11::module_& m);    // analysis_bindings.cpp
void bind_simulation(pybind11::module_& m);  // simulation_bindings.cpp
void bind_atoms(pybind11::module_& m);       // atoms_bindings.cpp
void bind_geometry(pybind11::module_& m);    // geometry_bindings.cpp
void bind_data(pybind11::module_& m);        // data_bindings.cpp

// `threads` OpenMP threads for one call (0: the process's default), restored afterwards so that
// a call's choice does not become the next call's default.
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : saved_(omp_get_max_threads()) {
    if (threads < 0) throw pybind11::value_error("threads: expected 0 (the default) or more");
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~ThreadCount() { omp_set_num_threads(saved_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int saved_;
};

/// A numpy copy of a result vector.
template <class T>
pybind11::array_t<T> to_numpy(const std::vector<T>& v) {
  return pybind11::array_t<T>(pybind11::ssize_t(v.size()), v.data());
}

}  // namespace shockfield::python
