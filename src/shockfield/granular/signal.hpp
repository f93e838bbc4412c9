#pragma once
// Measures of the signal travelling down a chain (definitions in docs/granular.md):
//   front edge   the deepest grain whose |v| is at least `edge_fraction` of the chain's largest |v|;
//   leading peak the first local maximum of v met going up from the front edge; its position
//                (grain index, refined by a parabola through the peak and its two neighbours)
//                and depth; amplitude = the peak's grain velocity;
//   force        the largest dynamic contact force F_k − F⁰_k over the leading lobe;
//   width        the lobe's full width at half its peak velocity, in grains (half crossings
//                interpolated linearly);
//   speed        the central difference of the peak's depth between neighbouring samples.
// Power laws y = A x^p are fitted by least squares on ln y = ln A + p ln x; the exponent's
// standard error is the regression's σ_p = sqrt(Σr²/(n − 2) / Σ(ln x − mean)²).
#include <vector>

#include "shockfield/granular/simulation.hpp"

namespace shockfield::granular {

struct SignalSample {
  double time = 0.0;
  double position = 0.0;  ///< grain index of the leading peak (fractional)
  double depth = 0.0;     ///< its depth [m]
  double velocity = 0.0;  ///< peak grain velocity [m/s]
  double force = 0.0;     ///< peak dynamic contact force in the lobe [N]
  double width = 0.0;     ///< FWHM of the lobe [grains]
  double speed = 0.0;     ///< [m/s], filled by fill_speeds
};

/// The leading peak now; `valid` false when no grain moves.
struct SignalFront {
  bool valid = false;
  SignalSample sample;
};
SignalFront measure_signal(const Simulation& sim, double edge_fraction = 0.01);

/// The largest velocity each chosen grain reaches and when, refined by a parabola through the
/// sampled maximum and its two neighbours in time. Call sample() at equal time intervals.
class PeakTracker {
 public:
  struct Peak {
    double time = 0.0;
    double velocity = 0.0;
  };
  explicit PeakTracker(std::vector<std::size_t> grains);
  void sample(const Simulation& sim);
  const std::vector<std::size_t>& grains() const { return grains_; }
  const Peak& peak(std::size_t j) const { return best_[j]; }

 private:
  std::vector<std::size_t> grains_;
  std::vector<double> before_, last_;  ///< the two previous samples of each grain
  std::vector<Peak> best_;
  double last_time_ = 0.0;
  long long samples_ = 0;
};

/// Steps `sim` to `t_end`, measuring the signal every t_end/count (every step if that is
/// shorter); returns the valid samples with their speeds filled.
std::vector<SignalSample> track_signal(Simulation& sim, double t_end, int count = 200);

/// Sets each sample's speed from its neighbours' depths and times (one-sided at the ends).
void fill_speeds(std::vector<SignalSample>& samples);

/// Energy backscattered above an impurity at grain `impurity`: the excess energy of grains
/// [0, impurity − margin) in `sim` minus that in `reference` (the same chain without the impurity,
/// same impulse and step, at the same time). Grains near the impurity are left out so that the
/// impurity's own rattling is not counted as reflected.
double reflected_energy(const Simulation& sim, const Simulation& reference, std::size_t impurity,
                        std::size_t margin = 5);

struct PowerLaw {
  double exponent = 0.0;
  double exponent_error = 0.0;  ///< standard error of the exponent
  double prefactor = 0.0;
};
/// Fit of y = A x^p to positive (x, y); InputError with fewer than three points.
PowerLaw fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace shockfield::granular
