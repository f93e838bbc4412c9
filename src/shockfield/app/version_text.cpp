// `shockfield --version`: what this build is and what it was built with, like `lmp -h`'s header
// (docs/install.md). The git commit and build type come from core/provenance.
#include <fftw3.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <omp.h>

#include "shockfield/app/commands.hpp"
#include "shockfield/app/python_helpers.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/provenance.hpp"
#include "shockfield/parallel/communicator.hpp"

namespace shockfield::app {
namespace {

// The OpenMP specification a compiler implements, from its _OPENMP date (yyyymm).
std::string openmp_version() {
  const int date = _OPENMP;
  const char* spec = date >= 202111 ? "5.2" : date >= 202011 ? "5.1" : date >= 201811 ? "5.0"
                     : date >= 201511 ? "4.5" : date >= 201307 ? "4.0" : "3.x";
  return fmt::format("{} ({}), {} threads available", spec, date, omp_get_max_threads());
}

std::string hdf5_version() {
  unsigned major = 0, minor = 0, release = 0;
  H5get_libversion(&major, &minor, &release);
  return fmt::format("{}.{}.{}", major, minor, release);
}

}  // namespace

std::string version_text() {
  const Provenance p = collect_provenance({}, {});
  std::string text = fmt::format("shockfield {}\n  git commit: {}\n  build: {}, {}\n", p.version,
                                 p.git_commit, p.build_type, p.compiler);
  text += fmt::format("  OpenMP: {}\n  FFTW: {}\n  HDF5: {}\n", openmp_version(), fftw_version,
                      hdf5_version());
  text += fmt::format("  MPI: {}\n", parallel::mpi_build_text());
#ifdef SHOCKFIELD_PYTHON_MODULE_FOR
  text += "  Python module: built for " SHOCKFIELD_PYTHON_MODULE_FOR "\n";
#else
  text += "  Python module: not built (no pybind11 at configure time)\n";
#endif
  try {
    text += fmt::format("  Python helpers: {}\n", python_package_dir().string());
  } catch (const InputError& e) {
    text += fmt::format("  Python helpers: missing ({})\n", e.what());
  }
  text.pop_back();  // CLI11 ends the text with its own newline
  return text;
}

}  // namespace shockfield::app
