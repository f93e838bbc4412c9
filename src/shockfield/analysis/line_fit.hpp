#pragma once
// Straight-line least squares with standard errors, for the two fits of a Hugoniot sweep:
//  - the shock speed of one run, U_s = slope of the front position against time over the fit
//    window of extract_hugoniot (hugoniot.hpp), with the scatter of the front about that line;
//  - the linear U_s–U_p Hugoniot over a sweep of piston speeds, U_s = c0 + s·U_p.
// Standard errors from the residuals (n − 2 degrees of freedom), e.g. Press et al., Numerical
// Recipes, 3rd ed., §15.2: σ_slope² = χ²/(n−2) / Σ(x−x̄)², σ_intercept² = σ_slope² Σx²/n.
// Successive front positions are correlated in time, so the slope error of a front fit is a
// lower bound of the run-to-run scatter (seeds, thermal state), not its estimate.
#include <string>
#include <vector>

namespace shockfield::analysis {

struct LineFit {
  double intercept = 0, slope = 0;
  double intercept_stderr = 0, slope_stderr = 0;  ///< NaN with two points (no residual)
  double residual_rms = 0;                        ///< √(χ²/n)
  int points = 0;
};

/// y = intercept + slope·x; throws InputError for fewer than 2 points, unequal sizes or all x
/// equal.
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

/// Front position (Å) against time (ps) over the last (1 − skip_fraction) of the time span, as
/// extract_hugoniot fits it; non-finite fronts are skipped. slope is U_s in Å/ps.
LineFit fit_shock_front(const std::vector<double>& time, const std::vector<double>& front,
                        double skip_fraction = 0.3);

/// U_s = c0 + s·U_p (km/s) from the points of a sweep.
struct UsUpFit {
  LineFit line;  ///< intercept = c0 (km/s), slope = s
  double c0() const { return line.intercept; }
  double s() const { return line.slope; }
};
UsUpFit fit_us_up(const std::vector<double>& up, const std::vector<double>& us);

/// TOML lines c0_km_s, s, their standard errors, the rms residual and the point count.
std::string us_up_fit_toml(const UsUpFit& fit);

}  // namespace shockfield::analysis
