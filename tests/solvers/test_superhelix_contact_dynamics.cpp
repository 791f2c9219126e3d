// Tests of the Super-Helix dynamics with velocity-level frictionless contact
// (solvers/superhelix/contact_dynamics.hpp).
//
// The settled rod: a heavy cantilever clamped horizontally at height delta over a frictionless floor, released
// straight, falls, lands and settles under Rayleigh damping. At rest the step's fixed point is the frictionless
// contact equilibrium at the Gauss points (the header's derivation), the same discrete problem the quasi-static
// solver frictional_statics.hpp solves by Newton on (q, r) with a primal-dual active set: two algorithms that
// share the kinematics and nothing of the contact solution. Scales: L = 1.7, rho S = 0.4, g = 6.1,
// (GJ, EI1, EI2) = (0.55, 0.9, 1.6) (the rod bends about n1 = y), delta = 0.05.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/contact_dynamics.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/testing/input_error.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
namespace contact = rodvv::solvers::contact;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::VecX;

constexpr double kDelta = 0.05;

struct Floor {
  sh::RodModel model;
  sh::RigidObstacle plane;
};

Floor heavy_rod_over_floor(std::size_t elements, std::size_t gauss_points = 4) {
  Floor f;
  sh::RodModel& m = f.model;
  m.length = 1.7;
  m.elements = elements;
  m.gauss_points = gauss_points;
  m.stiffness = Vec3(0.55, 0.9, 1.6);
  m.line_density = 0.4;
  m.rotational_inertia = Vec3(2e-4, 1e-4, 1.5e-4);
  m.gravity = Vec3(0.0, 0.0, -6.1);
  m.root_position = Vec3(0.3, -0.2, kDelta);
  m.root_frame = Mat3::Identity();  // n0 = x along the rod; bending about n1 = y moves it in the x-z plane
  m.rayleigh_stiffness = 0.05;
  f.plane = {sh::RigidObstacle::Shape::Plane, Vec3(0.0, 0.0, 0.0), Vec3::UnitZ(), 0.0, 0.0};
  return f;
}

VecX at_rest(const sh::RodModel& m) { return VecX::Zero(static_cast<Eigen::Index>(sh::dof_count(m))); }

// Steps until one changes q by less than 1e-13 of its size (about 30 - 150 steps here).
sh::DynamicState settle(const Floor& f, double h, const sh::ContactStepOptions& options = {}) {
  sh::DynamicState state{at_rest(f.model), at_rest(f.model), 0.0};
  for (int step = 0; step < 5000; ++step) {
    const auto next = sh::step_with_obstacles(f.model, state, h, {f.plane}, options);
    const double change = (next.state.q - state.q).lpNorm<Eigen::Infinity>();
    state = next.state;
    if (change <= 1e-13 * std::max(1.0, state.q.lpNorm<Eigen::Infinity>())) return state;
  }
  ADD_FAILURE() << "the rod did not come to rest in 5000 steps of h = " << h;
  return state;
}

double relative_distance_to_statics(const Floor& f, const VecX& q) {
  sh::FrictionalStaticOptions options;
  options.tolerance = 1e-11;
  const auto statics =
      sh::solve_frictional_increment(f.model, {f.plane}, sh::frictional_start(f.model, at_rest(f.model)), options);
  return (q - statics.q).lpNorm<Eigen::Infinity>() / statics.q.lpNorm<Eigen::Infinity>();
}

// Far from every obstacle the step is the dense step of dynamics.hpp, bit for bit.
TEST(SuperHelixContactDynamics, WithoutCandidatesItIsTheDenseStep) {
  Floor f = heavy_rod_over_floor(6);
  f.plane.point = Vec3(0.0, 0.0, -10.0);
  sh::DynamicState state{at_rest(f.model), at_rest(f.model), 0.4};
  for (Eigen::Index i = 0; i < state.q.size(); ++i) {
    state.q(i) = 0.1 * std::sin(1.3 * double(i));
    state.qdot(i) = 0.2 * std::cos(0.7 * double(i));
  }
  const auto with = sh::step_with_obstacles(f.model, state, 1e-2, {f.plane});
  const auto dense = sh::step(f.model, state, 1e-2, sh::DynamicsPath::Dense);
  EXPECT_TRUE(with.contacts.empty());
  EXPECT_EQ(with.state.q, dense.q);
  EXPECT_EQ(with.state.qdot, dense.qdot);
  EXPECT_EQ(with.state.time, dense.time);
}

// At rest on the floor the rod is the frictionless static equilibrium. With four Gauss points per element a
// lying element touches at four points but has one way to leave the floor (its kappa1), so W is singular and
// the default compliance 1e-9 softens the contacts: measured 8.9e-10 (h = 0.03) and 7.4e-9 (h = 0.1) relative,
// bound 2e-8. With one Gauss point per element W is regular and the compliance 0: measured 4.0e-10 at both h
// (the statics' own compliance, 1e-12 of its W, and tolerances), bound 10x.
TEST(SuperHelixContactDynamics, SettledRodIsTheFrictionlessStaticEquilibrium) {
  for (double h : {3e-2, 1e-1}) {
    const Floor f = heavy_rod_over_floor(8);
    EXPECT_LT(relative_distance_to_statics(f, settle(f, h).q), 2e-8) << "h = " << h;
    const Floor single = heavy_rod_over_floor(8, 1);
    sh::ContactStepOptions exact;
    exact.compliance = 0.0;
    EXPECT_LT(relative_distance_to_statics(single, settle(single, h, exact).q), 4e-9) << "h = " << h;
  }
}

