// The 3-D Noether invariant (invariants/noether3d, PHYSICS.md §1.1): the compact and flattened
// forms agree to round-off on arbitrary data, H equals the closed form on the helix under an axial
// wrench (with natural twist: the m.u_hat term is needed) at every station, H with the shear and
// extension energy equals the closed form on the special Cosserat helix at every station, and bad
// input is named.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <utility>

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

// The special Cosserat helix (references/rod3d, PHYSICS.md §7.1) sampled at stations: strains
// u, v (v != e0: shear and extension), W_shear = (v - e0).S(v - e0)/2 in the shear_energy field.
SpatialRodSolution cosserat_solution(const ref::SpecialCosseratHelix& rod, std::size_t stations) {
  const auto sol = ref::special_cosserat_helix(rod);
  SpatialRodSolution out;
  out.length = 7.0;
  for (std::size_t i = 0; i < stations; ++i) {
    const double s = out.length * static_cast<double>(i) / static_cast<double>(stations - 1);
    const auto point = ref::special_cosserat_helix_point(rod, s);
    out.s.push_back(s);
    out.position.push_back(point.position);
    out.frame.push_back(point.frame);
    out.strain_u.push_back(rod.u);
    out.strain_v.push_back(sol.strain_v);
    out.stiffness.push_back(Vec3(rod.C, rod.B, rod.B));
    out.natural_strain.push_back(Vec3::Zero());
    out.force_n.push_back(point.force);
    out.moment_m.push_back(point.moment);
    out.potential.push_back(0.0);
    out.shear_energy.push_back(sol.shear_energy);
  }
  return out;
}

ref::SpecialCosseratHelix cosserat_rod() {
  ref::SpecialCosseratHelix rod;
  rod.B = 2.0;
  rod.C = 1.3;
  rod.GA = 20.0;
  rod.EA = 80.0;
  rod.u = Vec3(-0.7, 0.4, 0.9);
  rod.root_position = Vec3(0.3, -1.0, 2.0);
  rod.root_frame = Eigen::AngleAxisd(0.8, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  return rod;
}

TEST(Noether3d, SpecialCosseratHelixWithShearEqualsClosedFormAtEveryStation) {
  // H = n.v + m.u - W_bend - W_shear, each term O(1) and formed from closed-form fields (a few eps
  // each): 64 eps absolute for H and for the compact - flattened difference (the flattened form's
  // chart term n.(r' - R(p) v) vanishes, and dL/dr' = n = R S (v - e0) is the shear force).
  // The closed form is itself checked against the mpmath table (test_rod3d_reference); here H from
  // the fields is also compared with the table's cosserat_H rows (40 digits, independent method).
  const std::pair<ref::SpecialCosseratHelix, double> cases[] = {
      {cosserat_rod(), 0.956196136147998583438004},
      {ref::SpecialCosseratHelix{1.0, 0.7, 50.0, 200.0, Vec3(0.5, 0.8, 0.0), Vec3::Zero(), Mat3::Identity()},
       0.3327418935449834067904957}};
  for (const auto& [rod, table] : cases) {
    const auto solution = cosserat_solution(rod, 50);
    const double exact = ref::special_cosserat_helix(rod).H;
    EXPECT_NEAR(exact, table, 16 * kEpsilon);
    EXPECT_NEAR(inv::noether3d_summary(solution).mean, table, 64 * kEpsilon);
    const auto compact = inv::noether3d_compact(solution);
    const auto flattened = inv::noether3d_flattened(solution);
    for (std::size_t i = 0; i < compact.size(); ++i) {
      EXPECT_NEAR(compact[i], exact, 64 * kEpsilon) << i;
      EXPECT_NEAR(flattened[i], exact, 64 * kEpsilon) << i;
    }
    const auto summary = inv::noether3d_summary(solution);
    EXPECT_LE(summary.spread, 64 * kEpsilon);
    EXPECT_LE(summary.form_difference, 64 * kEpsilon);
    std::cout << "[ summary  ] special Cosserat helix: |mean H - closed form| = "
              << std::abs(summary.mean - exact) / kEpsilon << " eps, spread " << summary.spread / kEpsilon
              << " eps, forms " << summary.form_difference / kEpsilon << " eps\n";
  }
}

TEST(Noether3d, SpecialCosseratHelixPerturbationsTurnRed) {
  const auto rod = cosserat_rod();
  const auto sol = ref::special_cosserat_helix(rod);
  const double exact = sol.H;
  // The shear energy must enter H: without it H is off by W_shear (here ~5e-3 >> 64 eps).
  auto no_shear = cosserat_solution(rod, 10);
  no_shear.shear_energy.clear();
  EXPECT_GT(std::abs(inv::noether3d_summary(no_shear).mean - exact), 1e10 * 64 * kEpsilon * sol.shear_energy);
  // A force lambda off by 1e-6 (relative): H moves by ~1e-6 |n.v| >> 64 eps.
  auto wrong_lambda = cosserat_solution(rod, 10);
  for (auto& n : wrong_lambda.force_n) n *= 1.0 + 1e-6;
  EXPECT_GT(std::abs(inv::noether3d_summary(wrong_lambda).mean - exact), 1e3 * 64 * kEpsilon);
  // A bending stiffness off by 1e-6 in the solution (m no longer K u): H and the two forms separate.
  auto wrong_stiffness = cosserat_solution(rod, 10);
  for (auto& k : wrong_stiffness.stiffness) k[1] *= 1.0 + 1e-6;
  const auto summary = inv::noether3d_summary(wrong_stiffness);
  EXPECT_GT(std::abs(summary.mean - exact), 1e3 * 64 * kEpsilon);
  EXPECT_GT(summary.form_difference, 1e3 * 64 * kEpsilon);
  // The force of a slightly different helix (lambda 1e-6 off) at every other station: no longer
  // one equilibrium, H varies along s by ~1e-6 |n.v| / 2 ~ 2e-7 >> 64 eps.
  auto mixed = cosserat_solution(rod, 10);
  for (std::size_t i = 0; i < mixed.s.size(); i += 2) mixed.force_n[i] *= 1.0 + 1e-6;
  EXPECT_GT(inv::noether3d_summary(mixed).spread, 1e3 * 64 * kEpsilon);
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
