// Lattice rules that the LAMMPS cross-check does not reach: repeats, counts, basis types, the
// orientation checks of the LAMMPS lattice command, boxes that are not whole repeats.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/md/lattice.hpp"

namespace shockfield::md {
namespace {

using geometry::Boundary;
constexpr std::array<Boundary, 3> ppp{Boundary::periodic, Boundary::periodic, Boundary::periodic};

LatticeSpec spec(LatticeStyle style, const std::array<std::array<int, 3>, 3>& orient = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}) {
  LatticeSpec s;
  s.style = style;
  s.a0 = 2.0;
  s.orient = orient;
  return s;
}

TEST(Lattice, PeriodicRepeats) {
  const std::array<std::array<int, 3>, 3> o111{{{1, -1, 0}, {1, 1, -2}, {1, 1, 1}}};
  EXPECT_TRUE(Lattice(spec(LatticeStyle::fcc)).repeat().isApprox(Vec3(2, 2, 2)));
  EXPECT_TRUE(Lattice(spec(LatticeStyle::fcc, o111)).repeat().isApprox(2.0 * Vec3(std::sqrt(0.5), std::sqrt(1.5), std::sqrt(3.0))));
  EXPECT_TRUE(Lattice(spec(LatticeStyle::bcc, o111)).repeat().isApprox(2.0 * Vec3(std::sqrt(2.0), std::sqrt(6.0), std::sqrt(3.0) / 2)));
  EXPECT_TRUE(Lattice(spec(LatticeStyle::diamond, o111)).repeat().isApprox(2.0 * Vec3(std::sqrt(0.5), std::sqrt(1.5), std::sqrt(3.0))));
  EXPECT_TRUE(Lattice(spec(LatticeStyle::sc, o111)).repeat().isApprox(2.0 * Vec3(std::sqrt(2.0), std::sqrt(6.0), std::sqrt(3.0))));
  EXPECT_TRUE(Lattice(spec(LatticeStyle::hcp)).repeat().isApprox(2.0 * Vec3(1, std::sqrt(3.0), std::sqrt(8.0 / 3.0))));
  LatticeSpec hcp = spec(LatticeStyle::hcp);
  hcp.c_over_a = 1.6;
  EXPECT_NEAR(Lattice(hcp).repeat().z(), 3.2, 1e-12);
}

TEST(Lattice, AtomCountsFillWholeRepeatsWithoutOverlap) {
  // Atoms per box = basis atoms × box volume / cell volume.
  struct Case { LatticeStyle style; double per_cell; };
  for (const Case c : {Case{LatticeStyle::sc, 1}, Case{LatticeStyle::bcc, 2}, Case{LatticeStyle::fcc, 4},
                       Case{LatticeStyle::diamond, 8}}) {
    const Lattice lattice(spec(c.style, {{{1, -1, 0}, {1, 1, -2}, {1, 1, 1}}}));
    const auto box = lattice.box({3, 2, 2}, ppp);
    Atoms atoms;
    atoms.mass = {1.0};
    const auto n = lattice.create_atoms(box, atoms);
    EXPECT_EQ(static_cast<double>(n), std::round(c.per_cell * box.volume() / 8.0));
    EXPECT_EQ(atoms.id.back(), static_cast<std::int64_t>(n));
  }
}

TEST(Lattice, BasisTypesAndNonPeriodicFaces) {
  LatticeSpec s = spec(LatticeStyle::bcc);
  s.basis_types = {0, 1};
  const Lattice lattice(s);
  auto box = lattice.box({2, 2, 2}, {Boundary::periodic, Boundary::periodic, Boundary::fixed});
  Atoms atoms;
  lattice.create_atoms(box, atoms);
  EXPECT_EQ(atoms.nlocal, 16u);  // the sites on zhi are outside, as in LAMMPS (x < hi)
  EXPECT_EQ(std::count(atoms.type.begin(), atoms.type.end(), 1), 8);
  box.hi.z() += 0.5;  // a box that is not whole repeats takes every site with lo ≤ z < hi
  Atoms more;
  lattice.create_atoms(box, more);
  EXPECT_EQ(more.nlocal, 20u);
}

void expect_lattice_error(const LatticeSpec& s, const std::string& fragment) {
  try {
    Lattice lattice(s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Lattice, InvalidSpecs) {
  expect_lattice_error(spec(LatticeStyle::fcc, {{{1, 1, 0}, {1, 0, 0}, {0, 0, 1}}}), "not orthogonal");
  expect_lattice_error(spec(LatticeStyle::fcc, {{{1, -1, 0}, {1, 1, -2}, {-1, -1, -1}}}), "not right-handed");
  expect_lattice_error(spec(LatticeStyle::fcc, {{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}}), "zero vector");
  expect_lattice_error(spec(LatticeStyle::hcp, {{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}}), "does not repeat along x");
  LatticeSpec s = spec(LatticeStyle::fcc);
  s.c_over_a = 1.6;
  expect_lattice_error(s, "only used by the hcp");
  s = spec(LatticeStyle::fcc);
  s.basis_types = {0, 1};
  expect_lattice_error(s, "2 basis types given, the fcc lattice has 4");
  s.a0 = -1;
  expect_lattice_error(s, "a0 must be > 0");
  EXPECT_THROW(Lattice(spec(LatticeStyle::sc)).box({0, 1, 1}, ppp), InputError);
  EXPECT_THROW(parse_lattice_style("bct", "style"), InputError);
}

}  // namespace
}  // namespace shockfield::md
