// Bad input stops with a shockfield::InputError whose message says what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "shockfield/analysis/field_statistics.hpp"
#include "shockfield/analysis/minkowski.hpp"
#include "shockfield/analysis/similarity.hpp"
#include "shockfield/core/error.hpp"

namespace sa = shockfield::analysis;

namespace {

template <class F>
void expect_input_error(F f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected one mentioning '" << fragment << "'";
  } catch (const shockfield::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

const std::vector<double> kT{0.0, 1.0};

}  // namespace

TEST(BadInput, EmptyField) {
  sa::GridField f;
  expect_input_error([&] { sa::minkowski_2d(f, kT); }, "empty field");
  expect_input_error([&] { sa::moments(f); }, "empty field");
}

TEST(BadInput, NaNValueNamesTheCell) {
  auto f = sa::GridField::filled(4, 3, 1, 1.0);
  f.values[f.index(2, 1)] = std::nan("");
  expect_input_error([&] { sa::minkowski_2d(f, kT); }, "cell (x=2, y=1, z=0)");
  f.is_void.assign(f.size(), 0);
  f.is_void[f.index(2, 1)] = 1;  // a void cell may hold anything
  EXPECT_NO_THROW(sa::minkowski_2d(f, kT));
}

TEST(BadInput, ThresholdsOutOfOrder) {
  const auto f = sa::GridField::filled(4, 4, 1, 1.0);
  const std::vector<double> bad{0.0, 2.0, 1.0}, repeated{1.0, 1.0}, none{};
  expect_input_error([&] { sa::minkowski_2d(f, bad); }, "thresholds out of order: 1 at position 3");
  expect_input_error([&] { sa::minkowski_2d(f, repeated); }, "out of order");
  expect_input_error([&] { sa::minkowski_2d(f, none); }, "none given");
}

TEST(BadInput, MismatchedGrids) {
  const auto a = sa::GridField::filled(4, 4, 1, 1.0), b = sa::GridField::filled(5, 4, 1, 1.0);
  expect_input_error([&] { sa::require_same_grid(a, b, "reference", "candidate"); },
                     "mismatched grids: reference has 4 x 4 x 1 cells, candidate has 5 x 4 x 1");
  expect_input_error([&] { sa::distance({1, 2, 3}, {1, 2, 3, 4}); }, "cannot be compared");
  auto sized = a;
  sized.values.pop_back();
  expect_input_error([&] { sa::minkowski_2d(sized, kT); }, "15 values for a grid of 4 x 4 x 1");
  auto stretched = a;
  stretched.spacing = {1.0, 2.0, 1.0};
  expect_input_error([&] { sa::minkowski_2d(stretched, kT); }, "square/cubic lattice");
  expect_input_error([&] { sa::minkowski_3d(a, kT); }, "expected a 3D field");
}

TEST(BadInput, ProcessTimes) {
  const sa::Process p{{0.0, 1.0}, {{0, 0, 0}, {1, 1, 1}}};
  const sa::Process backwards{{1.0, 0.0}, {{0, 0, 0}, {1, 1, 1}}};
  expect_input_error([&] { sa::process_distance(p, backwards, 0.0, 1.0); }, "times out of order");
  expect_input_error([&] { sa::process_distance(p, p, 0.0, 2.0); }, "outside the process's range");
  expect_input_error([&] { sa::process_distance(p, p, 1.0, 1.0); }, "expected t1 < t2");
}
