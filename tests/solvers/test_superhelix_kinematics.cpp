// Super-Helix kinematics (solvers/superhelix, ALGORITHMS.md §1.2-1.3): the singularity-free closed
// form against an independent matrix exponential, exactness for straight elements, and every
// derivative (position and frame Jacobians, point velocities, generalised forces) against finite
// differences or the dense definition.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/testing/superhelix_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

// 3 n random strains (n elements) in [-amplitude, amplitude].
VecX random_q(std::size_t n, double amplitude, unsigned seed) {
  return rodvv::testing::superhelix::random_vector(3 * n, amplitude, seed);
}

sh::RodModel random_model(std::size_t n) {
  sh::RodModel model;
  model.elements = n;
  model.length = 1.3;
  model.root_position = Vec3(0.1, -0.2, 0.3);
  model.root_frame = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  return model;
}

// exp([[sigma X, sigma I], [0, 0]]) = [[E, G], [0, I]]: an independent route (Pade scaling and
// squaring) to both closed forms.
void reference_maps(const Vec3& q, double sigma, Mat3& E, Mat3& G) {
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  A.block<3, 3>(0, 0) = sigma * sh::skew(q);
  A.block<3, 3>(0, 3) = sigma * Mat3::Identity();
  const Eigen::Matrix<double, 6, 6> expA = A.exp();
  E = expA.block<3, 3>(0, 0);
  G = expA.block<3, 3>(0, 3);
}

TEST(SuperHelixElement, ClosedFormMatchesMatrixExponential) {
  // |q| sigma from 1e-9 (series branch) through 1 (branch switch) to 6 (nearly a full turn).
  // Tolerance 64 eps: both sides are O(1) matrices built from a handful of rounded operations
  // (Pade scaling-and-squaring: ~10 eps; closed form: ~4 eps); measured <= 3 eps.
  for (double x : {1e-9, 1e-4, 0.3, 0.999, 1.001, 2.5, 6.0}) {
    const Vec3 q = x * Vec3(0.3, -0.8, 0.52).normalized();
    Mat3 E, G;
    reference_maps(q, 1.0, E, G);
    const sh::ElementMaps maps = sh::element_maps(q, 1.0);
    EXPECT_LE((maps.E - E).cwiseAbs().maxCoeff(), 64 * kEpsilon) << "x = " << x;
    EXPECT_LE((maps.G - G).cwiseAbs().maxCoeff(), 64 * kEpsilon) << "x = " << x;
  }
}

TEST(SuperHelixElement, CoefficientsContinuousAcrossSeriesSwitch) {
  // The series (x^2 < 1) and the trigonometric branch must agree at the switch to a few eps of the
  // coefficient scale (the trig formulas lose ~eps/x^2 = eps there).
  const auto below = sh::helix_coefficients(std::nextafter(1.0, 0.0));
  const auto above = sh::helix_coefficients(1.0);
  EXPECT_TRUE(rodvv::testing::is_close(below.s0, above.s0, 8 * kEpsilon, 0.0));
  EXPECT_TRUE(rodvv::testing::is_close(below.f1, above.f1, 8 * kEpsilon, 0.0));
  EXPECT_TRUE(rodvv::testing::is_close(below.f2, above.f2, 16 * kEpsilon, 0.0));
  EXPECT_TRUE(rodvv::testing::is_close(below.g1, above.g1, 64 * kEpsilon, 0.0));
  EXPECT_TRUE(rodvv::testing::is_close(below.g2, above.g2, 64 * kEpsilon, 0.0));
}

TEST(SuperHelixElement, StraightElementIsExact) {
  const sh::ElementMaps maps = sh::element_maps(Vec3::Zero(), 0.37);
  EXPECT_EQ(maps.E, Mat3::Identity());
  EXPECT_EQ(maps.G, 0.37 * Mat3::Identity());
}

TEST(SuperHelixElement, LocalJacobianMatchesFiniteDifferences) {
  // Central differences with step 1e-5: truncation ~ step^2 |d^3 G| ~ 1e-10, round-off
  // eps / step ~ 2e-11; tolerance 1e-9.
  for (double x : {0.0, 1e-3, 0.5, 0.99, 1.01, 3.0}) {
    const Vec3 q = x * Vec3(-0.4, 0.6, 0.7).normalized();
    const sh::ElementMaps maps = sh::element_maps(q, 0.8);
    for (int i = 0; i < 3; ++i) {
      const double step = 1e-5;
      const Vec3 dq = step * Vec3::Unit(i);
      const Vec3 fd = (sh::element_maps(q + dq, 0.8).G - sh::element_maps(q - dq, 0.8).G) * Vec3::UnitX() /
                      (2 * step);
      EXPECT_LE((fd - maps.dG0.col(i)).norm(), 1e-9) << "x = " << x << " i = " << i;
    }
  }
}

