// The thermo table: exact header and rows, columns aligned (every line the same length), integers
// as integers, other values as %.8g, bad rows refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "shockfield/core/thermo_table.hpp"

using namespace shockfield;

TEST(ThermoTable, HeaderAndRowsAreAlignedColumns) {
  const ThermoTable table({"Step", "Temp", "PotEng", "AVeryLongColumnName"});
  EXPECT_EQ(table.header(), "           Step            Temp          PotEng AVeryLongColumnName");
  const std::string row = table.row({1000, 300.123456789, -3.54e5, 0.5});
  EXPECT_EQ(row, "           1000       300.12346         -354000                 0.5");
  EXPECT_EQ(row.size(), table.header().size());
  // Every value ends where its column name ends.
  const std::string wide = table.row({123456789, -1.2345678e-100, 1e15, -0.0});
  EXPECT_EQ(wide, "      123456789 -1.2345678e-100           1e+15                   0");
  EXPECT_EQ(wide.size(), table.header().size());
}

TEST(ThermoTable, NonFiniteValuesAreNamed) {
  const ThermoTable table({"A", "B", "C"});
  EXPECT_EQ(table.row({std::nan(""), std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity()}),
            "            nan             inf            -inf");
}

TEST(ThermoTable, BadColumnsAndRowsAreRefused) {
  EXPECT_THROW(ThermoTable({"Step", ""}), std::invalid_argument);
  EXPECT_THROW(ThermoTable({"Pot Eng"}), std::invalid_argument);
  const ThermoTable table({"Step", "Temp"});
  EXPECT_THROW(table.row({1.0}), std::invalid_argument);
  EXPECT_THROW(table.row({1.0, 2.0, 3.0}), std::invalid_argument);
}
