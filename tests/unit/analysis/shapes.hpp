#pragma once
// Digitised test shapes for the analysis tests: a cell is white (1) when its centre (integer
// coordinates) lies inside the shape, else black (0).
#include <cmath>
#include <functional>

#include "shockfield/analysis/grid_field.hpp"

namespace shockfield::analysis::testing {

inline GridField digitise(std::size_t nx, std::size_t ny, std::size_t nz,
                          const std::function<bool(double, double, double)>& inside) {
  GridField f = GridField::filled(nx, ny, nz, 0.0);
  for (std::size_t z = 0; z < nz; ++z)
    for (std::size_t y = 0; y < ny; ++y)
      for (std::size_t x = 0; x < nx; ++x)
        f.values[f.index(x, y, z)] = inside(double(x), double(y), double(z)) ? 1.0 : 0.0;
  return f;
}

/// A disk of radius r in an n × n grid, centre slightly off the lattice.
inline GridField disk(std::size_t n, double r, double cx, double cy) {
  return digitise(n, n, 1, [=](double x, double y, double) {
    return std::hypot(x - cx, y - cy) <= r;
  });
}

/// A ball of radius r in an n³ grid, centre (c, c + 0.13, c + 0.29).
inline GridField ball(std::size_t n, double r, double c) {
  return digitise(n, n, n, [=](double x, double y, double z) {
    return std::sqrt((x - c) * (x - c) + (y - c - 0.13) * (y - c - 0.13) +
                     (z - c - 0.29) * (z - c - 0.29)) <= r;
  });
}

}  // namespace shockfield::analysis::testing
