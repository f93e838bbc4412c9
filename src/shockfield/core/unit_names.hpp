#pragma once
// A unit as the suffix of a CSV column name (docs/conventions.md, "Units in column names"): "/"
// becomes "_", a power its trailing digits, a reciprocal unit "per_": "kg/m3" → kg_m3, "m/s" →
// m_s, "1/A^3" → per_A3. Tables whose unit comes from their input (`shockfield analyze`'s field
// tables) spell a pure number or a model unit "1" as `1` and an input that names no unit as
// `unknown`, so every such column carries a suffix a reader (and tests/cli/conventions.py) can tell.
#include <string>

namespace shockfield::units {

/// The suffix naming `unit` raised to `power` (1, 2, −1, …): ("Pa", 2) → Pa2, ("m", −1) → per_m,
/// ("kg/m3", 2) → kg2_m6, ("1", p) → 1, ("", p) → unknown. Throws InputError for a unit it cannot
/// spell (characters other than letters, digits, "/", "^", "*", ".", " ").
std::string column_suffix(const std::string& unit, int power = 1);

/// `name` + "_" + column_suffix(unit, power): ("mean", "Pa") → mean_Pa.
std::string column_name(const std::string& name, const std::string& unit, int power = 1);

/// The unit styles of LAMMPS's `units` command, as a list for messages.
inline constexpr const char* kLammpsUnitStyles = "lj, real, metal, si, cgs, electron, micro, nano";

/// The length unit of a LAMMPS unit style (a dump's `ITEM: UNITS`; LAMMPS's `units` command page):
/// real and metal → "A", si → "m", cgs → "cm", electron → "Bohr", micro → "um", nano → "nm",
/// lj → "1" (reduced units); "" for a word that is no unit style.
std::string lammps_length_unit(const std::string& style);

}  // namespace shockfield::units
