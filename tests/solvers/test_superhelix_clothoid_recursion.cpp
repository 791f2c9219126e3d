// Super-clothoid dynamics, O(N) path (clothoid_dynamics.hpp): the articulated-body recursion adapted
// to nodal strains shared by neighbouring elements and to the block-tridiagonal implicit stiffness
// solves the same semi-implicit Euler step as the dense LDL^T path, to the 1e-12, at single
// steps from random states and at every step of a trajectory; a curl at rest stays exactly at rest.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/clothoid_dynamics.hpp"
#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "rodvv/testing/superhelix_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::superhelix::random_vector;

// The common loaded model, with the root also moved off the origin.
sh::RodModel loaded_model(std::size_t n) {
  sh::RodModel model = rodvv::testing::superhelix::loaded_model(n);
  model.root_position = Vec3(0.1, -0.2, 0.3);
  return model;
}

double relative_difference(const VecX& dense, const VecX& fast) {
  return (dense - fast).lpNorm<Eigen::Infinity>() / dense.lpNorm<Eigen::Infinity>();
}

TEST(SuperClothoidRecursion, RecursiveStepEqualsDenseStep) {
  // Same linear system, two eliminations (LDL^T of the assembled M + D vs the tip-to-root Schur
  // complements): they differ by round-off times the conditioning of M + D; the gate is
  // 1e-12 relative to |dv| (measured: summary line). Both share zeta, so its finite-difference
  // error does not enter the comparison.
  double worst = 0.0;
  for (std::size_t n : {1u, 2u, 5u, 12u}) {
    const sh::RodModel model = loaded_model(n);
    const std::size_t dofs = sh::clothoid_dof_count(model);
    const sh::DynamicState state{random_vector(dofs, 3.0, 41), random_vector(dofs, 2.0, 42), 0.0};
    for (double h : {1e-3, 1e-2}) {
      const VecX dense = sh::clothoid_velocity_change(model, state, h, sh::DynamicsPath::Dense);
      const VecX fast = sh::clothoid_velocity_change(model, state, h, sh::DynamicsPath::Recursive);
      const double relative = relative_difference(dense, fast);
      worst = std::max(worst, relative);
      EXPECT_LE(relative, 1e-12) << "N = " << n << " h = " << h;
    }
  }
  std::cout << "[ summary  ] clothoid: max relative |dv_dense - dv_recursive| = " << worst << "\n";
  // Teeth: the stiffness coupling between nodes matters (a step with gamma changed is different),
  // and so do the velocity terms.
  const sh::RodModel model = loaded_model(5);
  const sh::DynamicState state{random_vector(18, 3.0, 41), random_vector(18, 2.0, 42), 0.0};
  sh::RodModel stiffer = model;
  stiffer.rayleigh_stiffness *= 2.0;
  const VecX dense = sh::clothoid_velocity_change(model, state, 1e-2, sh::DynamicsPath::Dense);
  EXPECT_GT(relative_difference(dense, sh::clothoid_velocity_change(stiffer, state, 1e-2, sh::DynamicsPath::Recursive)),
            1e-6);
  sh::DynamicState resting = state;
  resting.qdot.setZero();
  EXPECT_GT(relative_difference(dense, sh::clothoid_velocity_change(model, resting, 1e-2, sh::DynamicsPath::Recursive)),
            1e-6);
}

TEST(SuperClothoidRecursion, PathsAgreeAlongTrajectory) {
  // A heavy curled rod released from rest and integrated by the recursive path for 60 steps; at
  // every step the dense path, from the same state, gives the same dv (1e-12 relative).
  const sh::RodModel model = loaded_model(6);
  const std::size_t dofs = sh::clothoid_dof_count(model);
  sh::DynamicState state{random_vector(dofs, 2.0, 51), VecX::Zero(static_cast<Eigen::Index>(dofs)), 0.0};
  double worst = 0.0;
  for (int i = 0; i < 60; ++i) {
    const VecX dense = sh::clothoid_velocity_change(model, state, 2e-3, sh::DynamicsPath::Dense);
    const VecX fast = sh::clothoid_velocity_change(model, state, 2e-3, sh::DynamicsPath::Recursive);
    const double relative = relative_difference(dense, fast);
    worst = std::max(worst, relative);
    EXPECT_LE(relative, 1e-12) << "step " << i;
    state.qdot += fast;
    state.q += 2e-3 * state.qdot;
    state.time += 2e-3;
  }
  std::cout << "[ summary  ] clothoid trajectory: max relative |dv_dense - dv_recursive| = " << worst << "\n";
  EXPECT_GT(state.qdot.lpNorm<Eigen::Infinity>(), 1e-2);  // it moved
}

