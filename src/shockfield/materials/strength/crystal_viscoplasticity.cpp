#include "shockfield/materials/strength/crystal_viscoplasticity.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "shockfield/core/error.hpp"

namespace shockfield::materials {

CrystalViscoplasticity CrystalViscoplasticity::ofhc_copper() { return CrystalViscoplasticity{}; }

void CrystalViscoplasticity::validate(const std::string& where) const {
  auto require = [&](bool ok, const char* name, double v, const char* expected) {
    if (!ok) throw InputError(fmt::format("{}: crystal {} = {} (expected {})", where, name, v, expected));
  };
  require(reference_rate > 0.0, "reference_rate", reference_rate, "> 0 1/s");
  require(rate_sensitivity > 0.0 && rate_sensitivity <= 1.0, "rate_sensitivity", rate_sensitivity, "0 < m <= 1");
  require(initial_resistance > 0.0, "g0", initial_resistance, "> 0 Pa");
  require(saturation_resistance > initial_resistance, "g_s", saturation_resistance, "> g0");
  require(hardening >= 0.0, "h0", hardening, ">= 0 Pa");
  require(latent_ratio >= 0.0, "q", latent_ratio, ">= 0");
  require(hardening_exponent > 0.0, "hardening_exponent", hardening_exponent, "a > 0");
  require(c44 > 0.0 && c11 > std::abs(c12) && c11 + 2.0 * c12 > 0.0, "c11/c12/c44", c11,
          "a positive-definite cubic stiffness (c44 > 0, c11 > |c12|, c11 + 2c12 > 0)");
  require(substep_factor > 0.0 && substep_factor < 2.0, "substep_factor", substep_factor, "0 < κ < 2");
}

CrystalViscoplasticity::State CrystalViscoplasticity::initial_state(const Mat3& orientation) const {
  State s;
  s.orientation = s.lattice = orientation;
  s.resistance.assign(systems.size(), initial_resistance);
  s.slip.assign(systems.size(), 0.0);
  return s;
}

Mat3 CrystalViscoplasticity::elastic_stress(const Mat3& fe) const {
  const Mat3 e = 0.5 * (fe.transpose() * fe - Mat3::Identity());  // eq. 30
  Mat3 s;  // eqs. 31-32, Voigt shear strains 2E_ij
  const double tr = e.trace();
  for (int i = 0; i < 3; ++i) s(i, i) = (c11 - c12) * e(i, i) + c12 * tr;
  s(0, 1) = s(1, 0) = 2.0 * c44 * e(0, 1);
  s(0, 2) = s(2, 0) = 2.0 * c44 * e(0, 2);
  s(1, 2) = s(2, 1) = 2.0 * c44 * e(1, 2);
  return s;
}

Mat3 CrystalViscoplasticity::update(State& s, const Mat3& f_old, const Mat3& f_new, double dt) const {
  const Mat3& g = s.orientation;
  const Mat3 a = g.transpose() * f_old * g, b = g.transpose() * f_new * g;  // crystal frame
  const std::size_t n = systems.size();
  std::vector<double> rate(n), hardening_rate(n);
  double done = 0.0;
  for (long long taken = 0; dt > 0.0 && done < 1.0; ++taken) {
    if (taken == kMaxSubsteps) return Mat3::Constant(std::numeric_limits<double>::quiet_NaN());
    const Mat3 f = a + done * (b - a);
    const Mat3 fe = f * s.fp.inverse();
    const Mat3 mandel = (fe.transpose() * fe) * elastic_stress(fe);
    double fastest = 0.0, weakest = s.resistance[0];
    for (std::size_t k = 0; k < n; ++k) {
      const double tau = systems[k].direction.dot(mandel * systems[k].normal);  // eq. 35
      const double ratio = std::abs(tau / s.resistance[k]);
      rate[k] = reference_rate * std::pow(ratio, 1.0 / rate_sensitivity) * (tau < 0.0 ? -1.0 : 1.0);  // eq. 37
      fastest = std::max(fastest, std::abs(rate[k]));
      weakest = std::min(weakest, s.resistance[k]);
    }
    const double max_increment = substep_factor * rate_sensitivity * weakest / c44;
    const double h = std::min((1.0 - done) * dt, fastest > 0.0 ? max_increment / fastest : dt);
    // eqs. 38-41
    const double total_rate = [&] {
      double sum = 0.0;
      for (double r : rate) sum += std::abs(r);
      return sum;
    }();
    if (hardening_law == HardeningLaw::sech2) {
      const double sech = 1.0 / std::cosh(hardening * s.accumulated_slip / (saturation_resistance - initial_resistance));
      const double h_self = hardening * sech * sech;
      for (std::size_t k = 0; k < n; ++k)
        hardening_rate[k] = h_self * (latent_ratio * total_rate + (1.0 - latent_ratio) * std::abs(rate[k]));
    } else {  // Kalidindi et al. 1992: h^β from each system's own resistance
      double weighted = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        const double x = 1.0 - s.resistance[k] / saturation_resistance;
        hardening_rate[k] = hardening * std::copysign(std::pow(std::abs(x), hardening_exponent), x) * std::abs(rate[k]);
        weighted += hardening_rate[k];
      }
      for (std::size_t k = 0; k < n; ++k)
        hardening_rate[k] = latent_ratio * weighted + (1.0 - latent_ratio) * hardening_rate[k];
    }
    Mat3 lp = Mat3::Zero();  // eq. 20
    for (std::size_t k = 0; k < n; ++k) lp += rate[k] * systems[k].direction * systems[k].normal.transpose();
    Mat3 fp = (Mat3::Identity() - h * lp).inverse() * s.fp;  // Algorithm 1 step 5
    s.fp = fp / std::cbrt(fp.determinant());                  // step 6
    for (std::size_t k = 0; k < n; ++k) {                      // step 7
      s.slip[k] += rate[k] * h;
      s.resistance[k] += hardening_rate[k] * h;
    }
    s.accumulated_slip += total_rate * h;
    done += h / dt;
    ++s.substeps;
  }
  const Mat3 fe = b * s.fp.inverse();  // step 8
  const double j = fe.determinant();
  const Mat3 sigma = fe * elastic_stress(fe) * fe.transpose() / j;  // step 9, eq. 34
  const Eigen::JacobiSVD<Mat3> svd(fe, Eigen::ComputeFullU | Eigen::ComputeFullV);
  s.lattice = g * (svd.matrixU() * svd.matrixV().transpose());  // steps 10-11: Re of Fe = Re Ue
  return g * sigma * g.transpose();
}

}  // namespace shockfield::materials
