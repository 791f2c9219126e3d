// The 3-D Noether invariant (invariants/noether3d, PHYSICS.md §1.1): the compact and flattened
// forms agree to round-off on arbitrary data, H equals the closed form on the helix under an axial
// wrench (with natural twist: the m.u_hat term is needed) at every station, and bad input is named.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::Mat3;
using rodvv::SpatialRodSolution;
using rodvv::Vec3;
using rodvv::testing::kEpsilon;
namespace inv = rodvv::invariants;
namespace ref = rodvv::references;

SpatialRodSolution helix_solution(const ref::AxialWrenchHelix& helix, std::size_t stations) {
  const auto sol = ref::axial_wrench_helix(helix);
  SpatialRodSolution out;
  out.length = 5.0;
  for (std::size_t i = 0; i < stations; ++i) {
    const double s = out.length * (static_cast<double>(i) + 0.5) / static_cast<double>(stations);
    const auto point = ref::axial_wrench_helix_point(helix, s);
    out.s.push_back(s);
    out.position.push_back(point.position);
    out.frame.push_back(point.frame);
    out.strain_u.push_back(Vec3(sol.tau, sol.kappa, 0.0));
    out.strain_v.push_back(Vec3::UnitX());
    out.stiffness.push_back(Vec3(helix.C, helix.B, helix.B));
    out.natural_strain.push_back(Vec3(sol.natural_twist, 0.0, 0.0));
    out.force_n.push_back(point.force);
    out.moment_m.push_back(point.moment);
    out.potential.push_back(0.0);
  }
  return out;
}

TEST(Noether3d, HelixUnderAxialWrenchEqualsClosedFormAtEveryStation) {
  const ref::AxialWrenchHelix helix{1.3, 0.9, 0.7, 0.6, 0.37};
  const auto solution = helix_solution(helix, 40);
  const double exact = ref::axial_wrench_helix(helix).H;
  const auto compact = inv::noether3d_compact(solution);
  const auto flattened = inv::noether3d_flattened(solution);
  // Each H is a sum of ~10 O(1) products of closed-form values: 64 eps absolute.
  for (std::size_t i = 0; i < compact.size(); ++i) {
    EXPECT_NEAR(compact[i], exact, 64 * kEpsilon) << i;
    EXPECT_NEAR(flattened[i], exact, 64 * kEpsilon) << i;
  }
  const auto summary = inv::noether3d_summary(solution);
  EXPECT_LE(summary.spread, 64 * kEpsilon);
  EXPECT_LE(summary.form_difference, 64 * kEpsilon);
}

TEST(Noether3d, NaturalTwistTermIsNeeded) {
  // Teeth: the naive W + n.v - V (without m.u_hat) misses M_t u_hat0 on a rod with natural twist.
  const ref::AxialWrenchHelix helix{1.3, 0.9, 0.7, 0.6, 0.37};
  const auto sol = ref::axial_wrench_helix(helix);
  const auto solution = helix_solution(helix, 4);
  const double h = inv::noether3d_compact(solution)[0];
  const Vec3 strain = solution.strain_u[0] - solution.natural_strain[0];
  const double naive = 0.5 * strain.dot(solution.stiffness[0].cwiseProduct(strain)) +
                       (solution.frame[0].transpose() * solution.force_n[0]).x();
  EXPECT_NEAR(h - naive, helix.twisting_moment * sol.natural_twist, 64 * kEpsilon);
  EXPECT_GT(std::abs(h - naive), 0.05);  // M_t u_hat0 = 0.094
}

TEST(Noether3d, CompactAndFlattenedFormsAgreeOnArbitraryData) {
  // Random rotations (including ones near 180 degrees, where the quaternion's w ~ 0), strains,
  // forces, potentials and shear energies: the two forms differ by round-off only. Each H is a sum
  // of O(10) products of O(1..10) numbers: 256 eps of the term scale.
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> dist(-3.0, 3.0);
  auto random_vec = [&] { return Vec3(dist(gen), dist(gen), dist(gen)); };
  SpatialRodSolution solution;
  for (int i = 0; i < 200; ++i) {
    const double angle = i % 10 == 0 ? std::numbers::pi - 1e-9 : dist(gen);
    solution.s.push_back(0.01 * i);
    solution.position.push_back(random_vec());
    solution.frame.push_back(Eigen::AngleAxisd(angle, random_vec().normalized()).toRotationMatrix());
    solution.strain_u.push_back(random_vec());
    solution.strain_v.push_back(i % 2 ? Vec3::UnitX() : Vec3(1.0, 0.01, -0.02));
    solution.stiffness.push_back(random_vec().cwiseAbs() + Vec3::Constant(0.1));
    solution.natural_strain.push_back(random_vec());
    solution.force_n.push_back(random_vec());
    // the constitutive moment (the flattened form takes dW/du, the compact form the stored m)
    solution.moment_m.push_back(solution.frame.back() *
                                solution.stiffness.back().cwiseProduct(solution.strain_u.back() - solution.natural_strain.back()));
    solution.potential.push_back(dist(gen));
    solution.shear_energy.push_back(std::abs(dist(gen)));
  }
  const auto summary = inv::noether3d_summary(solution);
  EXPECT_LE(summary.form_difference, 256 * kEpsilon * summary.scale);
  EXPECT_GT(summary.spread, 1.0);  // arbitrary data: H is not constant (the forms still agree)
  // Teeth: a moment that is not the constitutive one separates the forms.
  solution.moment_m[3] *= 1.0 + 1e-9;
  EXPECT_GT(inv::noether3d_summary(solution).form_difference, 1e3 * 256 * kEpsilon * summary.scale);
}

TEST(Noether3d, BadInputNamesTheField) {
  const ref::AxialWrenchHelix helix{1.3, 0.9, 0.7, 0.6, 0.37};
  auto expect_field = [](const SpatialRodSolution& sol, const std::string& field) {
    try {
      inv::noether3d_compact(sol);
      ADD_FAILURE() << "no InputError for " << field;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), field);
    }
  };
  expect_field(SpatialRodSolution{}, "solution.s");
  auto bad = helix_solution(helix, 3);
  bad.moment_m.pop_back();
  expect_field(bad, "solution.moment_m");
  bad = helix_solution(helix, 3);
  bad.frame[1](0, 0) += 1e-3;
  expect_field(bad, "solution.frame");
  bad = helix_solution(helix, 3);
  bad.stiffness[2][1] = 0.0;
  expect_field(bad, "solution.stiffness");
  bad = helix_solution(helix, 3);
  bad.force_n[0][2] = std::nan("");
  expect_field(bad, "solution.force_n");
}

}  // namespace
