// Fitting a Super-Helix to points (solvers/superhelix/curve_fit.hpp): points taken from a
// Super-Helix at arbitrary arc lengths are fitted back to round-off (the rod and its strains are
// recovered: the fit is exact where the data are representable); points of a smooth curve that is not
// a piecewise helix are fitted to O(h^3) in distance; kinks and repeated points are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/curve_fit.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;

TEST(SuperHelixCurveFit, PointsOfASuperHelixAreFittedBackExactly) {
  sh::RodModel rod;
  rod.elements = 5;
  rod.length = 1.3;
  rod.root_position = Vec3(0.2, -0.4, 0.1);
  rod.root_frame = Eigen::AngleAxisd(0.9, Vec3(1.0, 0.5, -0.3).normalized()).toRotationMatrix();
  VecX q(15);
  for (int e = 0; e < 5; ++e) q.segment<3>(3 * e) = Vec3(0.6 - 0.2 * e, 1.1 * std::cos(e), 0.8 + 0.3 * e);
  const sh::Kinematics kinematics(rod, q);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Vec3> points;
  const int m = 40;
  for (int i = 0; i <= m; ++i) {
    double s = rod.length * (i + (i > 0 && i < m ? jitter(rng) : 0.0)) / m;
    const std::size_t e = std::min<std::size_t>(std::size_t(s / (rod.length / 5)), 4);
    points.push_back(kinematics.position(e, s - double(e) * rod.length / 5));
  }
  const sh::CurveFit fit = sh::fit_super_helix(points, 5);
  EXPECT_LE(fit.max_distance, 1e-12 * rod.length);
  EXPECT_NEAR(fit.model.length, rod.length, 1e-11);
  EXPECT_LE((fit.model.root_frame.col(0) - rod.root_frame.col(0)).norm(), 1e-10);
  // The strains up to the gauge (the root frame's n1 is fixed by the fit, not by the data): the
  // twist and the curvature magnitudes are gauge-free.
  for (int e = 0; e < 5; ++e) {
    EXPECT_NEAR(fit.q[3 * e], q[3 * e], 1e-9) << e;
    EXPECT_NEAR(fit.q.segment<2>(3 * e + 1).norm(), q.segment<2>(3 * e + 1).norm(), 1e-9) << e;
  }
}

// A smooth 3-D curve that is no piecewise helix: the distance of the fitted rod to its points
// falls like h^3 (measured 2.08e-3, 2.08e-4, 2.53e-5 at N = 4, 8, 16: orders 3.3, 3.0), not like the
// h^2 of a chord polygon.
std::vector<Vec3> smooth_curve(int m) {
  std::vector<Vec3> points;
  for (int i = 0; i <= m; ++i) {
    const double t = 2.0 * i / m;
    points.push_back(Vec3(t, 0.4 * std::sin(1.7 * t), 0.3 * t * t - 0.1 * std::cos(2.3 * t)));
  }
  return points;
}

TEST(SuperHelixCurveFit, SmoothCurvesAreFittedAtThirdOrder) {
  const auto points = smooth_curve(120);
  double previous = 0.0;
  for (std::size_t n : {4u, 8u, 16u}) {
    const double distance = sh::fit_super_helix(points, n).max_distance;
    if (previous > 0.0) {
      const double order = std::log2(previous / distance);
      EXPECT_GT(order, 2.9) << n;
      EXPECT_LT(order, 3.5) << n;
    }
    previous = distance;
  }
  EXPECT_LT(previous, 5e-5);  // 2 x the measured 2.53e-5 at N = 16
}

TEST(SuperHelixCurveFit, RefusesKinksRepeatedPointsAndTooManyElements) {
  const auto parameter_of = [](const std::vector<Vec3>& points, std::size_t n) {
    try {
      sh::fit_super_helix(points, n);
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  auto points = smooth_curve(30);
  EXPECT_EQ(parameter_of(points, 4), "none");
  auto repeated = points;
  repeated[7] = repeated[6];
  EXPECT_EQ(parameter_of(repeated, 4), "points");
  auto kinked = points;
  kinked[15] += Vec3(0.0, 0.3, 0.0);
  EXPECT_EQ(parameter_of(kinked, 4), "points");
  EXPECT_EQ(parameter_of({Vec3::Zero(), Vec3::UnitX()}, 1), "points");
  EXPECT_EQ(parameter_of(points, 0), "elements");
  EXPECT_EQ(parameter_of(points, 20), "elements");
}

}  // namespace
