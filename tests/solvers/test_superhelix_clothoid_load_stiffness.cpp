// The exact load stiffness of the super-clothoid (clothoid_load_stiffness.hpp) and the element's
// forward-mode derivatives under it (clothoid_element_jacobian, clothoid_element_second_derivatives),
// against paths that share no derivative code with them: the complex-step first derivatives
// (clothoid_element_jacobian_complex_step), central differences of those, the second-order rate
// series of the dynamics (clothoid_element_rates: its own Taylor recurrence along one direction),
// and central differences of the generalised force.
//
// Tolerances: forward mode and complex step are both exact to round-off, so first derivatives agree
// to a few hundred eps of their size (sums of ~40 series terms over up to 4 sub-intervals). A
// central difference with step h = 1e-5 (central_difference_jacobian's for the rod, eps^(1/3) max(|q|,
// 1/L), is 6e-6 .. 8e-6 here) on O(1) derivatives errs by h^2/6 |f'''| + eps |f| / h
// ~ 2e-11 + 2e-11; the gates use 1e-8 relative to the largest entry (a factor ~250 above that, for
// third derivatives up to ~40 at the strongly curved states here). A wrong term (sign, factor, a
// missing chain-rule column) is O(1) relative.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/clothoid_load_stiffness.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "rodvv/solvers/superhelix/newton.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

constexpr double kStep = 1e-5;
constexpr double kDifferenceTolerance = 1e-8;  // relative to the largest entry, see the file comment
constexpr double kRoundOff = 256 * kEpsilon;   // two exact paths, relative to the largest entry

struct Strains {
  Vec3 a, b;
  double ell;
};
// Nearly straight, moderately curved (one sub-interval) and strongly curved with a steep gradient
// ((|a| + |b| ell) ell > 6: several sub-intervals, so the product rule across them is exercised).
const std::vector<Strains> kElements = {{Vec3(0.002, -0.003, 0.001), Vec3(0.01, 0.004, -0.02), 0.9},
                                        {Vec3(0.3, -0.5, 0.4), Vec3(-0.7, 0.2, 0.9), 0.9},
                                        {Vec3(1.9, -2.3, 1.2), Vec3(-1.5, 2.8, 0.6), 1.4}};

TEST(SuperClothoidSecondDerivatives, FirstDerivativesEqualTheComplexStep) {
  for (const Strains& e : kElements) {
    const sh::ClothoidSecondDerivatives forward = sh::clothoid_element_second_derivatives(e.a, e.b, e.ell);
    const sh::ClothoidJacobian first_order = sh::clothoid_element_jacobian(e.a, e.b, e.ell);
    const sh::ClothoidJacobian complex_step = sh::clothoid_element_jacobian_complex_step(e.a, e.b, e.ell);
    const double rotation = complex_step.rotation.cwiseAbs().maxCoeff();
    const double translation = complex_step.translation.cwiseAbs().maxCoeff();
    for (const auto& [R, r, Theta, T] : {std::tuple(forward.R, forward.r, forward.rotation, forward.translation),
                                         std::tuple(first_order.R, first_order.r, first_order.rotation,
                                                    first_order.translation)}) {
      EXPECT_LE((R - complex_step.R).cwiseAbs().maxCoeff(), kRoundOff);
      EXPECT_LE((r - complex_step.r).cwiseAbs().maxCoeff(), kRoundOff * e.ell);
      EXPECT_LE((Theta - complex_step.rotation).cwiseAbs().maxCoeff(), kRoundOff * rotation) << e.a.transpose();
      EXPECT_LE((T - complex_step.translation).cwiseAbs().maxCoeff(), kRoundOff * translation) << e.a.transpose();
    }
  }
}

