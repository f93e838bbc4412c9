#pragma once
// StateArray (method.hpp) descriptions of a method's std::vector storage: Vec3 (3 doubles, the
// Eigen vector has no padding), std::array<int, 3>, double, int and std::int64_t entries.
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "shockfield/core/method.hpp"
#include "shockfield/core/types.hpp"

namespace shockfield {

/// The first `rows` entries of `values` as the state array `name` in `unit`.
template <class T>
StateArray state_array(std::string name, std::vector<T>& values, std::size_t rows, std::string unit = "") {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(std::array<int, 3>) == 3 * sizeof(int));
  StateArray a{std::move(name), values.data(), rows, 1, StateArray::Type::f64, std::move(unit), {}, {}};
  if constexpr (std::is_same_v<T, Vec3>) {
    a.columns = 3;
  } else if constexpr (std::is_same_v<T, std::array<int, 3>>) {
    a.columns = 3;
    a.type = StateArray::Type::i32;
  } else if constexpr (std::is_same_v<T, int>) {
    a.type = StateArray::Type::i32;
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    a.type = StateArray::Type::i64;
  } else {
    static_assert(std::is_same_v<T, double>, "a state array holds Vec3, int[3], double, int or int64 entries");
  }
  return a;
}

/// The field `values` of a grid of `n` = (nx, ny, nz) nodes, x fastest, as the state array `name`
/// shaped (nx), (ny, nx) or (nz, ny, nx) for `dim` = 1, 2, 3.
inline StateArray grid_state_array(std::string name, std::vector<double>& values, int dim, std::array<int, 3> n,
                                   std::string unit = "") {
  StateArray a = state_array(std::move(name), values, values.size(), std::move(unit));
  for (int d = dim - 1; d >= 0; --d) a.shape.push_back(static_cast<std::size_t>(n[static_cast<std::size_t>(d)]));
  return a;
}

/// The value `member(entry)` of every entry of `values` (an array of structs, e.g. MPM's per-particle
/// material state) as the strided state array `name`: a double member shaped (rows), a Mat3 member
/// (rows, 3, 3) indexed [i, row, column] (Eigen stores a matrix column after column).
template <class S, class Member>
StateArray member_state_array(std::string name, std::vector<S>& values, Member member, std::string unit = "") {
  using Value = std::remove_reference_t<std::invoke_result_t<Member, S&>>;
  static_assert(std::is_same_v<Value, double> || std::is_same_v<Value, Mat3>, "a double or Mat3 member");
  StateArray a{std::move(name), nullptr, values.size(), 1, StateArray::Type::f64, std::move(unit), {values.size()},
               {sizeof(S)}};
  if constexpr (std::is_same_v<Value, Mat3>) {
    static_assert(!Mat3::IsRowMajor && sizeof(Mat3) == 9 * sizeof(double));
    a.columns = 9;
    a.shape = {values.size(), 3, 3};
    a.strides = {sizeof(S), sizeof(double), 3 * sizeof(double)};
  }
  if (!values.empty()) a.data = &member(values.front());
  return a;
}

}  // namespace shockfield
