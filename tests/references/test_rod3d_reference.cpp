// Tests of the 3-D rod references (references/src/rod3d.cpp, PHYSICS.md §7.1, ALGORITHMS.md §1.7).
//
// Oracle: tests/data/rod3d_reference.csv from tests/data/make_rod3d_table.py (mpmath, 40 digits,
// independent methods: findroot for beta_n L; numerical differentiation of the helix and body
// equilibrium for F, M and H). Tolerances in units of eps relative to max(|expected|, scale):
//  - beta_n L: bisection to adjacent doubles -> 2 eps (measured 0-1 eps);
//  - helix kappa, tau, F, M, H: a few trig evaluations and products -> 64 eps (measured <= 8 eps);
//  - the clamped-free mode shape and slope (mpmath in the textbook form, slope by mp.diff): see
//    mode_tolerance;
//  - special Cosserat helix (lambda, advance, radius, axial force and moment, H, position and frame
//    at s = 1.3; the table solves the 3x3 body equilibrium by findroot and integrates r' = R v,
//    R' = R [u]x by odefun): a square root, a few products and one Rodrigues rotation -> 64 eps
//    (measured: see the summary line).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::Vec3;
using rodvv::testing::in_epsilons;
using rodvv::testing::kEpsilon;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "quantity,index,B,C,radius,pitch_angle,twisting_moment,GA,EA,u0,u1,u2,s,value";
constexpr std::size_t kValue = 13;
// Mode shapes (n = 1, 2, 3, 7): the arguments b x carry b x eps (b = beta_n L, up to 20.5), which the sines and
// cosines pass on as absolute errors of that size, times the slope's factor b: gated at 2 b^2 eps (7 eps at n = 1,
// 840 eps at n = 7; measured: see the summary line).
double mode_tolerance(std::size_t n) {
  const double b = ref::cantilever_beta_l(n);
  return 2.0 * b * b;
}

ref::SpecialCosseratHelix cosserat_rod(const std::vector<std::string>& row) {
  ref::SpecialCosseratHelix rod;
  rod.B = parse_table_number(row[2]);
  rod.C = parse_table_number(row[3]);
  rod.GA = parse_table_number(row[7]);
  rod.EA = parse_table_number(row[8]);
  rod.u = Vec3(parse_table_number(row[9]), parse_table_number(row[10]), parse_table_number(row[11]));
  return rod;
}

double cosserat_quantity(const std::vector<std::string>& row) {
  const ref::SpecialCosseratHelix rod = cosserat_rod(row);
  const auto sol = ref::special_cosserat_helix(rod);
  const std::string& name = row[0];
  if (name == "cosserat_lambda") return sol.lambda;
  if (name == "cosserat_advance") return sol.advance;
  if (name == "cosserat_radius") return sol.radius;
  if (name == "cosserat_axial_force") return sol.axial_force;
  if (name == "cosserat_axial_moment") return sol.axial_moment;
  if (name == "cosserat_H") return sol.H;
  const auto point = ref::special_cosserat_helix_point(rod, parse_table_number(row[12]));
  const int index = std::stoi(row[1]);
  if (name == "cosserat_position") return point.position[index];
  if (name == "cosserat_frame") return point.frame(index / 3, index % 3);
  ADD_FAILURE() << "unknown quantity " << name;
  return 0.0;
}

double helix_quantity(const ref::AxialWrenchHelixSolution& sol, const std::string& name) {
  if (name == "helix_kappa") return sol.kappa;
  if (name == "helix_tau") return sol.tau;
  if (name == "helix_axial_force") return sol.axial_force;
  if (name == "helix_axial_moment") return sol.axial_moment;
  if (name == "helix_H") return sol.H;
  ADD_FAILURE() << "unknown quantity " << name;
  return 0.0;
}

// Compares every table row, the computed value scaled by (1 + relative_perturbation) (0 for the
// real test), and returns the worst errors in eps and the number of rows above the tolerance.
struct TableCheck {
  double worst_beta = 0.0, worst_helix = 0.0, worst_cosserat = 0.0, worst_mode = 0.0;
  int failures = 0;
  int rows = 0;
};

