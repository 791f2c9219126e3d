// references/cavity.hpp against the tables of PHYSICS.md §4.1 (mpmath, 40 digits, printed with 12-13
// significant digits). Tolerance: half a unit in the 12th significant digit is 5e-12 relative; x 2
// = 1e-11 (the double evaluation itself is ~1e-14).
#include <gtest/gtest.h>

#include <numbers>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/cavity.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {
namespace ref = rodvv::references;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kTol = 1e-11;
const ref::CavityColumn kColumn{};  // L = EI = 1, a = 0.1
// Relative tolerance with an absolute floor of 1e-13 (for the zero-force row).
::testing::AssertionResult close(double actual, double expected, double rel) {
  return rodvv::testing::is_close(actual, expected, rel, 1e-13);
}

struct PointRow {
  double psi_deg, phi0_deg, P, wall_force, kappa_c, shortening, H;
};
// PHYSICS.md §4.1, point-contact branch.
const PointRow kPoint[] = {
    {0, 18.1903521489, 9.99507377527, 0, 0.999507377527, 0.0250667235005, -9.4955662764},
    {2, 16.3514645371, 11.5783776553, 0.808651714381, 0.960771406503, 0.0252102084189, -11.1168368076},
    {4, 14.5851313025, 13.7418852402, 1.92185244989, 0.905939836260, 0.0254221903638, -13.3315217468},
    {6, 12.9522886062, 16.8581035416, 3.54371616153, 0.822706966424, 0.0257646511277, -16.5196801653},
    {8, 11.5990996323, 21.6418447332, 6.08312584661, 0.683545901129, 0.0263962248840, -21.4082272337},
    {10, 10.9320434885, 29.3930845048, 10.3655876889, 0.419987908972, 0.0278137170317, -29.3048895830},
};

TEST(CavityReference, PointContactBranchMatchesTheTable) {
  for (const PointRow& row : kPoint) {
    const auto s = ref::cavity_point_contact(kColumn, row.psi_deg * kDeg);
    EXPECT_TRUE(close(s.phi0 / kDeg, row.phi0_deg, kTol));
    EXPECT_TRUE(close(s.P, row.P, kTol));
    EXPECT_NEAR(s.wall_force, row.wall_force, kTol * std::max(1.0, row.wall_force));
    EXPECT_TRUE(close(s.kappa_mid, row.kappa_c, kTol));
    EXPECT_TRUE(close(s.shortening, row.shortening, kTol));
    EXPECT_TRUE(close(s.H, row.H, kTol));
  }
}

TEST(CavityReference, ShorteningInversionRecoversTheBoldRows) {
  // d = 0.026: P = 18.77024913497, H = -18.47467025139, 2Q = 4.55095304246, psi = 6.91211398195 deg.
  const auto s = ref::cavity_from_shortening(kColumn, 0.026);
  EXPECT_EQ(s.regime, ref::CavityRegime::PointContact);
  EXPECT_TRUE(close(s.P, 18.77024913497, kTol));
  EXPECT_TRUE(close(s.H, -18.47467025139, kTol));
  EXPECT_TRUE(close(s.wall_force, 4.55095304246, kTol));
  EXPECT_TRUE(close(s.psi / kDeg, 6.91211398195, kTol));
  // H = 1/2 EI kappa_c^2 - P on the point branch (PHYSICS.md §4.1): an identity of the formulas.
  EXPECT_TRUE(close(s.H, 0.5 * s.kappa_mid * s.kappa_mid - s.P, 1e-14 * 64));
  const auto t = ref::cavity_from_shortening(kColumn, 0.027);
  EXPECT_TRUE(close(t.P, 25.34747369597, kTol));
  EXPECT_TRUE(close(t.H, -25.18824649882, kTol));
}

struct LineRow {
  double l, phi0_deg, P, Q, shortening;
};
const LineRow kLine[] = {{0, 11.6590563884, 38.8647372906, 8.01954060826, 0.0307490369059},
                         {0.1, 13.0097012652, 47.7952032266, 11.0429164222, 0.0343735404784},
                         {0.3, 16.9838119916, 77.9073528657, 23.7946012404, 0.0451678212339},
                         {0.6, 32.9774116716, 215.816306082, 140.031812975, 0.0917610341583}};

TEST(CavityReference, LineContactBranchMatchesTheTable) {
  for (const LineRow& row : kLine) {
    const auto s = ref::cavity_line_contact(kColumn, row.l);
    EXPECT_TRUE(close(s.phi0 / kDeg, row.phi0_deg, kTol));
    EXPECT_TRUE(close(s.P, row.P, kTol));
    EXPECT_TRUE(close(s.edge_force, row.Q, kTol));
    EXPECT_TRUE(close(s.shortening, row.shortening, kTol));
    EXPECT_EQ(s.H, -s.P);
    // Inversion from the shortening returns the flat length.
    if (row.l > 0.0 && row.l < 0.6) {
      const auto back = ref::cavity_from_shortening(kColumn, s.shortening);
      EXPECT_EQ(back.regime, ref::CavityRegime::LineContact);
      EXPECT_NEAR(back.flat_length, row.l, 1e-12);
    }
  }
}

TEST(CavityReference, BranchesMeetAtTheTransitions) {
  // Touch: point branch at psi = 0 equals the free first mode with y_max = a.
  const double d_touch = ref::cavity_touch_shortening(kColumn);
  EXPECT_TRUE(close(d_touch, 0.0250667235004637, kTol));
  const auto free = ref::cavity_from_shortening(kColumn, std::nextafter(d_touch, 0.0));
  const auto point = ref::cavity_point_contact(kColumn, 0.0);
  EXPECT_TRUE(close(free.P, point.P, 1e-9));
  // Point -> line: kappa_c -> 0 and the loads agree.
  const double d_line = ref::cavity_transition_shortening(kColumn);
  EXPECT_TRUE(close(d_line, 0.0307490369058919, kTol));
  const auto before = ref::cavity_from_shortening(kColumn, d_line * (1 - 1e-12));
  const auto after = ref::cavity_line_contact(kColumn, 0.0);
  EXPECT_TRUE(close(before.P, after.P, 1e-6));
  EXPECT_LT(before.kappa_mid, 1e-3);
}

TEST(CavityReference, AWrongGapIsDetected) {
  const auto s = ref::cavity_from_shortening({1.0, 1.0, 0.1001}, 0.026);
  EXPECT_FALSE(close(s.P, 18.77024913497, kTol));
}

TEST(CavityReference, BadInputNamesTheParameter) {
  auto expect = [](auto f, const std::string& name) {
    try {
      f();
      ADD_FAILURE() << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  };
  expect([] { ref::cavity_from_shortening({1.0, 1.0, 0.0}, 0.026); }, "wall_gap");
  expect([] { ref::cavity_from_shortening({1.0, 1.0, 0.1}, 0.0); }, "shortening");
  expect([] { ref::cavity_from_shortening({1.0, 1.0, 0.1}, 0.1); }, "shortening");
  expect([] { ref::cavity_line_contact({1.0, 1.0, 0.1}, 0.7); }, "flat_length");
  expect([] { ref::cavity_point_contact({1.0, 1.0, 0.1}, 0.5); }, "psi");
  expect([] { ref::cavity_point_contact({-1.0, 1.0, 0.1}, 0.05); }, "L");
}

}  // namespace
