// references/sleeve.hpp (PHYSICS.md §6.1 sliding sleeve, §6.2 elastica arm scale), checked against
// tests/data/sleeve_reference.csv, written by tests/data/make_sleeve_table.py: mpmath at 34 digits,
// each arm integrated from the exit as an initial value problem (phi' = m/B, m' = -P cos phi) with
// mpmath.odefun, x and w by mpmath.quad over that solution, the tip where m = 0, shooting on the exit
// moment; the arm scale is closed by the axial balance at the EXITS, (P1 + P2) sin alpha =
// (M2^2 - M1^2)/(2B). The C++ instead uses elliptic integrals (Carlson forms) and closes the arm scale
// by the TIP condition P1 sin beta1 = P2 sin beta2, so the table is independent of both.
//
// Error unit: eps relative to max(|expected|, scale), scale = 1 for angles, the arm length scale for
// lengths and positions, P for forces, P x for moments (in_epsilons of tolerance.hpp).
// Tolerance per value: kSlack eps (1 + cond), cond = the relative condition number of the quantity
// with respect to the row's load (P, S or P1), measured by a central difference of the C++ function
// itself (see condition()). Why: the C++ evaluates closed forms to a few eps and solves its roots to
// a 4 eps bracket (TOMS 748, eps_tolerance), i.e. it returns the exact answer of a problem whose
// data are perturbed by a few eps; the output error is then a few eps times a condition number.
// kSlack = 64 covers "a few" with margin; the measured maxima are printed as "[ summary  ]" lines.
// Measured (x86-64 Release and ASan+UBSan, GCC 12): sleeve_length <= 2.0 eps (30 values),
// sleeve_pull <= 2.3 eps (20 values), arm_scale <= 4.1 eps (88 values); every value <= 0.054 of its
// tolerance. Conditions measured are <= ~4 (S/P = 0.9 rows).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/elastica.hpp"
#include "rodvv/references/sleeve.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {
namespace ref = rodvv::references;
using rodvv::testing::in_epsilons;
using rodvv::testing::kEpsilon;
using rodvv::testing::parse_table_number;

constexpr double kSlack = 64.0;

// One configuration of the table with its quantities.
struct Config {
  std::string kind;  // sleeve_length, sleeve_pull, arm_scale
  double P1, P2, B, alpha, L, sleeve_length, S;
  std::map<std::string, double> values;
  std::string key;  // the input fields as written, identifying the configuration
};

const std::vector<Config>& table() {
  static const std::vector<Config> configs = [] {
    std::vector<Config> out;
    const auto rows = rodvv::testing::read_reference_table(
        "sleeve_reference.csv", "kind,P1,P2,B,alpha,L,sleeve_length,S,quantity,value");
    for (const auto& f : rows) {
      std::string key;
      for (std::size_t i = 0; i < 8; ++i) key += f[i] + ",";
      Config c{f[0],
               parse_table_number(f[1]),
               parse_table_number(f[2]),
               parse_table_number(f[3]),
               parse_table_number(f[4]),
               parse_table_number(f[5]),
               parse_table_number(f[6]),
               parse_table_number(f[7]),
               {},
               key};
      // rows of one configuration are consecutive
      if (out.empty() || out.back().key != key) out.push_back(c);
      out.back().values[f[8]] = parse_table_number(f[9]);
    }
    return out;
  }();
  return configs;
}

// The quantities a configuration produces, as a name -> value map (same names as the table).
using Values = std::map<std::string, double>;

Values sleeve_values(const ref::SleeveEquilibrium& e) {
  return {{"free_length", e.free_length}, {"tip_angle", e.tip_angle}, {"exit_moment", e.exit_moment},
          {"tension_jump", e.tension_jump}, {"invariant", e.invariant}, {"tip_x", e.tip_x},
          {"tip_y", e.tip_y}};
}

Values arm_scale_values(const ref::ArmScaleEquilibrium& e) {
  return {{"l1", e.arm1.length},     {"l2", e.arm2.length},       {"beta1", e.arm1.tip_angle},
          {"beta2", e.arm2.tip_angle}, {"M1", e.arm1.exit_moment}, {"M2", e.arm2.exit_moment},
          {"N", e.axial_force},       {"tip1_x", e.arm1.tip_x},    {"tip1_y", e.arm1.tip_y},
          {"tip2_x", e.arm2.tip_x},   {"tip2_y", e.arm2.tip_y}};
}

