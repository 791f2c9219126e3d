// The nodal 3-D rod (solvers/rod3d): exact derivatives against finite differences, frame
// invariance, static equilibria against closed forms, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/elastica.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace rod = rodvv::solvers::rod3d;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::VecX;
constexpr double kPi = std::numbers::pi;
constexpr double kEps = 2.220446049250313e-16;

Mat3 tilted_frame(double angle) {
  return Eigen::AngleAxisd(angle, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
}

// A curved, twisted rod with anisotropic stiffness, natural strains, gravity and a tip force: every
// term of the energy is active and no symmetry hides an index mistake.
rod::RodModel general_model(std::size_t n, bool inextensible) {
  rod::RodModel model;
  model.elements = n;
  model.length = 1.7;
  model.stiffness = Vec3(0.61, 1.3, 2.1);
  model.natural_strain = Vec3(0.4, -0.7, 1.1);
  if (!inextensible) model.extensional_stiffness = 45.0;
  model.line_density = 0.8;
  model.gravity = Vec3(0.3, -2.0, 0.7);
  model.end_force = Vec3(-0.4, 0.9, 0.25);
  return model;
}

rod::RodState general_state(const rod::RodModel& model) {
  std::vector<Vec3> x(model.elements + 1);
  const double ell = rod::rest_edge_length(model);
  for (std::size_t i = 0; i <= model.elements; ++i) {
    const double s = double(i) * ell;
    x[i] = Vec3(0.9 * std::cos(1.1 * s), 0.9 * std::sin(1.1 * s), 0.6 * s) + Vec3(0.01 * std::sin(7.0 * s), 0.0, 0.0);
  }
  const Vec3 t0 = (x[1] - x[0]).normalized();
  const Vec3 m1 = t0.cross(Vec3(0.2, 0.1, 1.0)).normalized();
  std::vector<double> angles(model.elements);
  for (std::size_t j = 0; j < angles.size(); ++j) angles[j] = 0.3 * std::sin(double(j) + 0.5);
  auto state = rod::make_state(x, m1, angles);
  if (rod::is_inextensible(model))
    for (std::size_t j = 0; j < model.elements; ++j) state.multiplier.push_back(0.7 - 0.1 * double(j));
  return state;
}

VecX unit(std::size_t size, std::size_t k, double h) {
  VecX dz = VecX::Zero(Eigen::Index(size));
  dz[Eigen::Index(k)] = h;
  return dz;
}

// The residual of an extensible rod with conservative loads is the gradient of the potential, the
// reference frames being transported along the variation (the DER chart).
TEST(Rod3dEnergy, GradientIsTheDerivativeOfThePotential) {
  const auto model = general_model(7, false);
  const auto state = general_state(model);
  const rod::DofLayout layout(model);
  const VecX r = rod::static_residual(model, state, 1.0);
  // Central differences: truncation h^2 E'''/6 ~ 1e-10 with h = 1e-5 L, round-off eps E/h ~ 1e-11.
  const double h = 1e-5 * model.length;
  double worst = 0.0, scale = r.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < layout.size(); ++k) {
    const double plus = rod::energy(model, rod::displaced(model, state, unit(layout.size(), k, h))).potential();
    const double minus = rod::energy(model, rod::displaced(model, state, unit(layout.size(), k, -h))).potential();
    worst = std::max(worst, std::abs((plus - minus) / (2.0 * h) - r[Eigen::Index(k)]));
  }
  EXPECT_LT(worst, 1e-8 * scale) << "largest gradient error " << worst << " of scale " << scale;
}