TEST(SuperClothoidSecondDerivatives, MatchCentralDifferencesOfTheComplexStepJacobian) {
  for (const Strains& e : kElements) {
    const sh::ClothoidSecondDerivatives exact = sh::clothoid_element_second_derivatives(e.a, e.b, e.ell);
    double largest = 0.0, worst = 0.0;
    for (int q = 0; q < 6; ++q) {
      Vec3 a_plus = e.a, a_minus = e.a, b_plus = e.b, b_minus = e.b;
      (q < 3 ? a_plus[q] : b_plus[q - 3]) += kStep;
      (q < 3 ? a_minus[q] : b_minus[q - 3]) -= kStep;
      const sh::ClothoidJacobian plus = sh::clothoid_element_jacobian_complex_step(a_plus, b_plus, e.ell);
      const sh::ClothoidJacobian minus = sh::clothoid_element_jacobian_complex_step(a_minus, b_minus, e.ell);
      const Eigen::Matrix<double, 3, 6> rotation_rate = (plus.rotation - minus.rotation) / (2 * kStep);
      const Eigen::Matrix<double, 3, 6> translation_rate = (plus.translation - minus.translation) / (2 * kStep);
      worst = std::max({worst, (exact.rotation_rate[q] - rotation_rate).cwiseAbs().maxCoeff(),
                        (exact.translation_hessian[q] - translation_rate).cwiseAbs().maxCoeff()});
      largest = std::max({largest, exact.rotation_rate[q].cwiseAbs().maxCoeff(),
                          exact.translation_hessian[q].cwiseAbs().maxCoeff()});
    }
    EXPECT_LE(worst, kDifferenceTolerance * largest) << e.a.transpose();
    // The Hessian of r is symmetric by construction (stored once per pair); Theta's rate is not.
    EXPECT_GT(largest, 0.0);
  }
}

TEST(SuperClothoidSecondDerivatives, DirectionalSecondDerivativeIsTheRateSeriesBias) {
  // Along v = (adot, bdot): d2r/dt2 = v^T H_r v and d(omega)/dt = sum_pq dTheta_p/dq v_p v_q, both also
  // computed by clothoid_element_rates' own second-order recurrence: exact paths, round-off apart.
  const Vec3 adot(0.7, -1.1, 0.4), bdot(-0.3, 0.5, 1.2);
  Eigen::Matrix<double, 6, 1> v;
  v << adot, bdot;
  for (const Strains& e : kElements) {
    const sh::ClothoidSecondDerivatives exact = sh::clothoid_element_second_derivatives(e.a, e.b, e.ell);
    const sh::ClothoidRates rates = sh::clothoid_element_rates(e.a, e.b, adot, bdot, e.ell);
    Vec3 bias = Vec3::Zero(), angular_bias = Vec3::Zero();
    for (int q = 0; q < 6; ++q) {
      bias += v[q] * (exact.translation_hessian[q] * v);
      angular_bias += v[q] * (exact.rotation_rate[q] * v);
    }
    const double scale = std::max(1.0, rates.bias.norm() + rates.angular_bias.norm());
    EXPECT_LE((bias - rates.bias).norm(), kRoundOff * scale) << e.a.transpose();
    EXPECT_LE((angular_bias - rates.angular_bias).norm(), kRoundOff * scale) << e.a.transpose();
  }
}

TEST(SuperClothoidSecondDerivatives, BadInputNamesTheParameter) {
  const auto expect_parameter = [](auto&& call, const char* parameter) {
    try {
      call();
      ADD_FAILURE() << "no InputError for " << parameter;
    } catch (const rodvv::InputError& error) {
      EXPECT_EQ(error.parameter(), parameter);
    }
  };
  expect_parameter([] { sh::clothoid_element_second_derivatives(Vec3(NAN, 0, 0), Vec3::Zero(), 1.0); }, "a");
  expect_parameter([] { sh::clothoid_element_second_derivatives(Vec3::Zero(), Vec3(0, INFINITY, 0), 1.0); }, "b");
  expect_parameter([] { sh::clothoid_element_second_derivatives(Vec3::Zero(), Vec3::Zero(), -1.0); }, "ell");
  expect_parameter([] { sh::clothoid_element_second_derivatives(Vec3::Zero(), Vec3::Zero(), 1.0, 1e-3); },
                   "tolerance");
  expect_parameter([] { sh::clothoid_element_jacobian_complex_step(Vec3::Zero(), Vec3::Zero(), 0.0); }, "ell");
}

