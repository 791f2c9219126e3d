// Tests of the heavy cantilever lifted off a frictionless floor (references/src/heavy_touchdown.cpp).
//
// Oracle: tests/data/heavy_touchdown_reference.csv from tests/data/make_heavy_touchdown_table.py (mpmath, 30
// digits: the exact large-deflection elastica by shooting, not the C++ closed forms), at delta / l = 5.6e-6,
// 1e-3, 6.1e-3 and 9e-3 and scales from EI = 0.9 to 4.1e5. The clamp's moment sqrt(2 EI w delta) is exact:
// gated in eps (a square root of a product of three doubles: 8 eps). The small-deflection span and clamp
// force carry the model error (3/7) (delta / l)^2 (the expansion's next term): each row's relative error
// divided by (delta / l)^2 must lie within 1e-3 of 3/7 - both sides, so that a formula too good is as red as
// one too bad - where that error is above 1e-12 (at delta / l = 5.6e-6 it is 1.3e-11, the doubles' rounding
// 1e-16 a 1e-5 part of it). Measured: within 3.3e-5 of 3/7 (the next order, (delta / l)^4, and rounding).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "rodvv/references/heavy_touchdown.hpp"
#include "rodvv/testing/input_error.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::testing::in_epsilons;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "quantity,EI,w,delta,value";
enum Column { kQuantity, kEI, kW, kDelta, kValue };

struct TableCheck {
  double worst_moment_eps = 0.0;
  double worst_coefficient_offset = 0.0;  // max | error / (delta / l)^2 / (3/7) - 1 |
  int moment_failures = 0, model_failures = 0, rows = 0;
};

// The table checked with every delta scaled by delta_scale in the C++ formulas (1: the test itself).
TableCheck check_table(double delta_scale = 1.0) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("heavy_touchdown_reference.csv", kHeader)) {
    const auto number = [&](Column c) { return parse_table_number(row[c]); };
    const ref::HeavyTouchdown rod{number(kEI), number(kW), number(kDelta) * delta_scale};
    const std::string& name = row[kQuantity];
    const double expected = number(kValue);
    ++check.rows;
    if (name == "clamp_moment") {
      const double error = in_epsilons(ref::touchdown_clamp_moment(rod) - expected, expected);
      check.worst_moment_eps = std::max(check.worst_moment_eps, error);
      check.moment_failures += !(error <= 8.0);
      continue;
    }
    double actual = std::nan("");
    if (name == "clamp_force") actual = ref::touchdown_clamp_force(rod);
    if (name == "lifted_span") actual = ref::touchdown_lifted_span(rod);
    if (name == "lifted_arc") continue;  // reported in the table, no small-deflection counterpart
    const double slope = number(kDelta) / ref::touchdown_lifted_span({number(kEI), number(kW), number(kDelta)});
    const double relative = std::abs(actual / expected - 1.0);
    if (3.0 / 7.0 * slope * slope < 1e-12) continue;
    const double offset = std::abs(relative / (slope * slope) / (3.0 / 7.0) - 1.0);
    check.worst_coefficient_offset = std::max(check.worst_coefficient_offset, std::isnan(offset) ? 1e300 : offset);
    check.model_failures += !(offset <= 1e-3);
  }
  return check;
}

TEST(HeavyTouchdownReference, MatchesTheExactElasticaTable) {
  const TableCheck check = check_table();
  EXPECT_EQ(check.rows, 16);
  EXPECT_EQ(check.moment_failures, 0) << "worst " << check.worst_moment_eps << " eps";
  EXPECT_EQ(check.model_failures, 0) << "worst offset of the (3/7) (delta / l)^2 law " << check.worst_coefficient_offset;
  std::cout << "[ summary  ] clamp moment max error (eps): " << check.worst_moment_eps
            << "; small-deflection error / ((3/7) (delta/l)^2) within " << check.worst_coefficient_offset << " of 1\n";
}

TEST(HeavyTouchdownReference, PerturbedHeightTurnsTheMomentAndTheModelLawRed) {
  // delta (1 + 1e-9) moves the moment by 5e-10 relative (2e6 eps) and l by 2.5e-10, which is 60 % of the
  // model error at delta / l = 6.1e-3 and more at 1e-3.
  const TableCheck check = check_table(1.0 + 1e-9);
  EXPECT_EQ(check.moment_failures, 4);
  EXPECT_GT(check.model_failures, 0);
}

TEST(HeavyTouchdownReference, ShapeMeetsItsBoundaryConditions) {
  const ref::HeavyTouchdown rod{2.3, 17.0, 4e-3};
  const double l = ref::touchdown_lifted_span(rod), h = 1e-4 * l;
  EXPECT_NEAR(ref::touchdown_height(rod, 0.0), rod.delta, 4 * 2.2e-16 * rod.delta);  // at the clamp
  // y'(0) = 0 by a central difference, whose error is h^2 y''' / 6 with y''' = O(w l / EI): bound h^2 w l / EI.
  EXPECT_NEAR((ref::touchdown_height(rod, h) - ref::touchdown_height(rod, -h)) / (2 * h), 0.0, h * h * rod.w * l / rod.EI);
  EXPECT_EQ(ref::touchdown_height(rod, l), 0.0);
  EXPECT_EQ(ref::touchdown_height(rod, 1.5 * l), 0.0);
  // y'' = m / EI at the clamp: -M / EI with M = sqrt(2 EI w delta) (central second difference, O(h^2)).
  const double curvature =
      (ref::touchdown_height(rod, h) - 2 * ref::touchdown_height(rod, 0.0) + ref::touchdown_height(rod, -h)) / (h * h);
  EXPECT_NEAR(curvature, -ref::touchdown_clamp_moment(rod) / rod.EI, 1e-6 * ref::touchdown_clamp_moment(rod) / rod.EI);
}

TEST(HeavyTouchdownReference, RefusesNonPhysicalInput) {
  const auto parameter_of = [](const ref::HeavyTouchdown& rod) {
    return rodvv::testing::input_error_parameter_of([&] { ref::touchdown_lifted_span(rod); });
  };
  EXPECT_EQ(parameter_of({0.9, 0.06, 1e-3}), "<no InputError>");
  EXPECT_EQ(parameter_of({0.0, 0.06, 1e-3}), "EI");
  EXPECT_EQ(parameter_of({0.9, -0.06, 1e-3}), "w");
  EXPECT_EQ(parameter_of({0.9, 0.06, std::nan("")}), "delta");
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([] { ref::touchdown_height({0.9, 0.06, 1e-3}, std::nan("")); }),
            "x");
}

}  // namespace