// The C++ values of a configuration with its load (P, S or P1) multiplied by `factor`.
Values evaluate(const Config& c, double factor = 1.0) {
  if (c.kind == "sleeve_length")
    return sleeve_values(ref::sleeve_equilibrium_for_length({c.P1 * factor, c.B}, c.L));
  if (c.kind == "sleeve_pull") return sleeve_values(ref::sleeve_equilibrium({c.P1, c.B}, c.S * factor));
  if (c.kind == "arm_scale")
    return arm_scale_values(
        ref::arm_scale_equilibrium({c.alpha, c.P1 * factor, c.P2, c.B, c.L, c.sleeve_length}));
  ADD_FAILURE() << "unknown kind " << c.kind;
  return {};
}

// Scale of a quantity (the unit of its error in eps): angles 1, lengths sqrt(B/P), forces P,
// moments sqrt(P B).
double scale_of(const Config& c, const std::string& q) {
  const double P = c.kind == "arm_scale" ? std::min(c.P1, c.P2) : c.P1;
  const double length = std::sqrt(c.B / P);
  if (q == "tip_angle" || q == "beta1" || q == "beta2") return 1.0;
  if (q == "invariant" || q == "tension_jump" || q == "N") return P;
  if (q == "exit_moment" || q == "M1" || q == "M2") return std::sqrt(P * c.B);
  return length;
}

// Relative condition number |d ln q / d ln load| by a central difference of the C++ function
// (relative step 1e-6: truncation ~1e-12, rounding ~1e-10 relative to a cond of order one).
double condition(const Config& c, const std::string& q, double value) {
  constexpr double h = 1e-6;
  const double up = evaluate(c, 1.0 + h).at(q);
  const double down = evaluate(c, 1.0 - h).at(q);
  return std::abs((up - down) / (2.0 * h)) / std::max(std::abs(value), 1e-300);
}

struct Summary {
  double worst_eps = 0.0;
  double worst_fraction = 0.0;  // of the tolerance
  double worst_cond = 0.0;
  std::string where;
  std::map<std::string, double> per_quantity;  // max error [eps] per quantity
};

void compare_kind(const std::string& kind) {
  Summary summary;
  int compared = 0;
  for (const Config& c : table()) {
    if (c.kind != kind) continue;
    const Values got = evaluate(c);
    for (const auto& [q, expected] : c.values) {
      const auto it = got.find(q);
      ASSERT_NE(it, got.end()) << kind << ": no C++ value for " << q;
      const double scale = std::max(std::abs(expected), scale_of(c, q));
      const double error = in_epsilons(it->second - expected, scale);
      const double cond = condition(c, q, expected);
      const double tolerance = kSlack * (1.0 + cond);
      EXPECT_LE(error, tolerance) << kind << " P1=" << c.P1 << " alpha=" << c.alpha << " S=" << c.S
                                  << ": " << q << " = " << it->second << " vs " << expected << " ("
                                  << error << " eps, cond " << cond << ")";
      ++compared;
      if (error > summary.worst_eps) {
        summary.worst_eps = error;
        summary.where = q + " (P1=" + std::to_string(c.P1) + ", alpha=" + std::to_string(c.alpha) +
                        ", S=" + std::to_string(c.S) + ", cond " + std::to_string(cond) + ")";
      }
      summary.worst_fraction = std::max(summary.worst_fraction, error / tolerance);
      summary.worst_cond = std::max(summary.worst_cond, cond);
      summary.per_quantity[q] = std::max(summary.per_quantity[q], error);
    }
  }
  EXPECT_GT(compared, 0) << "no " << kind << " rows in the table";
  std::cout << "[ summary  ] " << kind << ": " << compared << " values, max error "
            << summary.worst_eps << " eps at " << summary.where << "; max error/tolerance "
            << summary.worst_fraction << ", max cond " << summary.worst_cond << "\n[ summary  ]  ";
  for (const auto& [q, e] : summary.per_quantity) std::cout << " " << q << " " << e;
  std::cout << " (eps)\n";
}

