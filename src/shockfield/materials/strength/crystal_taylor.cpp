#include "shockfield/materials/strength/crystal_taylor.hpp"

namespace shockfield::materials {

TaylorAggregate::State TaylorAggregate::initial_state() const {
  State s;
  for (const Mat3& g : orientations) s.push_back(crystal.initial_state(g));
  return s;
}

Mat3 TaylorAggregate::update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const {
  if (s.size() == 1) return crystal.update(s.front(), f_old, f_new, dt);
  Mat3 sum = Mat3::Zero();
  for (auto& grain : s) sum += crystal.update(grain, f_old, f_new, dt);
  return sum / static_cast<double>(s.size());  // eq. 43
}

double TaylorAggregate::accumulated_slip(const State& s) {
  double sum = 0.0;
  for (const auto& grain : s) sum += grain.accumulated_slip;
  return sum / static_cast<double>(s.size());
}

}  // namespace shockfield::materials