// The Jacobian is the derivative of the residual in the state's chart, for the inextensible KKT system with a dead tip
// moment (unsymmetric) as well as for the extensible rod.
void expect_jacobian_matches(const rod::RodModel& model) {
  const auto state = general_state(model);
  const rod::DofLayout layout(model);
  VecX r;
  Eigen::SparseMatrix<double> jacobian;
  rod::static_system(model, state, 1.0, r, jacobian);
  const Eigen::MatrixXd dense(jacobian);
  const double h = 1e-5 * model.length;
  double worst = 0.0;
  for (std::size_t k = 0; k < layout.size(); ++k) {
    const VecX plus = rod::chart_residual(model, state, unit(layout.size(), k, h), 1.0);
    const VecX minus = rod::chart_residual(model, state, unit(layout.size(), k, -h), 1.0);
    const VecX diff = (plus - minus) / (2.0 * h) - dense.col(Eigen::Index(k));
    const double e = diff.cwiseAbs().maxCoeff();
    worst = std::max(worst, e);
  }
  // Same step analysis as the gradient, one derivative higher: h^2 r'''/6 + eps r/h.
  EXPECT_LT(worst, 1e-7 * dense.cwiseAbs().maxCoeff()) << "largest Jacobian error " << worst;
}

TEST(Rod3dEnergy, JacobianIsTheDerivativeOfTheResidualExtensible) { expect_jacobian_matches(general_model(6, false)); }

TEST(Rod3dEnergy, JacobianIsTheDerivativeOfTheResidualInextensibleWithTipMoment) {
  auto model = general_model(6, true);
  model.end_moment = Vec3(0.3, -0.8, 0.45);
  expect_jacobian_matches(model);
}

// A rigid motion of the rod (positions and frames) leaves the elastic energy unchanged.
TEST(Rod3dEnergy, ElasticEnergyIsFrameIndifferent) {
  const auto model = general_model(9, false);
  const auto state = general_state(model);
  const Mat3 Q = tilted_frame(1.3);
  std::vector<Vec3> moved(state.position.size());
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = Q * state.position[i] + Vec3(3.0, -1.0, 2.0);
  const auto rotated = rod::make_state(moved, Q * state.reference_director[0], state.angle);
  const double e0 = rod::energy(model, state).elastic(), e1 = rod::energy(model, rotated).elastic();
  // A few hundred operations on O(1) values: 100 eps relative.
  EXPECT_TRUE(rodvv::testing::is_close(e1, e0, 100 * kEps, 0.0));
}

// The material frame turned by the same angle on every edge changes nothing but the bending axes:
// with EI1 = EI2 and no natural curvature, the energy is unchanged (a check that the twist of the
// reference frame is accounted for).
TEST(Rod3dEnergy, UniformMaterialRotationOfAnIsotropicRodIsFree) {
  auto model = general_model(9, false);
  model.stiffness = Vec3(0.61, 1.3, 1.3);
  model.natural_strain = Vec3(0.4, 0.0, 0.0);
  auto state = general_state(model);
  const double e0 = rod::energy(model, state).elastic();
  for (double& a : state.angle) a += 0.9;
  EXPECT_TRUE(rodvv::testing::is_close(rod::energy(model, state).elastic(), e0, 100 * kEps, 0.0));
}

// A twisted straight rod: uniform twist angle phi over length L stores GJ phi^2 / (2 (L - ell))
// (the twist lives on the N - 1 interior vertices, Voronoi length ell each).
TEST(Rod3dEnergy, TwistEnergyOfAStraightRod) {
  rod::RodModel model;
  model.elements = 10;
  model.length = 2.5;
  model.stiffness = Vec3(0.7, 1.9, 3.1);
  auto state = rod::make_straight_state(model);
  const double phi = 2.3;
  for (std::size_t j = 0; j < model.elements; ++j) state.angle[j] = phi * double(j) / double(model.elements - 1);
  const double ell = rod::rest_edge_length(model);
  const double per_vertex = phi / double(model.elements - 1);
  const double expected = 0.5 * model.stiffness[0] * per_vertex * per_vertex / ell * double(model.elements - 1);
  EXPECT_TRUE(rodvv::testing::is_close(rod::energy(model, state).twisting, expected, 100 * kEps, 0.0));
  EXPECT_EQ(rod::energy(model, state).bending, 0.0);
}

