// Super-Helix dynamics with a prescribed moving root (root_motion.hpp; issue 5 "clamped root,
// optionally moving"; ALGORITHMS.md §1.4/§1.6: the root's acceleration is the base acceleration).
// The root terms live in the bias accelerations zeta (r_tt = J qddot + zeta), shared by both paths:
//  - zeta equals the time derivative of the point velocities along a moving-root trajectory;
//  - equivalence principle: a root accelerating at a in gravity g == a fixed root in gravity g - a;
//  - Galilean invariance: a root moving at constant velocity changes nothing;
//  - dense == recursive with a rotating, accelerating root at every step;
//  - a root frame that is not a rotation is an InputError naming "root_motion.frame".
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/root_motion.hpp"
#include "rodvv/testing/superhelix_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;
using rodvv::testing::superhelix::random_vector;

// The common loaded model without the end moment.
sh::RodModel hanging_model(std::size_t n) {
  sh::RodModel model = rodvv::testing::superhelix::loaded_model(n);
  model.end_moment = Vec3::Zero();
  return model;
}

// A root that translates with acceleration and spins up about a tilted axis.
sh::RootMotion shaking_root(const sh::RodModel& model) {
  return sh::uniformly_accelerated_root(model, Vec3(0.3, -0.2, 0.1), Vec3(1.0, 2.0, -0.5), Vec3(0.3, -0.4, 1.0), 2.0,
                                        -3.0);
}

// Velocities of the Gauss points with a moving root: v_g = v0 + omega0 x (r_g - r0) + J_g qdot.
std::vector<Vec3> point_velocities(const sh::RodModel& model, const sh::RootState& root, const VecX& q,
                                   const VecX& qdot) {
  sh::RodModel moved = model;
  moved.root_position = root.position;
  moved.root_frame = root.frame;
  const sh::Kinematics kin(moved, q);
  auto v = kin.point_velocities(qdot);
  for (std::size_t g = 0; g < v.size(); ++g)
    v[g] += root.velocity + root.angular_velocity.cross(kin.points()[g].position - root.position);
  return v;
}

TEST(SuperHelixRootMotion, BiasIsTimeDerivativeOfPointVelocity) {
  // d/dt v_g(q + t qdot, qdot + t a, root(t0 + t)) at t = 0 equals J_g a + zeta_g (zeta with the root
  // terms). Central difference with step 1e-5 on O(1..10) accelerations: truncation ~ t^2 |v'''| ~
  // 1e-9, round-off ~ eps |v| / t ~ 1e-11; tolerance 1e-7 (1 + |expected|), as the fixed-root test.
  const sh::RodModel model = hanging_model(5);
  const sh::RootMotion root = shaking_root(model);
  const double t0 = 0.3;
  const VecX q = random_vector(15, 3.0, 4), qdot = random_vector(15, 2.0, 5), a = random_vector(15, 1.0, 6);
  const sh::RootState now = root.state_at(model, t0);
  sh::RodModel moved = model;
  moved.root_position = now.position;
  moved.root_frame = now.frame;
  const sh::Kinematics kin(moved, q);
  const auto zeta = sh::bias_accelerations(moved, kin, qdot, now);
  const double t = 1e-5;
  const auto vp = point_velocities(model, root.state_at(model, t0 + t), q + t * qdot, qdot + t * a);
  const auto vm = point_velocities(model, root.state_at(model, t0 - t), q - t * qdot, qdot - t * a);
  double worst = 0.0, root_part = 0.0;
  const auto fixed_zeta = sh::bias_accelerations(moved, kin, qdot);
  for (std::size_t g = 0; g < zeta.size(); ++g) {
    const auto& point = kin.points()[g];
    const Vec3 expected = (vp[g] - vm[g]) / (2 * t);
    const Vec3 actual = kin.position_jacobian(point.element, point.sigma) * a + zeta[g];
    worst = std::max(worst, (actual - expected).norm() / (1.0 + expected.norm()));
    EXPECT_LE((actual - expected).norm(), 1e-7 * (1.0 + expected.norm())) << g;
    root_part = std::max(root_part, (zeta[g] - fixed_zeta[g]).norm());
  }
  std::cout << "[ summary  ] moving-root zeta vs d/dt v: max relative error " << worst << "\n";
  // Teeth: the root terms are not small here, so dropping them would fail the check above.
  EXPECT_GT(root_part, 1.0);
}