TEST(SuperClothoidRecursion, CurlAtRestStaysAtRest) {
  // q = q0, no gravity or end loads, qdot = 0: every term of the recursion is exactly 0.
  sh::RodModel model = loaded_model(7);
  model.gravity.setZero();
  model.end_force.setZero();
  model.end_moment.setZero();
  const std::size_t dofs = sh::clothoid_dof_count(model);
  sh::DynamicState state{sh::clothoid_natural_strain_vector(model), VecX::Zero(static_cast<Eigen::Index>(dofs)), 0.0};
  for (int i = 0; i < 10; ++i) state = sh::clothoid_step(model, state, 1e-2, sh::DynamicsPath::Recursive);
  EXPECT_EQ((state.q - sh::clothoid_natural_strain_vector(model)).lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_EQ(state.qdot.lpNorm<Eigen::Infinity>(), 0.0);
  // Teeth: an end moment moves it.
  model.end_moment = Vec3(0.0, 0.01, 0.0);
  state = sh::clothoid_step(model, state, 1e-2, sh::DynamicsPath::Recursive);
  EXPECT_GT(state.qdot.lpNorm<Eigen::Infinity>(), 1e-3);
}

TEST(SuperClothoidRecursion, BadInputNamesTheParameter) {
  sh::RodModel model = loaded_model(2);
  sh::DynamicState state{VecX::Zero(9), VecX::Zero(9), 0.0};
  try {
    sh::clothoid_step(model, state, -1.0, sh::DynamicsPath::Recursive);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "h");
  }
  state.q = VecX::Zero(6);
  try {
    sh::clothoid_step(model, state, 1e-3, sh::DynamicsPath::Recursive);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "state");
  }
  model.natural_strain_per_element = {Vec3::Zero(), Vec3::Zero()};
  state.q = VecX::Zero(9);
  try {
    sh::clothoid_step(model, state, 1e-3, sh::DynamicsPath::Recursive);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "natural_strain_per_element");
  }
}

}  // namespace

namespace {

TEST(SuperClothoidRecursion, AnalyticBiasMatchesFiniteDifference) {
  // zeta from the second-order series rates against a global central difference of the point
  // velocities J_g(q +- e qdot) qdot, e = cbrt(eps) / (L |qdot|): truncation and round-off both
  // ~ cbrt(eps)^2 ~ 4e-11 relative to the scale |zeta|_max + |qdot|^2 L; tolerance 1e-9 of that
  // scale (x25), as for the Super-Helix.
  const sh::RodModel model = loaded_model(4);
  const std::size_t dofs = sh::clothoid_dof_count(model);
  const VecX q = random_vector(dofs, 3.0, 61), qdot = random_vector(dofs, 2.0, 62);
  const sh::ClothoidKinematics kin(model, q);
  const auto zeta = sh::clothoid_bias_accelerations(model, kin, qdot);
  const double rate = qdot.lpNorm<Eigen::Infinity>();
  const double e = std::cbrt(rodvv::testing::kEpsilon) / (model.length * rate);
  const sh::ClothoidKinematics plus(model, q + e * qdot), minus(model, q - e * qdot);
  double scale = rate * rate * model.length;
  for (const auto& z : zeta) scale = std::max(scale, z.norm());
  double worst = 0.0;
  for (std::size_t g = 0; g < zeta.size(); ++g) {
    const auto& point = kin.points()[g];
    const Vec3 fd = (plus.position_jacobian(point.element, point.sigma) * qdot -
                     minus.position_jacobian(point.element, point.sigma) * qdot) /
                    (2.0 * e);
    worst = std::max(worst, (fd - zeta[g]).norm() / scale);
    EXPECT_LE((fd - zeta[g]).norm(), 1e-9 * scale) << g;
  }
  std::cout << "[ summary  ] clothoid: max |zeta_series - zeta_fd| / scale = " << worst << "\n";
  // Element level: the rates of one element against central differences of clothoid_element along
  // (adot, bdot) (step 1e-4: ~1e-8 truncation; tolerance 1e-6 on O(10) strains).
  const Vec3 a(1.1, -2.3, 0.8), b(-3.0, 4.5, 2.2), adot(0.4, 0.9, -1.2), bdot(2.0, -0.5, 0.7);
  const double ell = 0.8, t = 1e-4;
  const sh::ClothoidRates rates = sh::clothoid_element_rates(a, b, adot, bdot, ell);
  const auto pp = sh::clothoid_element(a + t * adot, b + t * bdot, ell),
             p0 = sh::clothoid_element(a, b, ell), pm = sh::clothoid_element(a - t * adot, b - t * bdot, ell);
  EXPECT_LE((rates.velocity - (pp.r - pm.r) / (2 * t)).norm(), 1e-6);
  EXPECT_LE((rates.bias - (pp.r - 2.0 * p0.r + pm.r) / (t * t)).norm(), 1e-4);  // 2nd difference: eps/t^2 ~ 2e-8
  const rodvv::Mat3 W = (pp.R - pm.R) / (2 * t) * p0.R.transpose();
  EXPECT_LE((rates.angular_velocity - Vec3(W(2, 1), W(0, 2), W(1, 0))).norm(), 1e-6);
  // Teeth: the rates are not the first-order terms alone.
  EXPECT_GT(rates.bias.norm(), 1e-2);
}

}  // namespace

