// core/unit_names: the column suffix of a unit and its powers (docs/conventions.md).
#include <gtest/gtest.h>

#include "shockfield/core/error.hpp"
#include "shockfield/core/unit_names.hpp"

namespace shockfield::units {

TEST(UnitNames, SpellsTheUnitsTheWritersUse) {
  EXPECT_EQ(column_suffix("Pa"), "Pa");
  EXPECT_EQ(column_suffix("kg/m3"), "kg_m3");
  EXPECT_EQ(column_suffix("m/s"), "m_s");
  EXPECT_EQ(column_suffix("J/kg"), "J_kg");
  EXPECT_EQ(column_suffix("1/A^3"), "per_A3");
  EXPECT_EQ(column_name("mean", "K"), "mean_K");
}

TEST(UnitNames, PowersMultiplyEveryFactor) {
  EXPECT_EQ(column_suffix("m", 2), "m2");
  EXPECT_EQ(column_suffix("m", -1), "per_m");
  EXPECT_EQ(column_suffix("A", -1), "per_A");
  EXPECT_EQ(column_suffix("kg/m3", 2), "kg2_m6");
  EXPECT_EQ(column_suffix("m/s", -1), "s_m");
  EXPECT_EQ(column_suffix("1/A^3", -1), "A3");
}

TEST(UnitNames, PureNumbersAndUnnamedUnits) {
  EXPECT_EQ(column_suffix("1", 2), "1");
  EXPECT_EQ(column_suffix("1", -1), "1");
  EXPECT_EQ(column_suffix("", 2), "unknown");
}

TEST(UnitNames, RefusesWhatItCannotSpell) {
  EXPECT_THROW(column_suffix("m/s²"), InputError);
  EXPECT_THROW(column_suffix("Pa-s"), InputError);
  EXPECT_THROW(column_suffix("m123"), InputError);
}

// The length unit of each style of LAMMPS's `units` command (its documentation's table), as a dump's
// ITEM: UNITS names it; anything else is no style.
TEST(UnitNames, LammpsUnitStylesLengths) {
  EXPECT_EQ(lammps_length_unit("metal"), "A");
  EXPECT_EQ(lammps_length_unit("real"), "A");
  EXPECT_EQ(lammps_length_unit("si"), "m");
  EXPECT_EQ(lammps_length_unit("cgs"), "cm");
  EXPECT_EQ(lammps_length_unit("electron"), "Bohr");
  EXPECT_EQ(lammps_length_unit("micro"), "um");
  EXPECT_EQ(lammps_length_unit("nano"), "nm");
  EXPECT_EQ(lammps_length_unit("lj"), "1");
  EXPECT_EQ(lammps_length_unit("Metal"), "");
  EXPECT_EQ(lammps_length_unit(""), "");
}

}  // namespace shockfield::units