// ---- statics -------------------------------------------------------------------------------------

struct TipError {
  double u, w;
};

// The Mattiasson cantilever (alpha = P L^2 / EI1 = 2) in a tilted frame, bending about m1.
TipError mattiasson_tip_error(std::size_t n) {
  rod::RodModel model;
  model.elements = n;
  model.length = 1.3;
  model.stiffness = Vec3(0.8, 1.7, 4.4);
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = tilted_frame(0.7);
  model.root.position = Vec3(0.2, 0.4, -0.1);
  const Vec3 t0 = model.root.frame.col(0), d = model.root.frame.col(2);
  const double P = 2.0 * model.stiffness[1] / (model.length * model.length);
  model.end_force = P * d;
  rod::StaticOptions options;
  options.load_steps = 4;
  options.tolerance = 1e-12;
  const auto result = rod::solve_static(model, rod::make_straight_state(model), options);
  const Vec3 tip = rod::make_solution(model, result.state).vertex_position.back() - model.root.position;
  const auto exact = rodvv::references::cantilever_tip({model.length, model.stiffness[1], P});
  return {std::abs((model.length - tip.dot(t0)) - exact.u), std::abs(tip.dot(d) - exact.w)};
}

TEST(Rod3dStatics, MattiassonCantileverConvergesAtSecondOrder) {
  const TipError coarse = mattiasson_tip_error(16), fine = mattiasson_tip_error(32), finer = mattiasson_tip_error(64);
  const double order_w = std::log2(fine.w / finer.w), order_u = std::log2(fine.u / finer.u);
  EXPECT_NEAR(order_w, 2.0, 0.1);
  EXPECT_NEAR(order_u, 2.0, 0.1);
  EXPECT_NEAR(std::log2(coarse.w / fine.w), 2.0, 0.15);
  // Magnitude: the polygon elastica's error constant is O(1) in L (measured 0.02 L h^-2 -> bound 1e-3 at N = 64).
  EXPECT_LT(finer.w, 1e-3);
}

TEST(Rod3dStatics, StraightRodUnderTensionStretchesByFOverEA) {
  rod::RodModel model;
  model.elements = 8;
  model.length = 2.0;
  model.extensional_stiffness = 150.0;
  model.root.support = rod::EndSupport::Pinned;  // a clamped end edge is the clamp: it does not stretch
  model.root.frame = tilted_frame(0.4);
  model.end_force = 3.0 * model.root.frame.col(0);
  const auto result = rod::solve_static(model, rod::make_straight_state(model));
  const double extension = (result.state.position.back() - result.state.position.front()).norm() - model.length;
  // Linear in the load for a straight bar: exact up to the Newton tolerance (1e-10 relative force).
  EXPECT_TRUE(rodvv::testing::is_close(extension, 3.0 * model.length / 150.0, 1e-9, 0.0));
}

TEST(Rod3dStatics, BadInputNamesTheParameter) {
  rod::RodModel model;
  model.elements = 1;
  EXPECT_THROW(rod::validate(model), rodvv::InputError);
  model.elements = 8;
  model.stiffness[2] = -1.0;
  try {
    rod::validate(model);
    FAIL();
  } catch (const rodvv::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("EI2"), std::string::npos) << e.what();
  }
  model.stiffness[2] = 1.0;
  model.tip.support = rod::EndSupport::Clamped;
  model.tip.rotation = std::nan("");
  EXPECT_THROW(rod::validate(model), rodvv::InputError);
  model.tip.rotation = 1e9;
  EXPECT_THROW(rod::validate(model), rodvv::InputError);
  model.tip.rotation = 0.0;
  model.tip.frame(0, 0) = 1.1;
  EXPECT_THROW(rod::validate(model), rodvv::InputError);
  model.tip = {};
  model.length = 0.0;
  EXPECT_THROW(rod::validate(model), rodvv::InputError);
}

}  // namespace
