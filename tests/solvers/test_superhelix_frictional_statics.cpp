// Tests of the Super-Helix's quasi-static frictional contact (solvers/superhelix/frictional_statics.hpp).
//
// Oracle for the friction law: a straight heavy rod lying along the fall line of a plane tilted by alpha,
// root clamped at its upper end, drawn up or down the slope. It rests on its Gauss points as a continuous
// beam on point supports (its weight is distributed, its supports are points: the clamp takes a share of
// the weight, 9 % at N = 8, and the first supports alternate about the mean); drawn, the inextensible rod
// slides as a whole, so every contact's friction is mu r_N against the motion and the root's pull along the
// rod is exactly W sin alpha +- mu sum r_N (W = rho S g L), and sum r_N tends to W cos alpha as N grows.
// Tolerance: the Newton's relative residual (1e-9 of the force scale) -> 1e-8 W.
// Scales: L = 1.3, rho S = 0.7, g = 7.3, (GJ, EI1, EI2) = (0.9, 2.1, 1.4), mu = 0.35, alpha = 20 degrees.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/testing/input_error.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::VecX;

constexpr double kAlpha = 20.0 * std::numbers::pi / 180.0;
constexpr double kMu = 0.35, kLength = 1.3, kDensity = 0.7, kGravity = 7.3;

struct Slope {
  sh::RodModel model;
  sh::RigidObstacle plane;
  Vec3 down;  // the fall line, along the rod
};

// The rod's centreline on the plane (radius 0: the plane is where the centreline touches).
Slope slope(double gravity_sign = 1.0, double mu = kMu) {
  Slope s;
  const Vec3 normal = Eigen::AngleAxisd(kAlpha, Vec3::UnitY()) * Vec3::UnitZ();
  s.down = Eigen::AngleAxisd(kAlpha, Vec3::UnitY()) * Vec3::UnitX();
  if (s.down.z() > 0.0) s.down = -s.down;
  sh::RodModel& m = s.model;
  m.length = kLength;
  m.elements = 8;
  m.gauss_points = 1;
  m.stiffness = Vec3(0.9, 2.1, 1.4);
  m.line_density = kDensity;
  m.gravity = Vec3(0.0, 0.0, -gravity_sign * kGravity);
  m.root_position = Vec3(0.2, -0.4, 0.3);
  m.root_frame << s.down, normal.cross(s.down), normal;  // bends about n1 off the plane
  s.plane = {sh::RigidObstacle::Shape::Plane, m.root_position, normal, 0.0, mu};
  return s;
}

struct Drawn {
  double pull = 0.0;    // the clamp's pull up the slope
  double normal = 0.0;  // sum of the contacts' r_N
};

// The rod drawn by `draw` along the fall line (up: negative) after resting on the plane.
Drawn draw_rod(const Slope& s, double draw) {
  sh::RodModel model = s.model;
  const VecX straight = VecX::Zero(3 * Eigen::Index(model.elements));  // on the plane
  sh::RigidObstacle plane = s.plane;
  plane.mu = 0.0;
  const auto rest = sh::solve_frictional_increment(model, {plane}, sh::frictional_start(model, straight));
  model.root_position += draw * s.down;
  const auto drawn = sh::solve_frictional_increment(model, {s.plane}, rest);
  Drawn out;
  Vec3 root_force = model.line_density * model.length * model.gravity;  // the forces on the rod
  for (const auto& c : drawn.contacts) {
    root_force += c.force;
    out.normal += c.local_force[0];
  }
  out.pull = root_force.dot(s.down);  // the clamp balances them: its pull up the slope
  return out;
}

double pull_after_draw(const Slope& s, double draw) { return draw_rod(s, draw).pull; }

TEST(SuperHelixFrictionalStatics, RodDrawnOnASlopeFeelsSlidingFrictionExactly) {
  const Slope s = slope();
  const double W = kDensity * kGravity * kLength;
  const Drawn up = draw_rod(s, -0.01), down = draw_rod(s, 0.01);
  EXPECT_NEAR(up.pull, W * std::sin(kAlpha) + kMu * up.normal, 1e-8 * W);
  EXPECT_NEAR(down.pull, W * std::sin(kAlpha) - kMu * down.normal, 1e-8 * W);
  // The clamp's share of the weight falls with N: sum r_N -> W cos alpha.
  EXPECT_NEAR(up.normal / (W * std::cos(kAlpha)), 0.91, 0.02);
  Slope fine = s;
  fine.model.elements = 64;
  EXPECT_NEAR(draw_rod(fine, -0.01).normal / (W * std::cos(kAlpha)), 1.0, 0.02);
}

TEST(SuperHelixFrictionalStatics, WrongFrictionOrGravityIsSeen) {
  const double W = kDensity * kGravity * kLength;
  const Drawn right = draw_rod(slope(), -0.01);
  const double expected = W * std::sin(kAlpha) + kMu * right.normal;
  // mu 10 % off moves the pull by 0.1 mu sum r_N = 0.03 W.
  EXPECT_GT(std::abs(pull_after_draw(slope(1.0, 1.1 * kMu), -0.01) - expected), 0.02 * W);
  // Gravity upward lifts the rod off the plane: no friction, no weight along the slope held.
  EXPECT_GT(std::abs(pull_after_draw(slope(-1.0), -0.01) - expected), 0.5 * W);
}

