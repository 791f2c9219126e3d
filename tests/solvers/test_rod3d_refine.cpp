// Nested iteration on the nodal 3-D rod (solvers/rod3d/refine.hpp): a coarse state carried over to a
// finer rod reproduces a smooth twisted rod at the interpolation's orders, returns a state unchanged at
// its own resolution, and starts a fine statics solve next to its equilibrium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/harness/order_fit.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/refine.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"
#include "rodvv/testing/input_error.hpp"

namespace {

namespace rod = rodvv::solvers::rod3d;
using rodvv::Vec3;

// A clamped-root, free-tip rod of length 1.7 in n edges.
rod::RodModel rod_model(std::size_t n) {
  rod::RodModel model;
  model.elements = n;
  model.length = 1.7;
  model.stiffness = Vec3(0.61, 1.3, 2.1);
  model.root.support = rod::EndSupport::Clamped;
  return model;
}

// The smooth rod the tests discretise, in arclength s: a unit-speed helix (radius 0.5, 1.2 rad per unit
// length, pitch rate 0.8) and a material angle from the space-parallel transport that turns through
// more than a full turn over the rod (4 rad per unit length plus a wobble), so that an angle carried
// over modulo 2 pi would show.
Vec3 centreline(double s) { return Vec3(0.5 * std::cos(1.2 * s), 0.5 * std::sin(1.2 * s), 0.8 * s); }
double material_angle(double s) { return 4.0 * s + 0.8 * std::sin(2.1 * s); }

// The rod of `model` sampled from the smooth one: vertices on the centreline at their rest arclengths,
// the first material director normal to edge 0 (whose midpoint is s = 0, where the chord's direction is
// the tangent's to O(ebar^2)), the angles at the edges' midpoints, multipliers a linear function of s.
rod::RodState sampled_state(const rod::RodModel& model) {
  std::vector<Vec3> x(model.elements + 1);
  for (std::size_t i = 0; i <= model.elements; ++i) x[i] = centreline(rod::vertex_arclength(model, i));
  const Vec3 t0 = (x[1] - x[0]).normalized();
  const Vec3 m1 = t0.cross(Vec3(0.2, 0.1, 1.0)).normalized();
  std::vector<double> angles(model.elements);
  rod::RodState state;
  const double ebar = rod::rest_edge_length(model);
  for (std::size_t j = 0; j < angles.size(); ++j) angles[j] = material_angle(rod::vertex_arclength(model, j) + 0.5 * ebar);
  state = rod::make_state(x, m1, angles);
  state.multiplier.resize(model.elements);
  for (std::size_t j = 0; j < angles.size(); ++j)
    state.multiplier[j] = 2.5 - 0.7 * (rod::vertex_arclength(model, j) + 0.5 * ebar);
  return state;
}

struct Gaps {
  double position = 0.0, director = 0.0, multiplier = 0.0;
};

Gaps gaps(const rod::RodState& a, const rod::RodState& b) {
  Gaps g;
  for (std::size_t i = 0; i < a.position.size(); ++i) g.position = std::max(g.position, (a.position[i] - b.position[i]).norm());
  for (std::size_t j = 0; j < a.elements(); ++j) {
    g.director = std::max(g.director, (rod::material_frame(a, j).col(1) - rod::material_frame(b, j).col(1)).norm());
    g.multiplier = std::max(g.multiplier, std::abs(a.multiplier[j] - b.multiplier[j]));
  }
  return g;
}

// The least-squares order of errors at n = 32, 64, 128 edges (h = 1/n), by the harness's own fit.
double observed_order(const std::vector<double>& errors) {
  const std::vector<double> h{1.0 / 32, 1.0 / 64, 1.0 / 128};
  const std::vector<std::optional<double>> e(errors.begin(), errors.end());
  return rodvv::harness::fit_order(h, e, 3).least_squares.value_or(std::nan(""));
}

// Refining the coarse rod of n edges to 4n + 3 (not a multiple: the fine vertices fall anywhere in the
// coarse edges) against the fine rod sampled directly. The Hermite interpolant with Catmull-Rom tangents
// is O(ebar^3) in position (its tangents carry O(ebar^2)); the frames carry the two polylines' different
// parallel transports, O(ebar^2), which the interpolation's O(ebar^3) hides on coarse rods. Measured at
// n = 8, 16, 32, 64, 128: positions 6.4e-4, 7.3e-5, 8.6e-6, 1.1e-6, 1.3e-7 (pairwise orders 3.15, 3.07,
// 3.04, 3.02), directors 1.9e-2, 2.5e-3, 4.3e-4, 9.7e-5, 2.4e-5 (2.96, 2.52, 2.15, 2.03). Fitted over the
// asymptotic 32 .. 128; bounds at twice the finest level's.
TEST(Rod3dRefine, ASmoothTwistedRodIsReproducedAtThirdOrderInPositionAndSecondInFrames) {
  std::vector<double> position, director, multiplier;
  for (std::size_t n : {32, 64, 128}) {
    const rod::RodModel coarse = rod_model(n), fine = rod_model(4 * n + 3);
    const Gaps g = gaps(rod::refine_state(coarse, sampled_state(coarse), fine), sampled_state(fine));
    position.push_back(g.position);
    director.push_back(g.director);
    multiplier.push_back(g.multiplier);
  }
  EXPECT_NEAR(observed_order(position), 3.0, 0.25) << position[0] << " " << position[1] << " " << position[2];
  EXPECT_NEAR(observed_order(director), 2.0, 0.25) << director[0] << " " << director[1] << " " << director[2];
  EXPECT_LE(position.back(), 2.0 * 1.3e-7);
  EXPECT_LE(director.back(), 2.0 * 2.4e-5);
  // Linear multipliers are reproduced: the interpolant is exact for quadratics.
  for (double gap : multiplier) EXPECT_LE(gap, 1e-14);
}

// At its own resolution the interpolant takes the vertices themselves (bit for bit: a fine vertex within
// 1e-12 edge of a coarse one is that vertex) and the frames to
// round-off (the angles are re-accumulated: 64 eps per edge over 24 edges).
TEST(Rod3dRefine, RefiningToTheSameResolutionReturnsTheState) {
  const rod::RodModel model = rod_model(24);
  const rod::RodState state = sampled_state(model);
  const rod::RodState same = rod::refine_state(model, state, model);
  for (std::size_t i = 0; i < state.position.size(); ++i) EXPECT_EQ(same.position[i], state.position[i]) << i;
  const Gaps g = gaps(same, state);
  EXPECT_LE(g.director, 64.0 * 24 * 2.220446049250313e-16);
  EXPECT_LE(g.multiplier, 1e-14);
}

// What nested iteration is for: the refined equilibrium of a coarse rod is within the discretisation
// error of the fine one, where Newton converges quadratically. A 3-D cantilever (anisotropic, tilted
// clamp, dead tip force out of every principal plane), 12 edges refined to 48: measured 5 Newton
// iterations in one load step against 20 from the straight rod in 4, and the same equilibrium.
TEST(Rod3dRefine, ARefinedEquilibriumStartsTheFineSolveNextToItsEquilibrium) {
  const auto cantilever = [](std::size_t n) {
    rod::RodModel model = rod_model(n);
    model.root.frame = Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
    model.end_force = Vec3(0.9, -1.4, 0.6);
    return model;
  };
  rod::StaticOptions options;
  options.load_steps = 4;
  options.tolerance = 1e-12;
  const rod::RodModel coarse = cantilever(12), fine = cantilever(48);
  const auto coarse_equilibrium = rod::solve_static(coarse, rod::make_straight_state(coarse), options);
  const auto direct = rod::solve_static(fine, rod::make_straight_state(fine), options);
  options.load_steps = 1;
  const auto nested = rod::solve_static(fine, rod::refine_state(coarse, coarse_equilibrium.state, fine), options);
  EXPECT_LE(nested.iterations, 6u) << "direct: " << direct.iterations;
  EXPECT_GT(direct.iterations, 2 * nested.iterations);
  double gap = 0.0;
  for (std::size_t i = 0; i <= fine.elements; ++i)
    gap = std::max(gap, (nested.state.position[i] - direct.state.position[i]).norm());
  // Both at residual 1e-12 of the force scale (the test of PseudoTransientContinuationFindsTheSameEquilibrium).
  EXPECT_LE(gap, 1e-9 * fine.length);
}

TEST(Rod3dRefine, BadInputNamesTheParameter) {
  using rodvv::testing::input_error_parameter_of;
  const rod::RodModel model = rod_model(16);
  const rod::RodState state = sampled_state(model);
  EXPECT_EQ(input_error_parameter_of([&] { rod::refine_state(model, state, rod_model(15)); }), "fine_model");
  rod::RodModel longer = rod_model(32);
  longer.length = 1.8;
  EXPECT_EQ(input_error_parameter_of([&] { rod::refine_state(model, state, longer); }), "fine_model");
  rod::RodModel clamped_tip = rod_model(32);
  clamped_tip.tip.support = rod::EndSupport::Clamped;
  EXPECT_EQ(input_error_parameter_of([&] { rod::refine_state(model, state, clamped_tip); }), "fine_model");
  EXPECT_EQ(input_error_parameter_of([&] { rod::refine_state(rod_model(17), state, rod_model(32)); }), "coarse");
  const rod::RodModel two = rod_model(2);
  EXPECT_EQ(input_error_parameter_of([&] { rod::refine_state(two, sampled_state(two), rod_model(8)); }), "coarse");
  rod::RodState folded = state;
  folded.position[5] = folded.position[3];  // edge 4 runs back along edge 3
  EXPECT_EQ(input_error_parameter_of([&] { rod::refine_state(model, folded, rod_model(32)); }), "coarse");
}

}  // namespace