TEST(SuperHelixRootMotion, EquivalencePrinciple) {
  // A root accelerating at a (no rotation, starting at rest) in gravity g gives the same q(t) as a
  // fixed root in gravity g - a: in the bias the root enters as zeta + a, i.e. m (zeta + a - g) vs
  // m (zeta - (g - a)), equal up to one rounding of the sum (~eps |g|) per step. Over 200 steps the
  // rounding differences of dv (~eps |dv| per step) accumulate at most linearly (the damped system
  // does not amplify them over 0.2 s): tolerance 200 steps x 64 eps x max(|q|, 1).
  const sh::RodModel model = hanging_model(6);
  const Vec3 a(1.5, -0.7, 3.0);
  const sh::RootMotion accelerating = sh::uniformly_accelerated_root(model, Vec3::Zero(), a);
  sh::RodModel equivalent = model;
  equivalent.gravity = model.gravity - a;
  const int steps = 200;
  for (auto path : {sh::DynamicsPath::Dense, sh::DynamicsPath::Recursive}) {
    sh::DynamicState s1{random_vector(18, 2.0, 11), random_vector(18, 1.0, 12), 0.0}, s2 = s1;
    double worst = 0.0;
    for (int i = 0; i < steps; ++i) {
      s1 = sh::step(model, s1, 1e-3, path, accelerating);
      s2 = sh::step(equivalent, s2, 1e-3, path);
      worst = std::max(worst, (s1.q - s2.q).lpNorm<Eigen::Infinity>());
    }
    const double scale = std::max(1.0, s2.q.lpNorm<Eigen::Infinity>());
    std::cout << "[ summary  ] equivalence principle, max |q_moving - q_equivalent| = " << worst << "\n";
    EXPECT_LE(worst, steps * 64 * kEpsilon * scale);
    // Teeth: the wrong sign (g + a) is a different motion.
    sh::RodModel wrong = model;
    wrong.gravity = model.gravity + a;
    sh::DynamicState s3{random_vector(18, 2.0, 11), random_vector(18, 1.0, 12), 0.0};
    for (int i = 0; i < steps; ++i) s3 = sh::step(wrong, s3, 1e-3, path);
    EXPECT_GT((s3.q - s1.q).lpNorm<Eigen::Infinity>(), 1e3 * steps * 64 * kEpsilon * scale);
  }
}

TEST(SuperHelixRootMotion, UniformRootVelocityChangesNothing) {
  // Galilean invariance: the dynamics reads only relative positions, the root's angular velocity
  // and its accelerations, all zero or identical here, so q(t) agrees to round-off of the base
  // point offsets (64 eps per step, 200 steps).
  const sh::RodModel model = hanging_model(6);
  const sh::RootMotion drifting = sh::uniformly_accelerated_root(model, Vec3(3.0, -1.0, 2.0), Vec3::Zero());
  const int steps = 200;
  sh::DynamicState s1{random_vector(18, 2.0, 21), random_vector(18, 1.0, 22), 0.0}, s2 = s1;
  for (int i = 0; i < steps; ++i) {
    s1 = sh::step(model, s1, 1e-3, sh::DynamicsPath::Recursive, drifting);
    s2 = sh::step(model, s2, 1e-3, sh::DynamicsPath::Recursive);
  }
  const double difference = (s1.q - s2.q).lpNorm<Eigen::Infinity>();
  std::cout << "[ summary  ] Galilean, |q_drifting - q_fixed| = " << difference << "\n";
  EXPECT_LE(difference, steps * 64 * kEpsilon * std::max(1.0, s2.q.lpNorm<Eigen::Infinity>()));
  // Teeth: a rotating root at the same speed scale is seen at once.
  const sh::RootMotion spinning = sh::uniformly_accelerated_root(model, Vec3::Zero(), Vec3::Zero(), Vec3::UnitZ(), 3.0);
  sh::DynamicState s3{random_vector(18, 2.0, 21), random_vector(18, 1.0, 22), 0.0};
  for (int i = 0; i < steps; ++i) s3 = sh::step(model, s3, 1e-3, sh::DynamicsPath::Recursive, spinning);
  EXPECT_GT((s3.q - s2.q).lpNorm<Eigen::Infinity>(), 1e-3);
}