// Teeth of the comparison above: the floor 1e-6 delta higher for the statics alone is seen.
TEST(SuperHelixContactDynamics, StaticsComparisonSeesAFloorMovedByAMicroDelta) {
  const Floor f = heavy_rod_over_floor(8, 1);
  sh::ContactStepOptions exact;
  exact.compliance = 0.0;
  const VecX q = settle(f, 0.1, exact).q;
  Floor raised = f;
  raised.plane.point.z() += 1e-6 * kDelta;
  EXPECT_GT(relative_distance_to_statics(raised, q), 1e-8);
}

// One step into the floor: every candidate's linearised gap at the end of the step is >= 0, and an impulse is
// exerted only where that gap is closed (complementarity), to the LCP's round-off; Lemke and projected
// Gauss-Seidel find the same step.
TEST(SuperHelixContactDynamics, LandingStepIsComplementaryAndBothLcpSolversAgree) {
  const Floor f = heavy_rod_over_floor(6, 1);
  sh::DynamicState state{at_rest(f.model), at_rest(f.model), 0.0};
  state.q(1) = 0.1;  // kappa1 of the first element: the rod bends down, the tip about 0.006 above the floor
  for (Eigen::Index i = 1; i < state.qdot.size(); i += 3) state.qdot(i) = 2.0;  // and swings down, ~3 L/s at the tip
  const double h = 0.02;
  sh::ContactStepOptions options;
  options.compliance = 0.0;
  const auto lemke = sh::step_with_obstacles(f.model, state, h, {f.plane}, options);
  options.method = contact::LcpMethod::ProjectedGaussSeidel;
  const auto pgs = sh::step_with_obstacles(f.model, state, h, {f.plane}, options);
  ASSERT_FALSE(lemke.contacts.empty());
  const sh::Kinematics kinematics(f.model, state.q);
  std::size_t active = 0;
  for (const auto& c : lemke.contacts) {
    const auto& point = kinematics.points()[c.point];
    const double gap_after =
        c.gap + h * c.normal.dot(kinematics.position_jacobian(point.element, point.sigma) * lemke.state.qdot);
    EXPECT_GE(gap_after, -1e-14) << "point " << c.point;
    EXPECT_GE(c.impulse, 0.0);
    if (c.impulse > 0.0) {
      EXPECT_NEAR(gap_after, 0.0, 1e-14) << "point " << c.point;
      ++active;
    }
  }
  EXPECT_GT(active, 0u);
  EXPECT_LT((lemke.state.qdot - pgs.state.qdot).lpNorm<Eigen::Infinity>(),
            1e-9 * lemke.state.qdot.lpNorm<Eigen::Infinity>());
}

TEST(SuperHelixContactDynamics, RefusesBadInputByName) {
  const Floor f = heavy_rod_over_floor(4);
  const sh::DynamicState state{at_rest(f.model), at_rest(f.model), 0.0};
  const auto parameter_of = [](auto&& call) { return rodvv::testing::input_error_parameter_of(call); };
  const auto with_obstacle = [&](auto change) {
    sh::RigidObstacle o = f.plane;
    change(o);
    return parameter_of([&] { sh::step_with_obstacles(f.model, state, 0.01, {o}); });
  };
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle&) {}), "<no InputError>");
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle& o) { o.mu = 0.3; }), "obstacles");  // frictionless only
  EXPECT_EQ(with_obstacle([](sh::RigidObstacle& o) { o.direction *= 1.01; }), "obstacles");
  const auto with_options = [&](auto change) {
    sh::ContactStepOptions options;
    change(options);
    return parameter_of([&] { sh::step_with_obstacles(f.model, state, 0.01, {f.plane}, options); });
  };
  EXPECT_EQ(with_options([](sh::ContactStepOptions& o) { o.contact_distance = -1.0; }), "contact_distance");
  EXPECT_EQ(with_options([](sh::ContactStepOptions& o) { o.compliance = -1e-9; }), "compliance");
  EXPECT_EQ(with_options([](sh::ContactStepOptions& o) { o.compliance = 2.0; }), "compliance");
  EXPECT_EQ(with_options([](sh::ContactStepOptions& o) { o.lcp.tolerance = 0.0; }), "lcp.tolerance");
  EXPECT_EQ(parameter_of([&] { sh::step_with_obstacles(f.model, state, 0.0, {f.plane}); }), "h");
  sh::DynamicState wrong = state;
  wrong.q = VecX::Zero(3);
  EXPECT_EQ(parameter_of([&] { sh::step_with_obstacles(f.model, wrong, 0.01, {f.plane}); }), "state");
}

}  // namespace