namespace {

TEST(SuperClothoidRecursion, MovingRoot) {
  // (1) Both paths agree (1e-12 relative) at every step of a trajectory driven by a translating,
  // spinning-up root. (2) Equivalence principle: a root accelerating at a in gravity g == a fixed
  // root in gravity g - a, to the rounding of zeta + a - g vs zeta - (g - a) per step (200 steps x
  // 64 eps x max(|q|, 1), as for the Super-Helix).
  const sh::RodModel model = loaded_model(5);
  const std::size_t dofs = sh::clothoid_dof_count(model);
  const sh::RootMotion root = sh::uniformly_accelerated_root(model, Vec3(0.3, -0.2, 0.1), Vec3(1.0, 2.0, -0.5),
                                                             Vec3(0.3, -0.4, 1.0), 2.0, -3.0);
  sh::DynamicState state{random_vector(dofs, 2.0, 71), random_vector(dofs, 1.0, 72), 0.0};
  double worst = 0.0;
  for (int i = 0; i < 40; ++i) {
    const VecX dense = sh::clothoid_velocity_change(model, state, 1e-3, sh::DynamicsPath::Dense, root);
    const VecX fast = sh::clothoid_velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive, root);
    worst = std::max(worst, relative_difference(dense, fast));
    EXPECT_LE(relative_difference(dense, fast), 1e-12) << "step " << i;
    state.qdot += fast;
    state.q += 1e-3 * state.qdot;
    state.time += 1e-3;
  }
  std::cout << "[ summary  ] clothoid rotating root: max relative |dv_dense - dv_recursive| = " << worst << "\n";
  // Teeth: the root's motion is felt.
  EXPECT_GT(relative_difference(sh::clothoid_velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive, root),
                                sh::clothoid_velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive)),
            1e-3);

  const Vec3 a(1.5, -0.7, 3.0);
  const sh::RootMotion accelerating = sh::uniformly_accelerated_root(model, Vec3::Zero(), a);
  sh::RodModel equivalent = model;
  equivalent.gravity = model.gravity - a;
  sh::DynamicState s1{random_vector(dofs, 2.0, 73), random_vector(dofs, 1.0, 74), 0.0}, s2 = s1;
  const int steps = 200;
  double difference = 0.0;
  for (int i = 0; i < steps; ++i) {
    s1 = sh::clothoid_step(model, s1, 1e-3, sh::DynamicsPath::Recursive, accelerating);
    s2 = sh::clothoid_step(equivalent, s2, 1e-3, sh::DynamicsPath::Recursive);
    difference = std::max(difference, (s1.q - s2.q).lpNorm<Eigen::Infinity>());
  }
  std::cout << "[ summary  ] clothoid equivalence principle, max |q_moving - q_equivalent| = " << difference << "\n";
  EXPECT_LE(difference, steps * 64 * rodvv::testing::kEpsilon * std::max(1.0, s2.q.lpNorm<Eigen::Infinity>()));
}

}  // namespace