// §6.1 rows at fixed free length l = 1 (through cantilever_tip).
TEST(SleeveReference, FixedLengthRowsMatchTheMpmathTable) { compare_kind("sleeve_length"); }
// §6.1 rows at a given pull S (explicit closed form, no iteration).
TEST(SleeveReference, GivenPullRowsMatchTheMpmathTable) { compare_kind("sleeve_pull"); }
// §6.2 arm-scale configurations (TOMS 748 on l1, nested TOMS 748 per arm).
TEST(SleeveReference, ArmScaleRowsMatchTheMpmathTable) { compare_kind("arm_scale"); }

// The table of PHYSICS.md §6.1 (l = B = 1, P = alpha), printed with 13 significant digits: half a
// unit in the 13th digit is <= 5e-13 relative; x 2 -> 1e-12.
TEST(SleeveReference, PhysicsTableSixOneIsReproduced) {
  struct Row {
    double alpha, phi_tip, s_over_p, m_e, x_tip;
  };
  const Row rows[] = {{0.5, 0.2445336471332, 0.2421038721061, 0.4920405187646, 0.9840810375292},
                      {1, 0.4613519497119, 0.4451591187953, 0.9435667637166, 0.9435667637166},
                      {2, 0.7817498315565, 0.7045223208193, 1.678716558350, 0.8393582791748},
                      {5, 1.215368117612, 0.9374975614726, 3.061858196378, 0.6123716392756},
                      {10, 1.430285538804, 0.9901445900927, 4.450044022462, 0.4450044022462}};
  constexpr double kTol = 1e-12;
  for (const Row& r : rows) {
    const auto e = ref::sleeve_equilibrium_for_length({r.alpha, 1.0}, 1.0);
    EXPECT_TRUE(rodvv::testing::is_close(e.tip_angle, r.phi_tip, kTol, 0.0)) << r.alpha;
    EXPECT_TRUE(rodvv::testing::is_close(e.invariant / r.alpha, r.s_over_p, kTol, 0.0)) << r.alpha;
    EXPECT_TRUE(rodvv::testing::is_close(e.exit_moment, r.m_e, kTol, 0.0)) << r.alpha;
    EXPECT_TRUE(rodvv::testing::is_close(e.tip_x, r.x_tip, kTol, 0.0)) << r.alpha;
    // S l^2 / B column = S here.
    EXPECT_TRUE(rodvv::testing::is_close(e.tension_jump, r.s_over_p * r.alpha, kTol, 0.0)) << r.alpha;
  }
}

// ------------------------------------------------------------------------------------------------
// Identities of the closed forms (each a few roundings apart; tolerances in the comments).

TEST(SleeveReference, PullAndLengthDirectionsAreInverse) {
  // l -> S -> l: the second step is explicit; cond(l; S) = |d ln l/d ln S| <= ~3 for S/P <= 0.99,
  // so 64 eps (1 + 3) = 256 eps relative covers it.
  for (double P : {0.5, 1.0, 2.0, 5.0, 10.0}) {
    const auto forward = ref::sleeve_equilibrium_for_length({P, 1.3}, 0.8);
    const auto back = ref::sleeve_equilibrium({P, 1.3}, forward.invariant);
    EXPECT_TRUE(rodvv::testing::is_close(back.free_length, 0.8, 256 * kEpsilon, 0.0)) << P;
    EXPECT_TRUE(rodvv::testing::is_close(back.tip_angle, forward.tip_angle, 256 * kEpsilon, 0.0)) << P;
    EXPECT_TRUE(rodvv::testing::is_close(back.tip_y, forward.tip_y, 256 * kEpsilon, 0.0)) << P;
  }
}

TEST(SleeveReference, HorizontalClampArmIsTheCantileverOfSectionThreeFive) {
  // inclined_arm_tip with theta0 = 0 and cantilever_tip are different closed forms of the same arm
  // (addition-theorem forms with a = pi/4 vs elastica.cpp); both are accurate to a few eps: 64 eps.
  for (double P : {0.5, 1.0, 3.0, 20.0}) {
    const auto arm = ref::inclined_arm_tip({0.0, P, 1.0}, 1.0);
    const auto cantilever = ref::cantilever_tip({1.0, 1.0, P});
    EXPECT_TRUE(rodvv::testing::is_close(arm.tip_angle, cantilever.phi_L, 64 * kEpsilon, 0.0)) << P;
    EXPECT_TRUE(rodvv::testing::is_close(arm.drop, cantilever.w, 64 * kEpsilon, 0.0)) << P;
    EXPECT_TRUE(rodvv::testing::is_close(arm.invariant, cantilever.H, 64 * kEpsilon, 0.0)) << P;
  }
}

