#pragma once
// Fields a method computes from its state rather than stores (DBM's ρ, u and T are moments of
// the distributions f): a capability a method adds beside Method (core/method.hpp), asked for
// by a caller between steps — the Python module's Simulation.fields(). Unlike state_arrays(),
// these are copies made at the call: writing into them changes nothing.
#include <cstddef>
#include <string>
#include <vector>

namespace shockfield {

struct DerivedArray {
  std::string name;                ///< "rho", "velocity", "T", ...
  std::vector<double> values;      ///< row-major over `shape`
  std::vector<std::size_t> shape;  ///< e.g. (ny, nx) or (ny, nx, 2)
  std::string unit;                ///< "1" for lattice units
};

class DerivedArrays {
 public:
  virtual ~DerivedArrays() = default;
  /// The fields at the current step (empty: none offered, e.g. a decomposed run).
  virtual std::vector<DerivedArray> derived_arrays() const = 0;
};

}  // namespace shockfield