TableCheck check_table(double relative_perturbation) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("rod3d_reference.csv", kHeader)) {
    ++check.rows;
    const double expected = parse_table_number(row[kValue]);
    if (row[0] == "beta_l") {
      const double actual =
          ref::cantilever_beta_l(static_cast<std::size_t>(std::stoi(row[1]))) * (1.0 + relative_perturbation);
      const double error = in_epsilons(actual - expected, expected);
      check.worst_beta = std::max(check.worst_beta, error);
      if (error > 2.0) ++check.failures;
    } else if (row[0] == "mode_shape" || row[0] == "mode_slope") {
      const auto n = static_cast<std::size_t>(std::stoi(row[1]));
      const auto point = ref::cantilever_mode_shape(n, parse_table_number(row[12]));
      const double actual = (row[0] == "mode_shape" ? point.value : point.slope) * (1.0 + relative_perturbation);
      const double error = in_epsilons(actual - expected, expected);
      check.worst_mode = std::max(check.worst_mode, error);
      if (error > mode_tolerance(n)) ++check.failures;
    } else if (row[0].rfind("cosserat_", 0) == 0) {
      const double actual = cosserat_quantity(row) * (1.0 + relative_perturbation);
      const double error = in_epsilons(actual - expected, expected);
      check.worst_cosserat = std::max(check.worst_cosserat, error);
      if (error > 64.0) ++check.failures;
    } else {
      ref::AxialWrenchHelix helix{parse_table_number(row[2]), parse_table_number(row[3]), parse_table_number(row[4]),
                                  parse_table_number(row[5]), parse_table_number(row[6])};
      const double actual = helix_quantity(ref::axial_wrench_helix(helix), row[0]) * (1.0 + relative_perturbation);
      const double error = in_epsilons(actual - expected, expected);
      check.worst_helix = std::max(check.worst_helix, error);
      if (error > 64.0) ++check.failures;
    }
  }
  return check;
}

TEST(Rod3dReference, MatchesMpmathTable) {
  const TableCheck check = check_table(0.0);
  EXPECT_EQ(check.rows, 112);
  EXPECT_EQ(check.failures, 0);
  std::cout << "[ summary  ] beta_n L max " << check.worst_beta << " eps, helix max " << check.worst_helix
            << " eps, special Cosserat helix max " << check.worst_cosserat << " eps, mode shapes max "
            << check.worst_mode << " eps\n";
}

// The clamp's conditions (phi(0) = phi'(0) = 0, not in the table: a relative perturbation of 0 stays 0) and the
// free end's phi''(1) = 0 by a one-sided difference of the slope (step 1e-4: truncation ~1e-8 b^3 phi'(1)).
TEST(Rod3dReference, ModeShapesMeetTheCantileverEndConditions) {
  for (std::size_t n : {1, 2, 3, 7}) {
    const double b = ref::cantilever_beta_l(n);
    const auto clamp = ref::cantilever_mode_shape(n, 0.0);
    EXPECT_LE(std::abs(clamp.value), 8.0 * kEpsilon) << n;
    EXPECT_LE(std::abs(clamp.slope), 8.0 * b * b * kEpsilon) << n;
    EXPECT_EQ(ref::cantilever_mode_shape(n, 1.0).value, 1.0) << n;
    const double step = 1e-4;
    const double s0 = ref::cantilever_mode_shape(n, 1.0).slope, s1 = ref::cantilever_mode_shape(n, 1.0 - step).slope,
                 s2 = ref::cantilever_mode_shape(n, 1.0 - 2.0 * step).slope;
    const double curvature = (3.0 * s0 - 4.0 * s1 + s2) / (2.0 * step);  // one-sided, O(step^2)
    EXPECT_LE(std::abs(curvature), 1e-6 * b * b * std::abs(s0)) << n;
  }
  EXPECT_THROW(ref::cantilever_mode_shape(0, 0.5), rodvv::InputError);
  EXPECT_THROW(ref::cantilever_mode_shape(51, 0.5), rodvv::InputError);
  EXPECT_THROW(ref::cantilever_mode_shape(1, 1.01), rodvv::InputError);
  EXPECT_THROW(ref::cantilever_mode_shape(1, std::nan("")), rodvv::InputError);
}

