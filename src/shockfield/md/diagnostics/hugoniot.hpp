#pragma once
// Shock-front tracking and Hugoniot-state extraction from binned profiles of a piston-driven
// shock in material initially at rest. The front is where the particle velocity along the
// axis first exceeds half the piston speed, looking from the undisturbed side (linear
// interpolation between bins); U_s is the least-squares slope of the front position against
// time over the fit window; the shocked state is the count-weighted mean of the bins between
// the piston and the front (a margin of `margin_bins` bins kept from each), the initial density
// that of the bins ahead of the front (the same margin kept from the free end). Rankine–Hugoniot
// cross-checks: P = ρ₀ U_s U_p and ρ = ρ₀ U_s/(U_s − U_p).
#include <string>
#include <vector>

#include "shockfield/md/diagnostics/profiles.hpp"

namespace shockfield::md {

struct HugoniotState {
  double us = NAN;            ///< shock speed, km/s
  double up = NAN;            ///< mean particle speed behind the front, km/s
  double piston_speed = NAN;  ///< km/s
  double pressure = NAN;      ///< P_axis from the virial, GPa
  double pressure_rh = NAN;   ///< ρ₀ U_s U_p, GPa
  double density = NAN;       ///< g/cm³
  double density_rh = NAN;    ///< ρ₀ U_s/(U_s − U_p), g/cm³
  double density0 = NAN;      ///< g/cm³, ahead of the front
  double temperature = NAN;   ///< K
  int frames = 0;             ///< profiles used in the fit window
  std::string note;           ///< why a value is missing, if one is
  /// Every value finite (a state the sweep can use); otherwise `note` says why not.
  bool complete() const;
};

/// The Hugoniot state of a time-averaged homogeneous cell (an msst or nphug stage: U_s, U_p in
/// km/s, P in GPa, ρ, ρ₀ in g/cm³, T in K over `samples` steps): the Rankine–Hugoniot pressure
/// and density from ρ₀, U_s, U_p beside the measured ones, and piston_speed = U_p (the speed of
/// the piston that would drive this shock).
HugoniotState cell_hugoniot_state(double us, double up, double pressure, double density, double density0,
                                  double temperature, double samples, std::string note);

/// Front position (Å) in one profile, NaN when no bin exceeds half the piston speed.
double front_position(const Profile& profile, int axis, int side, double piston_speed);

/// `piston_speed` in Å/ps along side·axis, `wall(t)` the piston position, frames in time order.
/// The fit window is the last (1 − skip_fraction) of the frames' time span; it ends at the first
/// profile whose front is within `margin_bins` of the free end (then the note says the front
/// reached the free end: make the sample longer or the stage shorter).
HugoniotState extract_hugoniot(const std::vector<Profile>& frames, int axis, int side,
                               double piston_speed, double wall0, double wall_t0,
                               double skip_fraction = 0.3, int margin_bins = 3);

/// The state as TOML: finite values only (a missing one is left out, never written as nan),
/// `complete` and `note`.
std::string hugoniot_toml(const HugoniotState& s);

}  // namespace shockfield::md
