#pragma once
// Unit systems and conversions. Only this file holds conversion constants.
// md uses LAMMPS "metal" units: Å, eV, ps, amu, K, bar. The constants are the ones LAMMPS
// (29 Sep 2021, src/update.cpp) uses, so that our numbers and LAMMPS's agree to round-off.

namespace shockfield::units::metal {

inline constexpr double boltz = 8.617343e-5;     ///< Boltzmann constant, eV/K
inline constexpr double mvv2e = 1.0364269e-4;    ///< amu·Å²/ps² → eV
inline constexpr double ftm2v = 1.0 / 1.0364269e-4;  ///< eV/Å / amu → Å/ps²
inline constexpr double nktv2p = 1.6021765e6;    ///< eV/Å³ → bar
inline constexpr double amu_per_A3_to_g_per_cc = 1.66053904;  ///< amu/Å³ → g/cm³
inline constexpr double A_per_ps_to_km_per_s = 0.1;  ///< Å/ps → km/s
inline constexpr double bar_to_GPa = 1.0e-4;
inline constexpr double eV_to_J = 1.6021765e-19;     ///< the eV of nktv2p
inline constexpr double amu_to_kg = 1.66053904e-27;  ///< the amu of amu_per_A3_to_g_per_cc

}  // namespace shockfield::units::metal

namespace shockfield::units::si {

inline constexpr double eV = 1.602176634e-19;     ///< J (exact, SI 2019)
inline constexpr double amu = 1.66053906660e-27;  ///< kg (CODATA 2018)
inline constexpr double boltz = 1.380649e-23;     ///< Boltzmann constant, J/K (exact, SI 2019)
inline constexpr double hbar = 1.054571817e-34;   ///< reduced Planck constant, J·s (exact)
inline constexpr double angstrom = 1e-10;         ///< m

/// A model in dim < 3 dimensions stands for a slab (2D: per metre of thickness) or a bar (1D: per
/// square metre of cross-section), its points' volumes ΔX^dim: its extensive totals (mass,
/// momentum, energy) are per unit of the missing dimensions. The suffix a CSV column name carries
/// after its unit (`kinetic_J_per_m`), and the words a log line adds after the unit.
inline constexpr const char* per_missing_dimensions_column(int dim) {
  return dim >= 3 ? "" : dim == 2 ? "_per_m" : "_per_m2";
}
inline constexpr const char* per_missing_dimensions_text(int dim) {
  return dim >= 3 ? "" : dim == 2 ? " per m of thickness" : " per m2 of cross-section";
}

}  // namespace shockfield::units::si

namespace shockfield::units::model {

/// The same label for the methods in dimensionless model units (dbm, phasefield), which have no
/// unit to name: a total of a 2D model is per unit length of thickness (`mass_per_length`), of a
/// 1D model per unit area of cross-section (`free_energy_per_area`). DBM's D2V16 lattice is 2D for
/// every case (a 1D problem is one row of cells).
inline constexpr const char* per_missing_dimensions_column(int dim) {
  return dim >= 3 ? "" : dim == 2 ? "_per_length" : "_per_area";
}
inline constexpr const char* per_missing_dimensions_text(int dim) {
  return dim >= 3 ? "" : dim == 2 ? " per unit length of thickness" : " per unit area of cross-section";
}

}  // namespace shockfield::units::model