TEST(Rod3dReference, PerturbedInputTurnsTableRed) {
  // 1e-9 relative (e.g. a perturbed lambda): >= 5600 eps even on the smallest tabulated value
  // (1.2e-3, measured against the absolute floor 1), far above all tolerances: every row must fail.
  const TableCheck check = check_table(1e-9);
  EXPECT_EQ(check.failures, check.rows);
}

TEST(Rod3dReference, HelixPointIsAnEquilibriumWithAxialWrench) {
  const ref::AxialWrenchHelix helix{1.3, 0.9, 0.7, 0.6, 0.37};
  const auto sol = ref::axial_wrench_helix(helix);
  for (double s : {0.0, 0.4, 2.5, 11.0}) {
    const auto point = ref::axial_wrench_helix_point(helix, s);
    // frame is a rotation, n0 = r' (central difference, step 1e-5: error ~1e-10)
    EXPECT_LE((point.frame.transpose() * point.frame - rodvv::Mat3::Identity()).norm(), 8 * kEpsilon);
    const Vec3 dr = (ref::axial_wrench_helix_point(helix, s + 1e-5).position -
                     ref::axial_wrench_helix_point(helix, s - 1e-5).position) / 2e-5;
    EXPECT_LE((dr - point.frame.col(0)).norm(), 1e-9);
    // pure axial wrench: m + (r - r_axis) x n = M e_z (a few products: 16 eps of |M| + |r||n|)
    const Vec3 arm(point.position.x(), point.position.y(), 0.0);
    const Vec3 wrench = point.moment + arm.cross(point.force);
    EXPECT_LE((wrench - sol.axial_moment * Vec3::UnitZ()).norm(), 16 * kEpsilon * (1 + std::abs(sol.axial_moment)));
    // body strains: the frame rotates with u = (tau, kappa, 0) -> dR/ds = R [u]x
    const auto ahead = ref::axial_wrench_helix_point(helix, s + 1e-5), behind = ref::axial_wrench_helix_point(helix, s - 1e-5);
    const rodvv::Mat3 W = point.frame.transpose() * (ahead.frame - behind.frame) / 2e-5;
    EXPECT_NEAR(W(2, 1), sol.tau, 1e-9);
    EXPECT_NEAR(W(0, 2), sol.kappa, 1e-9);
    EXPECT_NEAR(W(1, 0), 0.0, 1e-9);
  }
}

TEST(Rod3dReference, FrequencyAndSelfWeightFormulas) {
  const double beta1 = ref::cantilever_beta_l(1);
  EXPECT_TRUE(rodvv::testing::is_close(ref::cantilever_frequency(1, 2.0, 0.5, 1.5),
                                       beta1 * beta1 * std::sqrt(2.0 / (0.5 * std::pow(1.5, 4))), 4 * kEpsilon, 0.0));
  EXPECT_TRUE(rodvv::testing::is_close(ref::self_weight_tip_deflection(3.0, 2.0, 4.0), 3.0 * 16.0 / 32.0, 2 * kEpsilon, 0.0));
}

TEST(Rod3dReference, RollUpClosesIntoACircle) {
  ref::EndMomentRollUp rod;
  rod.L = 2.0;
  rod.EI = 1.5;
  rod.M = 2 * std::numbers::pi * rod.EI / rod.L;
  rod.root_position = Vec3(1, 2, 3);
  rod.tangent = Vec3(0, 1, 0);
  rod.axis = Vec3(1, 0, 0);
  const auto end = ref::end_moment_roll_up_point(rod, rod.L);
  EXPECT_LE((end.position - rod.root_position).norm(), 16 * kEpsilon * rod.L);
  EXPECT_LE((end.tangent - rod.tangent).norm(), 16 * kEpsilon);
  const auto half = ref::end_moment_roll_up_point(rod, rod.L / 2);  // diametrically opposite
  EXPECT_NEAR((half.position - rod.root_position).norm(), 2 * rod.EI / rod.M, 16 * kEpsilon);
  // bends towards axis x tangent = (0, 0, 1)
  EXPECT_GT(half.position.z(), rod.root_position.z());
  EXPECT_DOUBLE_EQ(ref::end_moment_roll_up_invariant(rod), rod.M * rod.M / (2 * rod.EI));
  rod.M = 1e-9;  // the small-angle branch is continuous with the trig branch
  const auto straight = ref::end_moment_roll_up_point(rod, rod.L);
  EXPECT_NEAR(straight.position.y(), 2.0 + rod.L, 1e-15);
}

