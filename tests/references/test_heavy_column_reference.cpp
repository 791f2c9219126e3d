// Tests of Greenhill's heavy column (references/src/heavy_column.cpp).
//
// Oracle: tests/data/heavy_column_reference.csv from tests/data/make_heavy_column_table.py (mpmath,
// 40 digits: the besselj(-1/3) zero, cross-checked by odefun shooting; not the C++ power series).
// Error unit: eps relative to max(|expected|, 1) (in_epsilons). Tolerance: the series sums terms up
// to ~1.3 to a value near 0 (a few eps absolute) and |f'| ~ 0.09 at the root, so the root carries
// ~30 eps absolute on 7.84 (~4 eps relative) plus the 4 eps bracket; the length's cube root divides
// that by 3 and adds two roundings -> 16 eps for both.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/heavy_column.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::testing::in_epsilons;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "quantity,EI,w,value";
enum Column { kQuantity, kEI, kW, kValue };
constexpr double kTolerance = 16.0;  // eps, see the file comment

struct TableCheck {
  double worst = 0.0;
  int failures = 0, rows = 0, length_failures = 0;
};

// EI scaled by (1 + ei_perturbation) (0 for the real test).
TableCheck check_table(double ei_perturbation) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("heavy_column_reference.csv", kHeader)) {
    double actual = 0.0;
    const bool length = row[kQuantity] == "critical_length";
    if (row[kQuantity] == "critical_weight")
      actual = ref::heavy_column_critical_weight();
    else if (length)
      actual = ref::heavy_column_critical_length(
          {parse_table_number(row[kEI]) * (1.0 + ei_perturbation), parse_table_number(row[kW])});
    else
      ADD_FAILURE() << "unknown quantity " << row[kQuantity];
    const double expected = parse_table_number(row[kValue]);
    const double error = in_epsilons(actual - expected, expected);
    check.worst = std::max(check.worst, error);
    const bool failed = !(error <= kTolerance);
    check.failures += failed;
    check.length_failures += failed && length;
    ++check.rows;
  }
  return check;
}

TEST(HeavyColumnReference, MatchesMpmathTable) {
  const TableCheck check = check_table(0.0);
  EXPECT_EQ(check.rows, 6);
  EXPECT_EQ(check.failures, 0) << "worst " << check.worst << " eps";
  std::cout << "[ summary  ] max error (eps): heavy column " << check.worst << "\n";
}

TEST(HeavyColumnReference, PerturbedStiffnessTurnsTheLengthsRed) {
  // EI (1 + 1e-9) moves every length by 3.3e-10 relative (1.5e6 eps).
  EXPECT_EQ(check_table(1e-9).length_failures, 5);
}

TEST(HeavyColumnReference, RefusesNonPhysicalColumns) {
  const auto parameter_of = [](const ref::HeavyColumn& column) {
    try {
      ref::heavy_column_critical_length(column);
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter_of({1.0, 1.0}), "none");
  EXPECT_EQ(parameter_of({0.0, 1.0}), "EI");
  EXPECT_EQ(parameter_of({1.0, -2.0}), "w");
  EXPECT_EQ(parameter_of({1.0, std::nan("")}), "w");
}

}  // namespace
