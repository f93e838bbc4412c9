#pragma once
// 1D binned profiles along the shock axis: per bin the atom count, mass density, centre-of-mass
// velocity, temperature with the bin's centre-of-mass velocity removed (3n−3 degrees of freedom)
// and the pressure tensor P_ab = (Σ m (v−v̄)_a (v−v̄)_b + Σ W_ab)/V_bin from per-atom virials
// (LAMMPS compute stress/atom summed over the bin, sign flipped to pressure).
#include <filesystem>
#include <vector>

#include "shockfield/md/simulation.hpp"

namespace shockfield::md {

struct ProfileBin {
  double position = 0;   ///< bin centre along the axis, Å
  int count = 0;
  double density = 0;    ///< g/cm³
  Vec3 velocity = Vec3::Zero();  ///< centre-of-mass velocity, Å/ps
  double temperature = 0;        ///< K
  Voigt6 pressure = Voigt6::Zero();  ///< GPa, xx yy zz xy xz yz
};

struct Profile {
  std::int64_t step = 0;
  double time = 0;  ///< ps
  std::vector<ProfileBin> bins;
};

/// Bins the owned atoms along `axis` in slabs of `width` Å spanning the box. Needs per-atom
/// virials in sim.forces (sim.per_atom_this_step).
Profile bin_profile(const Simulation& sim, int axis, double width);

/// Column names of a profile CSV row, and the row for one bin.
std::vector<std::string> profile_columns();
std::vector<double> profile_row(const Profile& p, std::size_t bin);

}  // namespace shockfield::md

namespace shockfield::md {

/// Reads back the frames of a profiles.csv written by a run (for post-processing).
std::vector<Profile> read_profiles_csv(const std::filesystem::path& file);

}  // namespace shockfield::md