TEST(Rod3dReference, SpecialCosseratHelixPhysicsExample) {
  // PHYSICS.md §7.1 (its u = (0.8, 0, 0.5) with d3 along the rod is (0.5, 0.8, 0) here), printed to
  // 14 (lambda, truncated: the table has -0.1498316286229814) and 15 significant digits: 2e-14 and
  // 1e-15 absolute.
  ref::SpecialCosseratHelix rod;
  rod.B = 1.0;
  rod.C = 0.7;
  rod.GA = 50.0;
  rod.EA = 200.0;
  rod.u = Vec3(0.5, 0.8, 0.0);
  const auto sol = ref::special_cosserat_helix(rod);
  EXPECT_NEAR(sol.lambda, -0.14983162862297, 2e-14);
  EXPECT_NEAR(sol.radius, 0.899886505361503, 1e-15);
  EXPECT_NEAR(sol.advance, 0.527767502020969, 1e-15);
  // the inextensible, unshearable limit: lambda -> (C - B) u0 and the advance -> u0/|u| (v -> e0)
  rod.GA = rod.EA = 1e12;
  const auto rigid = ref::special_cosserat_helix(rod);
  EXPECT_NEAR(rigid.lambda, (rod.C - rod.B) * rod.u[0], 1e-11);
  EXPECT_NEAR(rigid.advance, rod.u[0] / rod.u.norm(), 1e-11);
}