TEST(SleeveReference, SymmetricScaleSitsCentred) {
  // alpha = 0, P1 = P2: l1 = l2 = (L - sleeve)/2 and mirror-image tips. The root is solved to a
  // 4 eps bracket of l1 ~ 1; 16 eps absolute.
  const auto e = ref::arm_scale_equilibrium({0.0, 1.0, 1.0, 1.0, 2.0, 0.2});
  EXPECT_NEAR(e.arm1.length, 0.9, 16 * kEpsilon);
  EXPECT_NEAR(e.arm2.length, 0.9, 16 * kEpsilon);
  EXPECT_NEAR(e.sleeve_shift, 0.0, 32 * kEpsilon);
  EXPECT_NEAR(e.arm1.tip_x, -e.arm2.tip_x, 16 * kEpsilon);
  EXPECT_NEAR(e.arm1.tip_y, e.arm2.tip_y, 16 * kEpsilon);
  EXPECT_NEAR(e.arm1.tip_angle, e.arm2.tip_angle, 16 * kEpsilon);
}

TEST(SleeveReference, ArmScaleSatisfiesTheEshelbyBalanceAndMirrorSymmetry) {
  // (P1 + P2) sin alpha = (M2^2 - M1^2)/(2B) and P2 sin beta2 = N: identities of the exact solution
  // that the C++ does not impose (it imposes P1 sin beta1 = P2 sin beta2 only); 64 eps of P.
  for (double alpha : {-0.4, 0.0, 0.1, 0.3}) {
    for (double P1 : {0.7, 1.0, 1.5}) {
      const ref::ArmScale s{alpha, P1, 1.0, 1.3, 2.5, 0.3};
      const auto e = ref::arm_scale_equilibrium(s);
      const double lhs = (s.P1 + s.P2) * std::sin(alpha);
      const double rhs = (e.arm2.exit_moment * e.arm2.exit_moment - e.arm1.exit_moment * e.arm1.exit_moment) /
                         (2.0 * s.B);
      EXPECT_NEAR(lhs, rhs, 64 * kEpsilon) << alpha << " " << P1;
      EXPECT_NEAR(s.P2 * std::sin(e.arm2.tip_angle), e.axial_force, 64 * kEpsilon) << alpha << " " << P1;
      EXPECT_DOUBLE_EQ(e.sleeve_shift, e.arm2.length - e.arm1.length);
      // Mirror x -> -x: alpha -> -alpha and the arms swap (64 eps of the lengths ~ 1).
      const auto m = ref::arm_scale_equilibrium({-alpha, s.P2, s.P1, s.B, s.L, s.sleeve_length});
      EXPECT_NEAR(m.arm1.length, e.arm2.length, 64 * kEpsilon);
      EXPECT_NEAR(m.arm1.tip_x, -e.arm2.tip_x, 64 * kEpsilon);
      EXPECT_NEAR(m.arm1.tip_y, e.arm2.tip_y, 64 * kEpsilon);
      EXPECT_NEAR(m.axial_force, e.axial_force, 64 * kEpsilon);
    }
  }
}

TEST(SleeveReference, ArmTipAngleIncreasesWithLength) {
  // The monotonicity that makes the arm-scale root unique (sleeve.hpp), sampled.
  for (double theta0 : {-1.4, -0.5, 0.0, 0.5, 1.4}) {
    double previous = theta0;
    for (double l = 0.05; l < 6.0; l += 0.05) {
      const double beta = ref::inclined_arm_tip({theta0, 2.0, 0.7}, l).tip_angle;
      EXPECT_GT(beta, previous) << theta0 << " " << l;
      EXPECT_LT(beta, 0.5 * std::numbers::pi);
      previous = beta;
    }
  }
  const auto zero = ref::inclined_arm_tip({0.3, 2.0, 0.7}, 0.0);
  EXPECT_EQ(zero.tip_angle, 0.3);
  EXPECT_EQ(zero.extent, 0.0);
}

