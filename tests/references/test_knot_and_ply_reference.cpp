// Tests of the self-contact references (references/src/knot_and_ply.cpp; PHYSICS.md §5.1, §5.2).
//
// Oracle: tests/data/knot_ply_reference.csv from tests/data/make_knot_ply_table.py (mpmath, 32
// digits, at the exact double inputs; independent methods: the homoclinic integrated as an ODE with
// odefun, findroot for its crossing and R_B; the ply's three linear equations solved by lu_solve, not
// the closed form). Error unit: eps relative to max(|expected|, 1) (in_epsilons). Tolerances:
//  - loose knot: exp, atan, tanh, cosh, sqrt and a few products, each ~1 ulp; theta = 4 atan(e^u)
//    loses nothing, x = s - 2 lambda tanh u cancels near the apex (|x| << |s|) by at most the size of
//    its terms (<= 2 |s| ~ 25 here) -> 32 eps; the crossing is a root to a 4 eps bracket -> 32 eps;
//  - ply: sin, cos and a dozen products and quotients; cos 2 theta = 0.17 at theta = 0.7 amplifies
//    by 1/0.17 -> 32 eps.
// Measured (x86-64 Release, GCC 12): knot 1.6, ply 1.8 eps (the "[ summary  ]" line).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/knot_and_ply.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::testing::in_epsilons;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "quantity,B,T,s,R,theta,F,M,value";
enum Column { kQuantity, kB, kT, kS, kR, kTheta, kF, kM, kValue };
enum Family { kKnot, kPly, kFamilies };
constexpr const char* kFamilyName[kFamilies] = {"knot", "ply"};
constexpr double kTolerance[kFamilies] = {32.0, 32.0};  // eps, see the file comment

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// The C++ value of a table row; B scaled by (1 + b_perturbation) (0 for the real test).
double evaluate(const std::vector<std::string>& row, double b_perturbation, Family& family) {
  auto number = [&](Column c) { return parse_table_number(row[c]); };
  const std::string& name = row[kQuantity];
  const double B = number(kB) * (1.0 + b_perturbation);
  if (starts_with(name, "knot_")) {
    family = kKnot;
    const ref::LooseKnot knot{B, number(kT)};
    const auto sol = ref::loose_knot(knot);
    if (name == "knot_end_shortening") return sol.end_shortening;
    if (name == "knot_crossing_arclength") return sol.crossing_arclength;
    if (name == "knot_crossing_height") return sol.crossing_height;
    if (name == "knot_radius_perpendicular") return sol.radius_perpendicular;
    const auto point = ref::loose_knot_point(knot, number(kS));
    if (name == "knot_theta") return point.theta;
    if (name == "knot_curvature") return point.curvature;
    if (name == "knot_x") return point.x;
    if (name == "knot_y") return point.y;
  } else {
    family = kPly;
    const ref::UniformPly ply{B, number(kR), number(kTheta), number(kF), number(kM)};
    const auto sol = ref::uniform_ply(ply);
    if (name == "ply_twisting_moment") return sol.twisting_moment;
    if (name == "ply_tension") return sol.tension;
    if (name == "ply_binormal_force") return sol.binormal_force;
    if (name == "ply_contact_force") return sol.contact_force;
    if (name == "plectoneme_tail_tension") return ref::plectoneme(ply).tail_tension;
  }
  ADD_FAILURE() << "unknown quantity " << name;
  return 0.0;
}

struct TableCheck {
  double worst[kFamilies] = {};
  int failures[kFamilies] = {};
  int rows[kFamilies] = {};
};

TableCheck check_table(double b_perturbation) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("knot_ply_reference.csv", kHeader)) {
    Family family = kFamilies;
    const double actual = evaluate(row, b_perturbation, family);
    if (family == kFamilies) continue;
    const double expected = parse_table_number(row[kValue]);
    const double error = in_epsilons(actual - expected, expected);
    check.worst[family] = std::max(check.worst[family], error);
    check.failures[family] += !(error <= kTolerance[family]);
    ++check.rows[family];
  }
  return check;
}

