// Tests of the capstan with bending stiffness (references/src/capstan.cpp).
//
// Oracle: tests/data/capstan_reference.csv from tests/data/make_capstan_table.py (mpmath, 40 digits:
// the homoclinic spans in closed form, the end forces as vector jumps, the contact arc by odefun, the
// holding tension by findroot; not the C++ closed form). Error unit: eps relative to max(|expected|, 1)
// (in_epsilons). Tolerance: acos(1 - beta / T) near 0 amplifies the rounding of 1 - beta/T by
// 1 / sin psi (<= 1 / 0.097 = 10 in the table); the root T_hold is bracketed to 4 eps and its mismatch
// loses about 1 / (1 - d(rhs)/dT) ~ 2 more -> 64 eps for every quantity. Measured (x86-64 Release,
// GCC 12): 1.3 eps.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/capstan.hpp"
#include "rodvv/testing/input_error.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::testing::in_epsilons;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "quantity,B,R,mu,wrap_angle,pull_tension,value";
enum Column { kQuantity, kB, kR, kMu, kWrap, kTension, kValue };
constexpr double kTolerance = 64.0;  // eps, see the file comment

struct TableCheck {
  double worst = 0.0;
  int failures = 0, rows = 0, tension_failures = 0;
};

// mu scaled by (1 + mu_perturbation) (0 for the real test).
TableCheck check_table(double mu_perturbation) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("capstan_reference.csv", kHeader)) {
    const auto number = [&](Column c) { return parse_table_number(row[c]); };
    const ref::CapstanSolution solution = ref::capstan_with_bending(
        {number(kB), number(kR), number(kMu) * (1.0 + mu_perturbation), number(kWrap), number(kTension)});
    const std::string& name = row[kQuantity];
    double actual = std::nan("");
    if (name == "hold_tension") actual = solution.hold_tension;
    if (name == "contact_angle") actual = solution.contact_angle;
    if (name == "hold_turn") actual = solution.hold_turn;
    if (name == "pull_turn") actual = solution.pull_turn;
    if (name == "hold_end_force") actual = solution.hold_end_force;
    if (name == "pull_end_force") actual = solution.pull_end_force;
    if (name == "hold_offset") actual = solution.hold_offset;
    if (name == "pull_offset") actual = solution.pull_offset;
    const double expected = number(kValue);
    const double error = in_epsilons(actual - expected, expected);
    check.worst = std::max(check.worst, std::isnan(error) ? 1e300 : error);
    const bool failed = !(error <= kTolerance);
    check.failures += failed;
    check.tension_failures += failed && name == "hold_tension";
    ++check.rows;
  }
  return check;
}

TEST(CapstanReference, MatchesMpmathTable) {
  const TableCheck check = check_table(0.0);
  EXPECT_EQ(check.rows, 40);
  EXPECT_EQ(check.failures, 0) << "worst " << check.worst << " eps";
  std::cout << "[ summary  ] max error (eps): capstan " << check.worst << "\n";
}

TEST(CapstanReference, PerturbedFrictionTurnsTheTensionsRed) {
  // mu (1 + 1e-9) moves T_hold by about mu phi 1e-9 relative (1e6 eps) in the four rows with friction.
  EXPECT_EQ(check_table(1e-9).tension_failures, 4);
}

TEST(CapstanReference, FlexibleAndFrictionlessLimits) {
  // B -> 0: Euler's capstan T_hold = T_pull e^{mu phi}, the correction O(sqrt(B)) (the end forces).
  const double phi = 2.5, mu = 0.35, T = 1.9;
  double previous_gap = 1.0;
  for (double B : {1e-2, 1e-4, 1e-6}) {
    const double gap = std::abs(ref::capstan_with_bending({B, 1.3, mu, phi, T}).hold_tension / (T * std::exp(mu * phi)) - 1.0);
    EXPECT_LT(gap, 0.5 * previous_gap) << "B = " << B;
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap, 1e-2);
  // mu = 0: the tension passes unchanged whatever B.
  EXPECT_NEAR(ref::capstan_with_bending({0.4, 0.8, 0.0, phi, T}).hold_tension, T, 8 * T * 2.2e-16);
}

TEST(CapstanReference, RefusesNonPhysicalInput) {
  const auto parameter_of = [](const ref::Capstan& capstan) {
    return rodvv::testing::input_error_parameter_of([&] { ref::capstan_with_bending(capstan); });
  };
  const double pi = std::numbers::pi;
  EXPECT_EQ(parameter_of({0.7, 0.8, 0.3, pi, 2.3}), "<no InputError>");
  EXPECT_EQ(parameter_of({0.0, 0.8, 0.3, pi, 2.3}), "B");
  EXPECT_EQ(parameter_of({0.7, -1.0, 0.3, pi, 2.3}), "R");
  EXPECT_EQ(parameter_of({0.7, 0.8, -0.1, pi, 2.3}), "mu");
  EXPECT_EQ(parameter_of({0.7, 0.8, std::nan(""), pi, 2.3}), "mu");
  EXPECT_EQ(parameter_of({0.7, 0.8, 0.3, 0.0, 2.3}), "wrap_angle");
  EXPECT_EQ(parameter_of({0.7, 0.8, 0.3, pi, 0.0}), "pull_tension");
  EXPECT_EQ(parameter_of({6.0, 0.8, 0.3, pi, 2.3}), "B");           // B / 2R^2 = 4.7 >= 2 T_pull
  EXPECT_EQ(parameter_of({0.736, 0.34, 0.3, pi, 2.3}), "B");        // enters the contact at -0.24
  EXPECT_EQ(parameter_of({0.7, 0.8, 0.3, 0.5, 2.3}), "wrap_angle");  // the spans alone turn by 1.2
}

}  // namespace
