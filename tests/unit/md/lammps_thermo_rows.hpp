#pragma once
// Thermo rows printed by LAMMPS (`thermo_modify format float %.17g`) and their comparison with
// ours, for the fix cross-checks (tests/unit/md_msst, tests/unit/md_nphug): the reference is one
// LAMMPS run on 1 MPI rank and the same run on 2 ranks, whose difference is LAMMPS's own
// round-off growth.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace shockfield::md::lammps_rows {

template <std::size_t N>
using Row = std::array<double, N>;

/// The rows of fixtures/<path> (whitespace-separated numbers, N per line).
template <std::size_t N>
std::vector<Row<N>> read(const std::string& path) {
  std::ifstream in("fixtures/" + path);
  if (!in) throw std::runtime_error("missing fixtures/" + path + " (run the tests from tests/)");
  std::vector<Row<N>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    Row<N> r{};
    for (double& v : r) words >> v;
    if (words) rows.push_back(r);
  }
  return rows;
}

/// Largest |a − b| per column over all rows.
template <std::size_t N>
Row<N> max_difference(const std::vector<Row<N>>& a, const std::vector<Row<N>>& b) {
  Row<N> d{};
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    for (std::size_t c = 0; c < N; ++c) d[c] = std::max(d[c], std::fabs(a[i][c] - b[i][c]));
  return d;
}

/// Our rows against LAMMPS's (`ref`, 1 rank; `np2`, 2 ranks): every column but the first (the
/// step) within `factor` times LAMMPS's own 1-vs-2-rank spread of it over the run, or within
/// `floor_rel` of its largest magnitude (round-off of a single step: the spread of a quantity
/// that the two LAMMPS runs happen to print identically would be 0).
template <std::size_t N>
void expect_follows(const std::vector<Row<N>>& ours, const std::vector<Row<N>>& ref, const std::vector<Row<N>>& np2,
                    const std::array<const char*, N>& names, double factor, double floor_rel) {
  ASSERT_EQ(ours.size(), ref.size());
  const Row<N> spread = max_difference(ref, np2), diff = max_difference(ours, ref);
  for (std::size_t c = 1; c < N; ++c) {
    double scale = 0;
    for (const auto& r : ref) scale = std::max(scale, std::fabs(r[c]));
    const double tol = std::max(factor * spread[c], floor_rel * scale);
    std::printf("%-20s max |ours - LAMMPS| = %.3e  LAMMPS 1 vs 2 ranks %.3e  (tolerance %.2e)\n", names[c], diff[c],
                spread[c], tol);
    EXPECT_LE(diff[c], tol) << names[c];
  }
}

}  // namespace shockfield::md::lammps_rows
