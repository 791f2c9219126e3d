// Tests of the 3-D rod references (references/src/rod3d.cpp, PHYSICS.md §7.1, ALGORITHMS.md §1.7).
//
// Oracle: tests/data/rod3d_reference.csv from tests/data/make_rod3d_table.py (mpmath, 40 digits,
// independent methods: findroot for beta_n L; numerical differentiation of the helix and body
// equilibrium for F, M and H). Tolerances in units of eps relative to max(|expected|, scale):
//  - beta_n L: bisection to adjacent doubles -> 2 eps (measured 0-1 eps);
//  - helix kappa, tau, F, M, H: a few trig evaluations and products -> 64 eps (measured <= 8 eps).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

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

constexpr const char* kHeader = "quantity,index,B,C,radius,pitch_angle,twisting_moment,value";

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
  double worst_beta = 0.0, worst_helix = 0.0;
  int failures = 0;
  int rows = 0;
};

TableCheck check_table(double relative_perturbation) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("rod3d_reference.csv", kHeader)) {
    ++check.rows;
    const double expected = parse_table_number(row[7]);
    if (row[0] == "beta_l") {
      const double actual =
          ref::cantilever_beta_l(static_cast<std::size_t>(std::stoi(row[1]))) * (1.0 + relative_perturbation);
      const double error = in_epsilons(actual - expected, expected);
      check.worst_beta = std::max(check.worst_beta, error);
      if (error > 2.0) ++check.failures;
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
  EXPECT_EQ(check.rows, 26);
  EXPECT_EQ(check.failures, 0);
  std::cout << "[ summary  ] beta_n L max " << check.worst_beta << " eps, helix max " << check.worst_helix
            << " eps\n";
}

TEST(Rod3dReference, PerturbedInputTurnsTableRed) {
  // 1e-9 relative: >= 5600 eps even on the smallest tabulated value (1.2e-3, measured against the
  // absolute floor 1), far above both tolerances: every row must fail.
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