TEST(KnotAndPlyReference, MatchesMpmathTable) {
  const TableCheck check = check_table(0.0);
  const int expected_rows[kFamilies] = {40, 23};
  std::cout << "[ summary  ] max error (eps):";
  for (int f = 0; f < kFamilies; ++f) {
    EXPECT_EQ(check.rows[f], expected_rows[f]) << kFamilyName[f];
    EXPECT_EQ(check.failures[f], 0) << kFamilyName[f] << ": worst " << check.worst[f] << " eps";
    std::cout << " " << kFamilyName[f] << " " << check.worst[f];
  }
  std::cout << "\n";
}

TEST(KnotAndPlyReference, PerturbedInputTurnsTableRed) {
  // B (1 + 1e-9) moves every B-dependent value by ~1e-9 relative (>= 4.5e6 eps): both families fail
  // (rows that cannot move stay green: the apex angle pi, x(0) = 0).
  const TableCheck check = check_table(1e-9);
  std::cout << "[ summary  ] rows red with B (1 + 1e-9):";
  for (int f = 0; f < kFamilies; ++f) {
    EXPECT_GT(check.failures[f], check.rows[f] / 2) << kFamilyName[f];
    std::cout << " " << kFamilyName[f] << " " << check.failures[f] << "/" << check.rows[f];
  }
  std::cout << "\n";
}