// A 3-D rod at unequal, non-unit scales, curved and twisted, with gravity, dead point forces and
// dead end loads (the end moment optional: it has no potential).
sh::RodModel loaded_rod(bool with_end_moment) {
  sh::RodModel model;
  model.elements = 5;
  model.length = 1.7;
  model.stiffness = Vec3(0.6, 1.3, 2.1);
  model.line_density = 0.8;
  model.gravity = Vec3(0.3, -9.0, 1.2);
  model.root_position = Vec3(0.2, -0.1, 0.4);
  model.root_frame = Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  model.end_force = Vec3(1.4, 0.6, -2.2);
  if (with_end_moment) model.end_moment = Vec3(-0.5, 0.9, 0.3);
  for (std::size_t g = 0; g < model.elements * model.gauss_points; ++g)
    model.point_forces.push_back(Vec3(0.2 * std::cos(0.7 * double(g)), -0.1, 0.15 * std::sin(1.3 * double(g))));
  return model;
}

VecX curled_state(std::size_t elements) {
  VecX q(Eigen::Index(3 * (elements + 1)));
  for (Eigen::Index i = 0; i < q.size(); ++i) q[i] = 1.3 * std::sin(0.9 * double(i) + 0.4);
  return q;
}

TEST(SuperClothoidLoadStiffness, MatchesCentralDifferencesOfTheGeneralisedForce) {
  for (bool moment : {false, true}) {
    const sh::RodModel model = loaded_rod(moment);
    const VecX q = curled_state(model.elements);
    const MatX exact = sh::clothoid_load_stiffness(model, sh::ClothoidKinematics(model, q), 0.7);
    const sh::StaticResidual force = [&model](const VecX& x, double lambda) {
      return sh::clothoid_external_force(model, sh::ClothoidKinematics(model, x), lambda);
    };
    const MatX differences = sh::central_difference_jacobian(force, q, 0.7, model.length);
    const double largest = exact.cwiseAbs().maxCoeff();
    EXPECT_LE((exact - differences).cwiseAbs().maxCoeff(), kDifferenceTolerance * largest) << "end moment " << moment;
    // Conservative loads: symmetric to round-off (O(N^2) sums of products: 1e3 eps); the dead end
    // moment adds the unsymmetric Ziegler part, O(1) relative.
    const double asymmetry = (exact - exact.transpose()).cwiseAbs().maxCoeff() / largest;
    if (moment)
      EXPECT_GT(asymmetry, 1e-3);
    else
      EXPECT_LE(asymmetry, 1e3 * kEpsilon);
  }
}

TEST(SuperClothoidLoadStiffness, StaticJacobianIsTheStiffnessMinusTheLoadStiffness) {
  const sh::RodModel model = loaded_rod(true);
  const VecX q = curled_state(model.elements);
  const MatX exact = sh::clothoid_static_jacobian(model, q, 0.4);
  const sh::StaticResidual residual = [&model](const VecX& x, double lambda) {
    return sh::clothoid_static_residual(model, x, lambda);
  };
  const MatX differences = sh::central_difference_jacobian(residual, q, 0.4, model.length);
  EXPECT_LE((exact - differences).cwiseAbs().maxCoeff(), kDifferenceTolerance * exact.cwiseAbs().maxCoeff());
}

TEST(SuperClothoidLoadStiffness, PointForcesOfTheWrongCountNameTheParameter) {
  const sh::RodModel model = loaded_rod(false);
  const sh::ClothoidKinematics kinematics(model, curled_state(model.elements));
  try {
    sh::clothoid_generalised_force_jacobian(kinematics, std::vector<Vec3>(3, Vec3::UnitX()), Vec3::Zero(),
                                            Vec3::Zero());
    ADD_FAILURE() << "no InputError";
  } catch (const rodvv::InputError& error) {
    EXPECT_EQ(error.parameter(), "point_forces");
  }
}

}  // namespace
