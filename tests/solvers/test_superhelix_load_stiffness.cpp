// The exact load stiffness of the Super-Helix (solvers/superhelix/load_stiffness.hpp) and the
// element second derivatives under it (element.hpp), against central differences of the first
// derivatives they differentiate (an independent path: only the O(N) force routine and the element
// maps, no second-derivative code).
//
// Tolerance of a central difference with step h on a function of O(1) derivatives: truncation
// h^2/6 |f'''| plus rounding eps |f| / h. With h = 1e-5 (in units where q ell ~ 1; the rod-level checks take
// central_difference_jacobian's eps^(1/3) max(|q|, 1/L), 4e-6 .. 8e-6 here): ~2e-11 + 2e-11;
// the gates use 1e-8 relative to the largest entry (a factor ~250 above that estimate, for third
// derivatives of size up to ~40 at the strongly curved states below), and a wrong term of any
// load (a missing sign or factor) is O(1) relative.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
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

// Element strains on both branches of the coefficients: x^2 = sigma^2 |q|^2 below 1e-4, below 1
// (series) and above 4 (trigonometric forms).
const std::vector<Vec3> kStrains = {Vec3(0.002, -0.003, 0.001), Vec3(0.3, -0.5, 0.4), Vec3(1.9, -2.3, 1.2)};

TEST(SuperHelixSecondDerivatives, FrameRateAndOffsetHessianMatchCentralDifferences) {
  const double sigma = 0.9;
  for (const Vec3& q : kStrains) {
    const sh::ElementSecondDerivatives exact = sh::element_second_derivatives(q, sigma);
    for (int k = 0; k < 3; ++k) {
      const Vec3 dq = kStep * Vec3::Unit(k);
      const sh::ElementMaps plus = sh::element_maps(q + dq, sigma), minus = sh::element_maps(q - dq, sigma);
      const Mat3 frame_rate = (plus.G - minus.G) / (2 * kStep);
      const Mat3 offset_rate = (plus.dG0 - minus.dG0) / (2 * kStep);  // column j: d/dq_k of dc/dq_j
      EXPECT_LE((exact.frame_rate[k] - frame_rate).cwiseAbs().maxCoeff(), kDifferenceTolerance) << q.transpose();
      for (int j = 0; j < 3; ++j)
        EXPECT_LE((exact.offset_hessian[j].col(k) - offset_rate.col(j)).cwiseAbs().maxCoeff(), kDifferenceTolerance)
            << q.transpose() << " j " << j << " k " << k;
    }
    // The directional second derivative of the dynamics' rates (its own closed form) is
    // qdot^T H qdot: both are exact, so they agree to round-off (a few hundred eps of |H|).
    const Vec3 qdot(0.7, -1.1, 0.4);
    Vec3 quadratic = Vec3::Zero();
    for (int j = 0; j < 3; ++j) quadratic += qdot[j] * (exact.offset_hessian[j] * qdot);
    EXPECT_LE((quadratic - sh::element_point_rates(q, qdot, sigma).bias).norm(), 256 * kEpsilon) << q.transpose();
  }
}

// A 3-D rod at unequal, non-unit scales, curved and twisted, with gravity and dead end loads.
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
  return model;
}

VecX curled_state(std::size_t elements) {
  VecX q(Eigen::Index(3 * elements));
  for (Eigen::Index i = 0; i < q.size(); ++i) q[i] = 1.3 * std::sin(0.9 * double(i) + 0.4);
  return q;
}

TEST(SuperHelixLoadStiffness, MatchesCentralDifferencesOfTheGeneralisedForce) {
  for (bool moment : {false, true}) {
    const sh::RodModel model = loaded_rod(moment);
    const VecX q = curled_state(model.elements);
    const MatX exact = sh::load_stiffness(model, sh::Kinematics(model, q), 0.7);
    const sh::StaticResidual force = [&model](const VecX& x, double lambda) {
      return sh::external_generalised_force(model, sh::Kinematics(model, x), lambda);
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

TEST(SuperHelixLoadStiffness, StaticJacobianIsTheStiffnessMinusTheLoadStiffness) {
  const sh::RodModel model = loaded_rod(true);
  const VecX q = curled_state(model.elements);
  const MatX exact = sh::static_jacobian(model, q, 0.4);
  const sh::StaticResidual residual = [&model](const VecX& x, double lambda) { return sh::static_residual(model, x, lambda); };
  const MatX differences = sh::central_difference_jacobian(residual, q, 0.4, model.length);
  EXPECT_LE((exact - differences).cwiseAbs().maxCoeff(), kDifferenceTolerance * exact.cwiseAbs().maxCoeff());
}

}  // namespace