TEST(KnotAndPlyReference, LooseKnotRelations) {
  const ref::LooseKnot knot{1.7, 0.45};
  const auto sol = ref::loose_knot(knot);
  // T = B/(2 R_B^2), T = B/(4 R_apex^2), end shortening 4 sqrt(B/T): a few roundings -> 8 eps
  EXPECT_TRUE(is_close(knot.B / (2 * sol.radius_perpendicular * sol.radius_perpendicular), knot.T, 8 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(knot.B / (4 * sol.apex_radius * sol.apex_radius), knot.T, 8 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(sol.end_shortening, 4 * std::sqrt(knot.B / knot.T), 4 * kEpsilon, 0.0));
  // PHYSICS.md §5.1: u_c = 1.915008048154537 (16 digits)
  EXPECT_NEAR(ref::loose_knot_crossing_parameter(), 1.915008048154537, 2e-15);
  // H = 1/2 B kappa^2 + T cos theta = T along the loop (each term <= 2T: 16 eps of T); the loop
  // crosses itself: x(s_c) = x(-s_c) = 0, y equal; the tails are straight and 4 lambda apart.
  for (double s : {-7.0, -2.2, -0.4, 0.0, 0.9, 3.3, 40.0}) {
    const auto p = ref::loose_knot_point(knot, s);
    EXPECT_NEAR(p.H, knot.T, 16 * kEpsilon * knot.T) << s;
  }
  const auto plus = ref::loose_knot_point(knot, sol.crossing_arclength);
  const auto minus = ref::loose_knot_point(knot, -sol.crossing_arclength);
  EXPECT_NEAR(plus.x, 0.0, 16 * kEpsilon * sol.crossing_arclength);
  EXPECT_NEAR(plus.x, -minus.x, 4 * kEpsilon * sol.crossing_arclength);
  EXPECT_NEAR(plus.y, sol.crossing_height, 4 * kEpsilon * sol.lambda);
  const double far = 900.0 * sol.lambda;  // sech underflows: exactly straight
  EXPECT_NEAR(ref::loose_knot_point(knot, far).x - ref::loose_knot_point(knot, -far).x, 2 * far - sol.end_shortening,
              8 * kEpsilon * far);
  EXPECT_EQ(ref::loose_knot_point(knot, far).curvature, 0.0);
}

TEST(KnotAndPlyReference, PlectonemeMatchesPhysicsTable) {
  // PHYSICS.md §5.2 table (B = R = 1), printed to 13 significant digits: 1e-12 relative.
  struct Row {
    double degrees, tail, p, twist;
  };
  const Row rows[] = {{5, 8.744177055552e-5, 5.859122448826e-5, 0.001339401520767},
                      {10, 0.001422220813914, 0.0009675983154551, 0.01097504547027},
                      {20, 0.02470483343725, 0.01786293311281, 0.09815601074537},
                      {30, 0.15625, 0.125, 0.4330127018922},
                      {40, 1.068461831987, 0.9831046652026, 2.343237033303}};
  for (const auto& row : rows) {
    const auto sol = ref::plectoneme({1.0, 1.0, row.degrees * std::numbers::pi / 180.0, 0.0, 0.0});
    EXPECT_TRUE(is_close(sol.tail_tension, row.tail, 1e-12, 0.0)) << row.degrees;
    EXPECT_TRUE(is_close(sol.ply.contact_force, row.p, 1e-12, 0.0)) << row.degrees;
    EXPECT_TRUE(is_close(sol.ply.tension, row.p, 1e-12, 0.0)) << row.degrees;  // n_t R^2/B = p R^3/B
    EXPECT_TRUE(is_close(-sol.ply.twisting_moment, row.twist, 1e-12, 0.0)) << row.degrees;
  }
}

TEST(KnotAndPlyReference, PlyScalesAndBalances) {
  // Dimensional scaling: p R^3/B, n_t R^2/B, M_t R/B depend on theta only (a few roundings: 16 eps).
  const auto unit = ref::plectoneme({1.0, 1.0, 0.4, 0.0, 0.0});
  const double B = 2.7, R = 0.031;
  const auto scaled = ref::plectoneme({B, R, 0.4, 0.0, 0.0});
  EXPECT_TRUE(is_close(scaled.ply.contact_force * R * R * R / B, unit.ply.contact_force, 16 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(scaled.ply.twisting_moment * R / B, unit.ply.twisting_moment, 16 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(scaled.tail_tension * R * R / B, unit.tail_tension, 16 * kEpsilon, 0.0));
  // The general ply with load (F, M): the closing conditions hold (force and moment of both strands)
  const ref::UniformPly ply{1.3, 0.8, 0.45, 0.37, -0.21};
  const auto g = ref::uniform_ply(ply);
  const double s = std::sin(ply.theta), c = std::cos(ply.theta);
  EXPECT_NEAR(g.tension * c + g.binormal_force * s, ply.F / 2, 16 * kEpsilon);
  EXPECT_NEAR(ply.B * g.curvature * s + g.twisting_moment * c + ply.R * (g.tension * s - g.binormal_force * c), ply.M / 2,
              16 * kEpsilon);
  EXPECT_NEAR(g.binormal_force, g.curvature * (g.twisting_moment - ply.B * g.torsion), 16 * kEpsilon);
}

TEST(KnotAndPlyReference, BadInputNamesTheParameter) {
  auto expect_parameter = [](auto call, const std::string& name) {
    try {
      call();
      ADD_FAILURE() << name << ": no exception";
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  };
  expect_parameter([] { ref::loose_knot({0.0, 1.0}); }, "B");
  expect_parameter([] { ref::loose_knot({1.0, -1.0}); }, "T");
  expect_parameter([] { ref::loose_knot_point({1.0, 1.0}, NAN); }, "s");
  expect_parameter([] { ref::uniform_ply({1.0, 1.0, std::numbers::pi / 4, 0.0, 0.0}); }, "theta");
  expect_parameter([] { ref::uniform_ply({1.0, 1.0, 0.0, 0.0, 0.0}); }, "theta");
  expect_parameter([] { ref::uniform_ply({1.0, 0.0, 0.3, 0.0, 0.0}); }, "R");
  expect_parameter([] { ref::uniform_ply({1.0, 1.0, 0.3, INFINITY, 0.0}); }, "F");
  expect_parameter([] { ref::plectoneme({1.0, 1.0, 0.3, 0.1, 0.0}); }, "F");
  expect_parameter([] { ref::plectoneme({1.0, 1.0, 0.3, 0.0, 0.1}); }, "M");
}

}  // namespace
