// Euler characteristic against scikit-image's euler_number on random binary images, both
// connectivities, 2D and 3D (fixtures from tests/fixtures/analysis/make_euler_fixtures.py).
// Reference: scikit-image 0.19.3 (Debian python3-skimage); exact agreement is required.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "shockfield/analysis/minkowski.hpp"

namespace sa = shockfield::analysis;

namespace {

struct Case {
  sa::GridField field;
  long chi_low = 0, chi_high = 0;  // skimage connectivity 1, and 2 (2D) / 3 (3D)
};

std::vector<Case> load(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path << " (run the tests from tests/)";
  std::vector<Case> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("image", 0) != 0) continue;
    std::istringstream head(line.substr(5));
    int dim = 0;
    head >> dim;
    std::vector<std::size_t> shape(dim);
    for (auto& s : shape) head >> s;
    Case c;
    head >> c.chi_low >> c.chi_high;
    // shape is slowest first (numpy order); the grid is x fastest.
    c.field = sa::GridField::filled(shape[dim - 1], shape[dim - 2], dim == 3 ? shape[0] : 1, 0.0);
    const std::size_t rows = c.field.n[1] * c.field.n[2];
    for (std::size_t r = 0; r < rows; ++r) {
      std::getline(in, line);
      for (std::size_t x = 0; x < c.field.n[0]; ++x)
        c.field.values[x + c.field.n[0] * r] = line.at(x) == '1' ? 1.0 : 0.0;
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

long euler_at_half(const sa::GridField& f, bool high_connectivity) {
  sa::MinkowskiOptions o;
  o.boundary = sa::Boundary::open;
  const std::vector<double> t{0.5};
  if (f.dimension() == 2) {
    o.connectivity2d = high_connectivity ? sa::Connectivity2D::eight : sa::Connectivity2D::four;
    return static_cast<long>(sa::minkowski_2d(f, t, o)[0].euler);
  }
  o.adjacency3d = high_connectivity ? sa::Adjacency3D::twentysix_6 : sa::Adjacency3D::six_26;
  return static_cast<long>(sa::minkowski_3d(f, t, o)[0].euler);
}

void check_file(const std::string& path, std::size_t expected_cases) {
  const auto cases = load(path);
  ASSERT_EQ(cases.size(), expected_cases);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    EXPECT_EQ(euler_at_half(c.field, false), c.chi_low) << path << " image " << i;
    EXPECT_EQ(euler_at_half(c.field, true), c.chi_high) << path << " image " << i;
  }
}

}  // namespace

TEST(EulerSkimage, RandomImages2D) { check_file("fixtures/analysis/euler_2d.txt", 40); }
TEST(EulerSkimage, RandomImages3D) { check_file("fixtures/analysis/euler_3d.txt", 24); }
