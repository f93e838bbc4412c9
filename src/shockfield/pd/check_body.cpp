#include "shockfield/pd/check_body.hpp"

#include <algorithm>
#include <cmath>

#include "shockfield/pd/lattice_bonds.hpp"

namespace shockfield::pd {

// The body --check builds the model on: at most 4⌈m⌉ + 1 points along each axis (m the horizon
// factor), so that it holds every kind of point of the whole body: a point's stable step depends
// on its family and its neighbours' families (shape tensors, weighted volumes), i.e. on what lies
// within two horizons (2⌈m⌉ points) of it, and along an axis of 4⌈m⌉ + 1 points there is a point
// at each distance 0..2⌈m⌉ from either surface with at least 2⌈m⌉ on its other side. So the sub-body
// has the whole body's smallest stable step (for a polycrystal, of the grains the sub-body holds).
// Its bonds grow as m^6 in 3D, so beyond kCheckBonds (~0.2 GB and ~2 s; m > 4 in 3D) it
// is made smaller until it has at most kCheckBonds (a body of (m+1)^3 points is all bonds, so for a
// huge m the sub-body holds no whole family): the stable step is then an estimate (the run
// computes its own on the whole body before its folder exists).
namespace {
constexpr double kCheckBonds = 5e6;
}  // namespace

// A body from a points_file is checked whole (its file has been read anyway).
BodySpec checked_body(const BodySpec& body) {
  if (body.cloud) return body;
  const int m = static_cast<int>(std::ceil(body.horizon_factor));
  BodySpec sub = body;
  for (int most = 4 * m + 1; most >= 2; --most) {
    for (int d = 0; d < body.dim; ++d) {
      const auto a = static_cast<std::size_t>(d);
      sub.counts[a] = std::min(body.counts[a], most);
    }
    if (lattice_bonds(sub.dim, sub.counts, sub.horizon_factor) <= kCheckBonds) break;
  }
  return sub;
}

// Whether a sub-body of checked_body has every kind of point of the body (else its stable step is
// an estimate).
bool holds_every_kind(const BodySpec& sub, const BodySpec& body) {
  const int m = static_cast<int>(std::ceil(body.horizon_factor));
  for (int d = 0; d < body.dim; ++d) {
    const auto a = static_cast<std::size_t>(d);
    if (sub.counts[a] < std::min(body.counts[a], 4 * m + 1)) return false;
  }
  return true;
}

}  // namespace shockfield::pd