TEST(SuperHelixRootMotion, RecursiveEqualsDenseWithRotatingRoot) {
  // Both paths at every step of a trajectory driven by a translating, spinning-up root (each step
  // from the same state): the 1e-12 relative gate (measured ~1e-14, as with a fixed root).
  const sh::RodModel model = hanging_model(8);
  const sh::RootMotion root = shaking_root(model);
  sh::DynamicState state{random_vector(24, 2.0, 31), random_vector(24, 1.0, 32), 0.0};
  double worst = 0.0;
  for (int i = 0; i < 100; ++i) {
    const VecX dense = sh::velocity_change(model, state, 1e-3, sh::DynamicsPath::Dense, root);
    const VecX fast = sh::velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive, root);
    const double relative = (dense - fast).lpNorm<Eigen::Infinity>() / dense.lpNorm<Eigen::Infinity>();
    worst = std::max(worst, relative);
    EXPECT_LE(relative, 1e-12) << "step " << i;
    state.qdot += fast;
    state.q += 1e-3 * state.qdot;
    state.time += 1e-3;
  }
  std::cout << "[ summary  ] rotating root: max relative |dv_dense - dv_recursive| = " << worst << "\n";
  // Teeth: the same state with the root held still gives a different step.
  const VecX moving = sh::velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive, root);
  const VecX still = sh::velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive);
  EXPECT_GT((moving - still).lpNorm<Eigen::Infinity>(), 1e-3 * moving.lpNorm<Eigen::Infinity>());
}

TEST(SuperHelixRootMotion, BadRootNamesTheParameter) {
  const sh::RodModel model = hanging_model(4);
  const sh::DynamicState state{VecX::Zero(12), VecX::Zero(12), 0.0};
  sh::RootMotion sheared;
  sheared.motion = [](double) {
    sh::RootState s;
    s.frame(0, 1) = 0.1;  // not orthogonal
    return s;
  };
  sh::RootMotion reflected;
  reflected.motion = [](double) {
    sh::RootState s;
    s.frame = -Mat3::Identity();  // orthogonal, det = -1
    return s;
  };
  sh::RootMotion not_finite;
  not_finite.motion = [](double) {
    sh::RootState s;
    s.acceleration.x() = std::nan("");
    return s;
  };
  for (auto path : {sh::DynamicsPath::Dense, sh::DynamicsPath::Recursive}) {
    for (const auto* root : {&sheared, &reflected}) {
      try {
        sh::step(model, state, 1e-3, path, *root);
        ADD_FAILURE() << "no InputError";
      } catch (const rodvv::InputError& e) {
        EXPECT_EQ(e.parameter(), "root_motion.frame");
      }
    }
    try {
      sh::step(model, state, 1e-3, path, not_finite);
      ADD_FAILURE() << "no InputError";
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), "root_motion");
    }
  }
  try {
    sh::uniformly_accelerated_root(model, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 1.0);
    ADD_FAILURE() << "no InputError";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "axis");
  }
  // A valid rotation passes.
  EXPECT_NO_THROW(sh::step(model, state, 1e-3, sh::DynamicsPath::Recursive, shaking_root(model)));
}

}  // namespace