TEST(SuperHelixKinematics, JacobiansMatchFiniteDifferences) {
  const sh::RodModel model = random_model(5);
  const VecX q = random_q(5, 2.0, 7);
  const sh::Kinematics kin(model, q);
  const double step = 1e-6;  // truncation ~1e-12 x |d^3 r| ~ 1e-11, round-off eps/step ~ 2e-10
  for (std::size_t e : {0u, 2u, 4u}) {
    for (double sigma : {0.0, 0.1, kin.element_length()}) {
      const MatX J = kin.position_jacobian(e, sigma), Theta = kin.rotation_jacobian(e, sigma);
      // dR = [Theta]x R  ->  Theta = vee(dR R^T)
      const auto fd =
          rodvv::testing::superhelix::finite_difference_jacobians<sh::Kinematics>(model, q, e, sigma, step);
      for (Eigen::Index j = 0; j < q.size(); ++j) {
        EXPECT_LE((fd.position.col(j) - J.col(j)).norm(), 1e-8) << "e " << e << " sigma " << sigma << " j " << j;
        EXPECT_LE((fd.rotation.col(j) - Theta.col(j)).norm(), 1e-8) << "e " << e << " sigma " << sigma << " j " << j;
      }
    }
  }
}

TEST(SuperHelixKinematics, FramesStayRotationsAndChainIsContinuous) {
  const sh::RodModel model = random_model(64);
  const sh::Kinematics kin(model, random_q(64, 8.0, 3));
  // 64 products of rotations: orthogonality drifts like sqrt(N) eps; 64 eps bound.
  const Mat3 R = kin.tip_frame();
  EXPECT_LE((R.transpose() * R - Mat3::Identity()).norm(), 64 * kEpsilon);
  for (std::size_t e = 0; e + 1 < 64; ++e) {
    EXPECT_LE((kin.position(e, kin.element_length()) - kin.base_position(e + 1)).norm(), 8 * kEpsilon);
    EXPECT_LE((kin.position(e + 1, 0.0) - kin.base_position(e + 1)).norm(), 8 * kEpsilon);
  }
}

TEST(SuperHelixKinematics, StraightRodIsExactAlongRootTangent) {
  sh::RodModel model = random_model(7);
  const sh::Kinematics kin(model, VecX::Zero(21));
  const Vec3 expected = model.root_position + model.length * model.root_frame.col(0);
  // 7 additions of ell n0: a few ulps.
  EXPECT_LE((kin.tip_position() - expected).norm(), 8 * kEpsilon);
}

TEST(SuperHelixKinematics, PointVelocitiesEqualJacobianTimesRates) {
  const sh::RodModel model = random_model(6);
  const VecX q = random_q(6, 3.0, 11), qdot = random_q(6, 1.0, 12);
  const sh::Kinematics kin(model, q);
  const auto v = kin.point_velocities(qdot);
  for (std::size_t g = 0; g < v.size(); ++g) {
    const auto& point = kin.points()[g];
    const Vec3 expected = kin.position_jacobian(point.element, point.sigma) * qdot;
    EXPECT_LE((v[g] - expected).norm(), 256 * kEpsilon * (1 + expected.norm())) << g;  // O(N) sums
  }
}

TEST(SuperHelixLoads, RecursiveGeneralisedForceEqualsDenseProjection) {
  sh::RodModel model = random_model(6);
  model.gravity = Vec3(0.3, -9.81, 1.0);
  model.end_force = Vec3(1.0, 2.0, -0.5);
  model.end_moment = Vec3(-0.2, 0.4, 0.9);
  const VecX q = random_q(6, 3.0, 5);
  const sh::Kinematics kin(model, q);
  const VecX fast = sh::external_generalised_force(model, kin);
  VecX dense = kin.position_jacobian(5, kin.element_length()).transpose() * model.end_force +
               kin.rotation_jacobian(5, kin.element_length()).transpose() * model.end_moment;
  for (const auto& point : kin.points())
    dense += kin.position_jacobian(point.element, point.sigma).transpose() * (point.mass * model.gravity);
  // O(N) sums of O(|F| L) terms: 256 eps relative to the largest entry.
  EXPECT_LE((fast - dense).lpNorm<Eigen::Infinity>(), 256 * kEpsilon * dense.lpNorm<Eigen::Infinity>());
}

TEST(SuperHelixModel, BadInputNamesTheParameter) {
  auto expect_parameter = [](const sh::RodModel& model, const std::string& name) {
    try {
      sh::validate(model);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& error) {
      EXPECT_EQ(error.parameter(), name);
    }
  };
  sh::RodModel m;
  m.elements = 0;
  expect_parameter(m, "elements");
  m = {};
  m.length = 0.0;
  expect_parameter(m, "length");
  m = {};
  m.stiffness[1] = -1.0;
  expect_parameter(m, "stiffness.bending1 (EI1)");
  m = {};
  m.line_density = 0.0;
  expect_parameter(m, "line_density");
  m = {};
  m.root_frame(0, 0) = 1.01;
  expect_parameter(m, "root_frame");
  m = {};
  m.root_frame.col(2) *= -1.0;  // a reflection: orthogonal but det = -1
  expect_parameter(m, "root_frame");
  m = {};
  m.gravity[2] = std::nan("");
  expect_parameter(m, "gravity[2]");
  m = {};
  m.natural_strain_per_element.resize(3);
  expect_parameter(m, "natural_strain_per_element");
  EXPECT_NO_THROW(sh::validate(sh::RodModel{}));
}

}  // namespace
