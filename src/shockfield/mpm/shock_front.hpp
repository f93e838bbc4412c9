#pragma once
// The shock front and the shocked state along the shock axis (docs/mpm.md, "Shock front and
// Hugoniot"), measured as MD measures a piston's (md/diagnostics/hugoniot.hpp):
//  - per frame, one body's particles binned in slabs along the shock axis (mass-weighted means
//    of the window quantities of diagnostics.hpp, and the bulk density), the front where the compressive longitudinal
//    stress −σ_aa crosses half its jump from the state ahead to the plateau behind (sub-slab
//    linear interpolation, analysis/shock_profile), and the plateau: the mean and scatter of each
//    quantity over the slabs between the impact face and the top of the front (where −σ_aa first
//    reaches 90 % of the jump), `margin_bins` slabs kept from each. With a Hugoniot elastic limit σ_HEL and a plateau above it the elastic precursor
//    is sought too, at half the HEL, and the plastic front then crosses (σ_HEL + plateau)/2;
//    the precursor's plateau is the half of the stretch between the fronts next to the precursor;
//  - over the frames, the front speed by least squares of position against time (analysis::fit_line)
//    over the last (1 − skip_fraction) of the frames where a front was found, ending before the
//    first frame whose leading front is within `margin_bins` of the body's free end, and the
//    plateaus pooled over those frames; U_s and u_p relative to the material ahead, and the
//    Rankine–Hugoniot density and longitudinal stress from them.
#include <optional>
#include <string>
#include <vector>

#include "shockfield/analysis/shock_profile.hpp"
#include "shockfield/materials/solid_material.hpp"
#include "shockfield/mpm/diagnostics.hpp"
#include "shockfield/mpm/particles.hpp"

namespace shockfield::mpm {

/// σ_HEL = (K + 4G/3)·Y0/(2G), K = ρ0c0²: the longitudinal stress of uniaxial strain where the
/// deviator reaches yield (s_aa = (2/3)Y0 with P = K ε_v, s_aa = (4/3)G ε); 0 without strength.
double hugoniot_elastic_limit(const materials::SolidMaterial& m);

struct ShockFrontSettings {
  int body = 0;                  ///< the [[body]] whose particles are profiled
  int direction = 1;             ///< +1: the shock runs towards increasing position along the axis
  double bin_width = 0.0;        ///< slab width [m]
  int margin_bins = 6;           ///< slabs kept from the fronts, the impact face and the free end
  double window_fraction = 1.0;  ///< the plateau window is this part of [face, front] next to the front
  double hel = 0.0;              ///< σ_HEL of the body's material [Pa]; 0: no precursor sought
  double skip_fraction = 0.3;    ///< first part of the frames' time span left out of the fit
};

/// [shock_front] as read: the settings and what the toml is named after.
struct ShockFrontSpec {
  ShockFrontSettings settings;
  std::string material;  ///< the profiled body's material: hugoniot_<material>.toml
};

/// What a profile holds per slab: the window quantities (diagnostics.hpp) and bulk_density [kg/m³]
/// (slab mass over slab volume, voids included).
std::vector<WindowQuantity> profile_quantities(int dim);

/// One frame's slabs: centres, masses, and per quantity of profile_quantities(dim) the
/// mass-weighted means (the bulk density: the slab's mass over its volume).
struct ShockProfile {
  double time = 0.0;
  std::vector<double> position, mass;
  std::vector<std::vector<double>> means;  ///< [quantity][slab]
};

/// Slabs [lo + k·width, lo + (k+1)·width) over [lo, hi) along the axis (dim − 1) of the particles
/// of `body`; each point's mass is shared among the slabs its box (half-width l0·|F_aa|) overlaps.
/// `cross_section`: the lateral measure of a slab (m in 2D, m² in 3D; the body filling it).
ShockProfile shock_profile(const Particles& p, int dim, int body, double lo, double hi, double width,
                           double cross_section, double time);

/// What one frame shows (positions in m; moments per profile quantity).
struct FrontFrame {
  double time = 0.0;
  double front = NAN;      ///< the (plastic) front
  double precursor = NAN;  ///< the elastic precursor, when one runs ahead by more than 2·margin_bins slabs
  double rise = NAN;       ///< the top of the (plastic) front: −σ_aa first at 90 % of its jump
  double face = NAN;       ///< the body's last occupied slab behind the front (the impact face)
  double free_end = NAN;   ///< its last occupied slab ahead
  double leading = NAN;     ///< the leading edge: the precursor, else where −σ_aa first reaches min(σ_HEL, peak)/2
  bool at_free_end = false;  ///< the leading edge within margin_bins of the free end
  std::vector<double> ahead;  ///< means ahead of the leading edge
  std::vector<analysis::WeightedMoments> plateau, precursor_plateau;
};

FrontFrame analyse_front(const ShockProfile& profile, int dim, const ShockFrontSettings& s);

/// One wave's state: its speed U_s and the plateau behind it, with the jump conditions from the
/// state it runs into (1: ahead of it): ρ = ρ1(U_s − u1)/(U_s − u_p), σ_aa = σ1 − ρ1(U_s − u1)(u_p − u1),
/// ρ the bulk densities (voids included: a porous body's Hugoniot), velocities relative to the
/// material ahead of the leading front, along the shock's direction.
struct WaveState {
  double us = NAN, us_stderr = NAN;   ///< [m/s]
  double up = NAN;                    ///< [m/s]
  double density_rh = NAN;            ///< [kg/m³]
  double stress_rh = NAN;             ///< σ_aa, tension positive [Pa]
  std::vector<analysis::WeightedMoments> plateau;  ///< per profile quantity
  int frames = 0;
  double fit_start = NAN, fit_end = NAN;  ///< [s]
};

struct ShockHugoniot {
  WaveState shock;                     ///< the (plastic) shock
  std::optional<WaveState> precursor;  ///< the elastic precursor, if found in 3 or more fitted frames
  std::vector<double> ahead;           ///< means of the state ahead over the fitted frames
  std::string note;                    ///< why a value is missing, if one is
  bool complete() const;
};

/// Fits the frames (in time order) as the header says.
ShockHugoniot fit_hugoniot(const std::vector<FrontFrame>& frames, int dim, const ShockFrontSettings& s);

/// hugoniot_<name>.toml: finite values only, keys named as MD's where they mean the same
/// (us, up, density, density0, density_rankine_hugoniot, temperature, frames_in_fit, complete,
/// note) with SI units; `title` is the comment line that opens it.
std::string hugoniot_toml(const ShockHugoniot& h, int dim, const std::string& title);

}  // namespace shockfield::mpm