TEST(Rod3dReference, SpecialCosseratHelixPointIsAnEquilibrium) {
  ref::SpecialCosseratHelix rod;
  rod.B = 2.0;
  rod.C = 1.3;
  rod.GA = 20.0;
  rod.EA = 80.0;
  rod.u = Vec3(-0.7, 0.4, 0.9);
  rod.root_position = Vec3(0.3, -1.0, 2.0);
  rod.root_frame = Eigen::AngleAxisd(0.8, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const auto sol = ref::special_cosserat_helix(rod);
  const double h = 1e-5;  // central differences: truncation ~h^2 |u|^3 ~ 1e-10, round-off ~eps/h ~ 1e-11
  for (double s : {0.0, 0.7, 3.1, 12.0}) {
    const auto p = ref::special_cosserat_helix_point(rod, s);
    const auto ahead = ref::special_cosserat_helix_point(rod, s + h), behind = ref::special_cosserat_helix_point(rod, s - h);
    EXPECT_LE((p.frame.transpose() * p.frame - rodvv::Mat3::Identity()).norm(), 16 * kEpsilon);
    // r' = R v and R' = R [u]x
    EXPECT_LE(((ahead.position - behind.position) / (2 * h) - p.frame * sol.strain_v).norm(), 1e-9) << s;
    const rodvv::Mat3 W = p.frame.transpose() * (ahead.frame - behind.frame) / (2 * h);
    EXPECT_LE((Vec3(W(2, 1), W(0, 2), W(1, 0)) - rod.u).norm(), 1e-9) << s;
    // n = R S (v - e0) and m = R K u (constitutive), n constant along the axis: n' = 0
    const Vec3 shear = sol.strain_v - Vec3::UnitX();
    EXPECT_LE((p.frame.transpose() * p.force - Vec3(rod.EA * shear[0], rod.GA * shear[1], rod.GA * shear[2])).norm(),
              64 * kEpsilon) << s;
    EXPECT_LE((p.force - sol.axial_force * sol.axis).norm(), 16 * kEpsilon) << s;
    // m' + r' x n = 0 (moment balance), by central differences
    const Vec3 dm = (ahead.moment - behind.moment) / (2 * h);
    EXPECT_LE((dm + (p.frame * sol.strain_v).cross(p.force)).norm(), 1e-9) << s;
    // the helix: distance from the axis = radius, advance along the axis = s * advance
    const Vec3 d = p.position - sol.axis_point;
    EXPECT_NEAR((d - d.dot(sol.axis) * sol.axis).norm(), sol.radius, 64 * kEpsilon * (1 + s)) << s;
    EXPECT_NEAR((p.position - rod.root_position).dot(sol.axis), s * sol.advance, 64 * kEpsilon * (1 + s)) << s;
    // pure axial wrench: m + (r - r_axis) x n = M a
    EXPECT_LE((p.moment + d.cross(p.force) - sol.axial_moment * sol.axis).norm(), 64 * kEpsilon * (1 + s)) << s;
  }
  // H = n.v + m.u - W_bend - W_shear = lambda u0 + W_bend + W_shear (PHYSICS.md §1.1)
  EXPECT_NEAR(sol.H, sol.lambda * rod.u[0] + sol.bending_energy + sol.shear_energy, 16 * kEpsilon);
}

TEST(Rod3dReference, SpecialCosseratHelixBadInputNamesTheParameter) {
  auto expect_parameter = [](const ref::SpecialCosseratHelix& rod, const std::string& name) {
    try {
      ref::special_cosserat_helix(rod);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  };
  const ref::SpecialCosseratHelix good;
  EXPECT_NO_THROW(ref::special_cosserat_helix(good));
  auto bad = good;
  bad.B = 0.0;
  expect_parameter(bad, "B");
  bad = good;
  bad.C = -1.0;
  expect_parameter(bad, "C");
  bad = good;
  bad.EA = 0.0;
  expect_parameter(bad, "EA");
  bad = good;
  bad.GA = std::nan("");
  expect_parameter(bad, "GA");
  bad = good;
  bad.u = Vec3::Zero();  // the axis u/|u| is undefined
  expect_parameter(bad, "u");
  bad = good;
  bad.u = Vec3(0.7, 0.0, 0.0);  // pure twist: straight rod, lambda undefined
  expect_parameter(bad, "u");
  bad = good;
  bad.u = Vec3(std::nan(""), 1.0, 0.0);
  expect_parameter(bad, "u");
  // no real root: 1 - 4 u0^2 (1/EA - 1/GA)(B - C) = 1 - 16 (9.9)(0.9) < 0
  bad = ref::SpecialCosseratHelix{1.0, 0.1, 10.0, 0.1, Vec3(2.0, 1.0, 0.0), Vec3::Zero(), rodvv::Mat3::Identity()};
  expect_parameter(bad, "u");
  bad = good;
  bad.root_frame(0, 1) = 1e-3;
  expect_parameter(bad, "root_frame");
  try {
    ref::special_cosserat_helix_point(good, std::nan(""));
    ADD_FAILURE() << "no InputError for s";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "s");
  }
}

TEST(Rod3dReference, BadInputNamesTheParameter) {
  auto expect_parameter = [](auto&& call, const std::string& name) {
    try {
      call();
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  };
  expect_parameter([] { ref::axial_wrench_helix({1.0, 1.0, 1.0, 1.6, 0.0}); }, "pitch_angle");
  expect_parameter([] { ref::axial_wrench_helix({0.0, 1.0, 1.0, 0.5, 0.0}); }, "B");
  expect_parameter([] { ref::axial_wrench_helix({1.0, 1.0, -1.0, 0.5, 0.0}); }, "radius");
  expect_parameter([] { ref::axial_wrench_helix({1.0, 1.0, 1.0, 0.5, std::nan("")}); }, "twisting_moment");
  expect_parameter([] { ref::cantilever_beta_l(0); }, "n");
  expect_parameter([] { ref::cantilever_frequency(1, 1.0, 0.0, 1.0); }, "line_density");
  expect_parameter([] { ref::self_weight_tip_deflection(1.0, 1.0, -1.0); }, "EI");
  ref::EndMomentRollUp rod;
  rod.axis = Vec3(1, 0, 0);  // parallel to the tangent
  expect_parameter([&] { ref::end_moment_roll_up_point(rod, 0.5); }, "axis");
}

}  // namespace
