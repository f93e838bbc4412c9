#include "shockfield/phasefield/domain_measures.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/analysis/minkowski.hpp"

namespace shockfield::phasefield {
namespace {

constexpr double kThreshold = 0.5;

// The moments are those of the hcp set {ξ > 1/2}, not of ξ: the diffuse tails of ξ would widen
// a radius-R disc's moment axes to √(R² + 5π²l²/3) (l = √(2D); +10 % at R = 12, D = 1).
double mass(double xi) { return xi > kThreshold ? 1.0 : 0.0; }

// Surface, curvature and χ of {ξ ≥ 1/2} from the Minkowski functionals (2D/3D), fronts in 1D.
void add_surface(const Grid& g, const std::vector<double>& xi, DomainMeasures& m) {
  if (g.dim == 1) {
    const auto hcp = [&](int i) { return xi[static_cast<std::size_t>(i)] > kThreshold; };
    std::int64_t fronts = 0;
    for (int i = 0; i + 1 < g.n[0]; ++i) fronts += hcp(i) != hcp(i + 1);
    if (g.periodic(0)) fronts += hcp(g.n[0] - 1) != hcp(0);
    m.surface = static_cast<double>(fronts);
    m.euler = fronts / 2;
    return;
  }
  analysis::GridField f;
  for (int d = 0; d < 3; ++d) f.n[d] = static_cast<std::size_t>(g.n[d]), f.spacing[d] = g.dx;
  f.values = xi;
  analysis::MinkowskiOptions options;
  options.boundary = g.all_periodic() ? analysis::Boundary::periodic : analysis::Boundary::open;
  const double threshold[] = {kThreshold};
  if (g.dim == 2) {
    const analysis::Functionals2D w = analysis::minkowski_2d(f, threshold, options).front();
    m.surface = w.boundary_length;
    m.euler = w.euler;
    m.mean_curvature = w.boundary_length > 0 ? 2.0 * std::numbers::pi * static_cast<double>(w.euler) / w.boundary_length : 0.0;
  } else {
    const analysis::Functionals3D w = analysis::minkowski_3d(f, threshold, options).front();
    m.surface = w.surface_area;
    m.euler = w.euler;
    m.mean_curvature = w.surface_area > 0 ? w.integral_mean_curvature / w.surface_area : 0.0;
  }
}

// Centre (circular mean along periodic axes) and semi-axes from the central second moments.
void add_axes(const Grid& g, const std::vector<double>& xi, DomainMeasures& m) {
  double total = 0.0;
  std::array<double, 3> linear{0, 0, 0}, cosine{0, 0, 0}, sine{0, 0, 0};
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const double w = mass(xi[g.index(i, j, k)]);
        const int node[3] = {i, j, k};
        total += w;
        for (int d = 0; d < g.dim; ++d) {
          const double x = node[d] * g.dx, phase = 2.0 * std::numbers::pi * x / g.length(d);
          linear[d] += w * x, cosine[d] += w * std::cos(phase), sine[d] += w * std::sin(phase);
        }
      }
  if (total <= 0.0) return;
  for (int d = 0; d < g.dim; ++d) {
    if (!g.periodic(d)) {
      m.center[d] = linear[d] / total;
      continue;
    }
    const double angle = std::atan2(sine[d], cosine[d]);
    m.center[d] = (angle < 0 ? angle + 2.0 * std::numbers::pi : angle) * g.length(d) / (2.0 * std::numbers::pi);
  }
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const double w = mass(xi[g.index(i, j, k)]);
        if (w == 0.0) continue;
        const int node[3] = {i, j, k};
        Eigen::Vector3d r = Eigen::Vector3d::Zero();
        for (int d = 0; d < g.dim; ++d) {
          r[d] = node[d] * g.dx - m.center[d];
          if (g.periodic(d)) r[d] -= g.length(d) * std::round(r[d] / g.length(d));  // minimum image
        }
        moment += w * r * r.transpose();
      }
  moment /= total;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(moment);  // ascending eigenvalues
  const double factor = g.dim == 3 ? 5.0 : g.dim == 2 ? 4.0 : 3.0;  // uniform ellipsoid, ellipse, segment
  for (int a = 0; a < g.dim; ++a) m.semi_axes[a] = std::sqrt(factor * std::max(0.0, eigen.eigenvalues()[2 - a]));
  // The long axis's sign is free: its largest component is made positive.
  Eigen::Vector3d axis = eigen.eigenvectors().col(2);
  Eigen::Index largest = 0;
  axis.cwiseAbs().maxCoeff(&largest);
  if (axis[largest] < 0) axis = -axis;
  for (int d = 0; d < 3; ++d) m.long_axis[d] = axis[d];
}

}  // namespace

DomainMeasures domain_measures(const Grid& grid, const std::vector<double>& xi) {
  DomainMeasures m;
  add_surface(grid, xi, m);
  add_axes(grid, xi, m);
  return m;
}

}  // namespace shockfield::phasefield