// ------------------------------------------------------------------------------------------------
// The comparison can fail: a load perturbed by 1e-9 relative moves the answer by ~1e-9 x cond,
// i.e. ~1e6 eps, far beyond kSlack (1 + cond) eps.
TEST(SleeveReference, APerturbedLoadTurnsTheComparisonRed) {
  for (const Config& c : table()) {
    const Values got = evaluate(c, 1.0 + 1e-9);
    const std::string q = c.kind == "arm_scale" ? "l1" : c.kind == "sleeve_pull" ? "free_length" : "tip_angle";
    const double expected = c.values.at(q);
    const double error = in_epsilons(got.at(q) - expected, std::max(std::abs(expected), scale_of(c, q)));
    EXPECT_GT(error, kSlack * (1.0 + condition(c, q, expected))) << c.kind << " " << q;
  }
}

// ------------------------------------------------------------------------------------------------
template <class F>
void expect_input_error(F f, const std::string& name, const std::string& fragment = "") {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << name;
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), name) << e.what();
    if (!fragment.empty()) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
}

TEST(SleeveReference, BadInputNamesTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_input_error([] { ref::sleeve_equilibrium({1.0, 1.0}, 0.0); }, "S", "(0, P)");
  expect_input_error([] { ref::sleeve_equilibrium({1.0, 1.0}, 1.0); }, "S", "(0, P)");
  expect_input_error([] { ref::sleeve_equilibrium({2.0, 1.0}, 2.5); }, "S", "(0, P)");
  expect_input_error([nan] { ref::sleeve_equilibrium({1.0, 1.0}, nan); }, "S");
  expect_input_error([] { ref::sleeve_equilibrium({-1.0, 1.0}, 0.5); }, "P");
  expect_input_error([] { ref::sleeve_equilibrium({1.0, 0.0}, 0.5); }, "B");
  expect_input_error([] { ref::sleeve_equilibrium_for_length({1.0, 1.0}, 0.0); }, "free_length");
  expect_input_error([] { ref::sleeve_equilibrium_for_length({1.0, -2.0}, 1.0); }, "B");
  expect_input_error([] { ref::inclined_arm_tip({1.6, 1.0, 1.0}, 1.0); }, "theta0");
  expect_input_error([] { ref::inclined_arm_tip({0.0, 1.0, 1.0}, -1.0); }, "length");
  expect_input_error([] { ref::inclined_arm_tip({0.0, 1.0, 1.0}, 1e3); }, "length");
  const ref::ArmScale good{0.1, 1.0, 1.0, 1.0, 2.0, 0.2};
  auto with = [good](auto change) {
    ref::ArmScale s = good;
    change(s);
    return s;
  };
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.alpha = 1.6; })); }, "alpha");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.alpha = -std::numbers::pi / 2; })); },
                     "alpha");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.P1 = 0.0; })); }, "P1");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([nan](auto& s) { s.P2 = nan; })); }, "P2");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.B = -1.0; })); }, "B");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.L = 0.0; })); }, "L");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.L = 1e3; })); }, "L");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.sleeve_length = 0.0; })); },
                     "sleeve_length");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.sleeve_length = 2.0; })); },
                     "sleeve_length", "a sleeve longer than the rod");
  expect_input_error([&] { ref::arm_scale_equilibrium(with([](auto& s) { s.sleeve_length = 3.0; })); },
                     "sleeve_length", "a sleeve longer than the rod");
}

TEST(SleeveReference, NoEquilibriumIsASolverErrorNamingTheArm) {
  // P1 sin(alpha) = 2.96 > P2 = 1: even with l1 = 0 arm 1 out-pulls anything arm 2 can hold.
  try {
    ref::arm_scale_equilibrium({0.3, 10.0, 1.0, 1.0, 2.0, 0.2});
    ADD_FAILURE() << "no SolverError";
  } catch (const ref::ArmPulledIn& e) {
    EXPECT_EQ(e.arm(), 2);
    EXPECT_NE(std::string(e.what()).find("arm 2 is pulled fully into the sleeve"), std::string::npos) << e.what();
    EXPECT_GE(e.residual(), 0.0);
  }
  // The mirror image: arm 1 is pulled in.
  try {
    ref::arm_scale_equilibrium({-0.3, 1.0, 10.0, 1.0, 2.0, 0.2});
    ADD_FAILURE() << "no SolverError";
  } catch (const ref::ArmPulledIn& e) {
    EXPECT_EQ(e.arm(), 1);
    EXPECT_NE(std::string(e.what()).find("arm 1 is pulled fully into the sleeve"), std::string::npos) << e.what();
    EXPECT_LE(e.residual(), 0.0);
  }
}

}  // namespace