TEST(SuperHelixFrictionalStatics, ObstacleNormalsAndTheirGradientsMatchFiniteDifferences) {
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  const std::vector<sh::RigidObstacle> obstacles{
      {sh::RigidObstacle::Shape::Plane, Vec3(0.1, 0.2, -0.3), axis, 0.0, 0.2},
      {sh::RigidObstacle::Shape::Ball, Vec3(0.1, 0.2, -0.3), Vec3::UnitZ(), 0.7, 0.2},
      {sh::RigidObstacle::Shape::Cylinder, Vec3(0.1, 0.2, -0.3), axis, 0.7, 0.2},
      {sh::RigidObstacle::Shape::Edge, Vec3(0.1, 0.2, -0.3), axis, 0.7, 0.2, Vec3(0.8, 0.0, -0.3).normalized()}};
  const Vec3 x(1.1, -0.6, 0.9);
  const double h = 1e-6;
  for (const auto& obstacle : obstacles) {
    const sh::ObstacleProximity at = sh::obstacle_proximity(obstacle, x);
    EXPECT_NEAR(at.normal.norm(), 1.0, 1e-15);
    for (int j = 0; j < 3; ++j) {
      const Vec3 e = h * Vec3::Unit(j);
      const auto plus = sh::obstacle_proximity(obstacle, x + e), minus = sh::obstacle_proximity(obstacle, x - e);
      EXPECT_NEAR((plus.gap - minus.gap) / (2 * h), at.normal[j], 1e-9);  // grad gap = n
      EXPECT_LE(((plus.normal - minus.normal) / (2 * h) - at.normal_gradient.col(j)).norm(), 1e-8);
    }
  }
}

TEST(SuperHelixFrictionalStatics, AnEdgeIsATopAFrontAndARoundingBetween) {
  // A table's edge: top face normal +z, front face normal +x, rounded by 0.2 about the y axis through (1, 2, 3).
  const sh::RigidObstacle edge{sh::RigidObstacle::Shape::Edge, Vec3(1, 2, 3), Vec3::UnitZ(), 0.2, 0.0, Vec3::UnitX()};
  const Vec3 corner(1, 2, 3);
  const auto over_top = sh::obstacle_proximity(edge, corner + Vec3(-1.0, 0.3, 0.5));
  EXPECT_NEAR(over_top.gap, 0.3, 1e-15);
  EXPECT_EQ(over_top.normal, Vec3::UnitZ());
  EXPECT_EQ(over_top.normal_gradient, Mat3::Zero());
  const auto before_front = sh::obstacle_proximity(edge, corner + Vec3(0.4, 0.3, -2.0));
  EXPECT_NEAR(before_front.gap, 0.2, 1e-15);
  EXPECT_EQ(before_front.normal, Vec3::UnitX());
  const auto round = sh::obstacle_proximity(edge, corner + Vec3(0.3, -5.0, 0.4));
  EXPECT_NEAR(round.gap, 0.3, 1e-15);
  EXPECT_LE((round.normal - Vec3(0.6, 0.0, 0.8)).norm(), 1e-15);
  // Inside the solid the nearer face decides: 0.1 behind the front, 0.5 below the top.
  EXPECT_NEAR(sh::obstacle_proximity(edge, corner + Vec3(-0.1, 0.0, -0.5)).gap, -0.3, 1e-15);
  // The normal is continuous where a face meets the rounding.
  const auto top_end = sh::obstacle_proximity(edge, corner + Vec3(-1e-12, 0.0, 0.4));
  const auto round_start = sh::obstacle_proximity(edge, corner + Vec3(1e-12, 0.0, 0.4));
  EXPECT_LE((top_end.normal - round_start.normal).norm(), 1e-11);
  EXPECT_NEAR(top_end.gap, round_start.gap, 1e-15);
}

TEST(SuperHelixFrictionalStatics, RefusesBadInputByName) {
  const Slope s = slope();
  const VecX straight = VecX::Zero(24);
  const auto start = sh::frictional_start(s.model, straight);
  const auto parameter_of = [](auto&& call) { return rodvv::testing::input_error_parameter_of(call); };
  const auto with_obstacle = [&](auto change) {
    sh::RigidObstacle o = s.plane;
    change(o);
    return parameter_of([&] { sh::solve_frictional_increment(s.model, {o}, start); });
  };
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle&) {}), "<no InputError>");
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle& o) { o.mu = -0.1; }), "obstacles");
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle& o) { o.direction *= 1.01; }), "obstacles");
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle& o) {
              o.shape = sh::RigidObstacle::Shape::Ball;
              o.radius = 0.0;
            }),
            "obstacles");
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle& o) {
              o.shape = sh::RigidObstacle::Shape::Edge;
              o.radius = 0.1;
              o.side = (o.side + 0.01 * o.direction).normalized();  // not orthogonal to the direction
            }),
            "obstacles");
  sh::FrictionalStaticResult bad = start;
  bad.points.pop_back();
  EXPECT_EQ(parameter_of([&] { sh::solve_frictional_increment(s.model, {s.plane}, bad); }), "previous");
  bad = start;
  bad.q = VecX::Zero(5);
  EXPECT_EQ(parameter_of([&] { sh::solve_frictional_increment(s.model, {s.plane}, bad); }), "previous");
  sh::RodModel forced = s.model;
  forced.point_forces.assign(8, Vec3::Zero());
  EXPECT_EQ(parameter_of([&] { sh::solve_frictional_increment(forced, {s.plane}, start); }), "point_forces");
  sh::FrictionalStaticOptions options;
  options.tolerance = 0.0;
  EXPECT_EQ(parameter_of([&] { sh::solve_frictional_increment(s.model, {s.plane}, start, options); }), "tolerance");
  options = {};
  options.max_iterations = 0;
  EXPECT_EQ(parameter_of([&] { sh::solve_frictional_increment(s.model, {s.plane}, start, options); }), "max_iterations");
  EXPECT_EQ(parameter_of([&] { sh::frictional_start(s.model, VecX::Zero(3)); }), "q");
}

}  // namespace
