#pragma once
// Structural and dynamic similarity of patterns (Xu et al. 2015, §3.1, Figs. 3–4; applied in §4.1.2,
// Figs. 42–45). A pattern is a point in the (D + 1)-dimensional space of its Minkowski
// functionals; two patterns are the closer the more alike they are.
//   d   = √(Σ_i (F_i,2 − F_i,1)²)                (§3.1, 2D: F = (A, L, χ))
//   S   = 1 / d                                 structural similarity
//   d_P = ∫_{t1}^{t2} d(t) dt / (t2 − t1)         process distance (§3.1's S_D formula, §4.1.2's d_P)
//   S_D = 1 / d_P                               dynamic similarity
// The paper prints the time average of d under the name S_D; since S = 1/d, we call the average
// the process distance d_P (the name §4.1.2 minimises) and S_D its inverse.
#include <span>
#include <vector>

#include "shockfield/analysis/minkowski.hpp"

namespace shockfield::analysis {

/// Dimensionless Minkowski coordinates of one pattern.
using MorphologyPoint = std::vector<double>;

/// 2D: (A, L / (N h), χ / N_black) — fractional area, boundary length per cell in grid units,
/// eq. (33)'s Euler characteristic (0 when there is no black node).
MorphologyPoint morphology_point(const Functionals2D& f, const GridFieldView& grid);
/// 3D: (V, S / (N h²), b̄ / (N h), χ / N_black).
MorphologyPoint morphology_point(const Functionals3D& f, const GridFieldView& grid);

/// Euclidean distance d; InputError if the points have different lengths.
double distance(const MorphologyPoint& a, const MorphologyPoint& b);
/// S = 1 / d (infinity for identical points).
double structural_similarity(const MorphologyPoint& a, const MorphologyPoint& b);

/// A pattern evolving in time: points[i] at times[i] (strictly increasing).
struct Process {
  std::vector<double> times;
  std::vector<MorphologyPoint> points;
};

/// The process's point at time t, linear between samples; InputError outside its time range.
MorphologyPoint point_at(const Process& p, double t);

/// d_P over [t1, t2]: trapezoid rule on the union of both processes' sample times in the
/// interval (each process interpolated linearly). InputError unless t1 < t2 and both processes
/// cover [t1, t2].
double process_distance(const Process& a, const Process& b, double t1, double t2);
/// S_D = 1 / d_P.
double dynamic_similarity(const Process& a, const Process& b, double t1, double t2);

struct ThresholdMatch {
  std::size_t index = 0;          ///< position of the best threshold
  double threshold = 0.0;         ///< T_th2 minimising d_P
  double distance = 0.0;          ///< its d_P
  std::vector<double> distances;  ///< d_P for every candidate threshold
};

/// Fig. 43's search: the reference process (v1, T_th1) against another process (v2, ·) known at
/// every candidate threshold — candidates[k] is the process at thresholds[k] — returns the
/// threshold whose process is closest (smallest d_P over [t1, t2]). Ties keep the lowest threshold.
ThresholdMatch match_threshold(const Process& reference, std::span<const double> thresholds,
                               const std::vector<Process>& candidates, double t1, double t2);

}  // namespace shockfield::analysis
