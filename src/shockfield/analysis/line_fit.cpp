#include "shockfield/analysis/line_fit.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw InputError(fmt::format("line fit: {} x values but {} y values", x.size(), y.size()));
  const auto n = static_cast<int>(x.size());
  if (n < 2) throw InputError(fmt::format("line fit: {} point(s), need at least 2", n));
  double xm = 0, ym = 0;
  for (int i = 0; i < n; ++i) {
    xm += x[i];
    ym += y[i];
  }
  xm /= n;
  ym /= n;
  double sxx = 0, sxy = 0;  // centred sums: no cancellation for x far from 0 (times, positions)
  for (int i = 0; i < n; ++i) {
    sxx += (x[i] - xm) * (x[i] - xm);
    sxy += (x[i] - xm) * (y[i] - ym);
  }
  if (!(sxx > 0)) throw InputError("line fit: all x values are equal");
  LineFit f;
  f.points = n;
  f.slope = sxy / sxx;
  f.intercept = ym - f.slope * xm;
  double chi2 = 0, sum_x2 = 0;
  for (int i = 0; i < n; ++i) {
    const double r = y[i] - f.intercept - f.slope * x[i];
    chi2 += r * r;
    sum_x2 += x[i] * x[i];
  }
  f.residual_rms = std::sqrt(chi2 / n);
  if (n > 2) {
    f.slope_stderr = std::sqrt(chi2 / (n - 2) / sxx);
    f.intercept_stderr = f.slope_stderr * std::sqrt(sum_x2 / n);
  } else {
    f.slope_stderr = f.intercept_stderr = std::numeric_limits<double>::quiet_NaN();
  }
  return f;
}

LineFit fit_shock_front(const std::vector<double>& time, const std::vector<double>& front, double skip_fraction) {
  if (time.size() != front.size() || time.empty())
    throw InputError(fmt::format("shock front fit: {} times and {} front positions", time.size(), front.size()));
  const double t_fit = time.front() + skip_fraction * (time.back() - time.front());
  std::vector<double> t, x;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < t_fit || !std::isfinite(front[i])) continue;
    t.push_back(time[i]);
    x.push_back(front[i]);
  }
  return fit_line(t, x);
}

UsUpFit fit_us_up(const std::vector<double>& up, const std::vector<double>& us) { return UsUpFit{fit_line(up, us)}; }

std::string us_up_fit_toml(const UsUpFit& f) {
  return fmt::format(
      "# U_s = c0 + s U_p, least squares; standard errors from the residuals (n - 2 dof)\n"
      "c0_km_s = {}\nc0_stderr_km_s = {}\ns = {}\ns_stderr = {}\nresidual_rms_km_s = {}\npoints = {}\n",
      f.c0(), f.line.intercept_stderr, f.s(), f.line.slope_stderr, f.line.residual_rms, f.line.points);
}

}  // namespace shockfield::analysis
