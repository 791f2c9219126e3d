// The nodal 3-D rod (solvers/rod3d): exact derivatives against finite differences, frame
// invariance, static equilibria against closed forms, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/testing/input_error.hpp"
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

// Distributed dead loads (a manufactured solution's): a force on every vertex and a moment on every edge, the
// moments' virtual-work couples depending on the edges (unsymmetric, like the tip moment's).
rod::RodModel model_with_distributed_loads(std::size_t n, bool inextensible) {
  auto model = general_model(n, inextensible);
  for (std::size_t i = 0; i <= n; ++i)
    model.vertex_forces.push_back(Vec3(0.3 * std::sin(double(i)), -0.2 + 0.05 * double(i), 0.4 * std::cos(double(i))));
  for (std::size_t j = 0; j < n; ++j)
    model.edge_moments.push_back(Vec3(0.25 * std::cos(1.3 * double(j)), 0.5 - 0.1 * double(j), -0.35 * std::sin(double(j) + 0.2)));
  return model;
}

TEST(Rod3dEnergy, JacobianIsTheDerivativeOfTheResidualWithDistributedLoads) {
  expect_jacobian_matches(model_with_distributed_loads(6, true));
  expect_jacobian_matches(model_with_distributed_loads(5, false));
}

// The same loads through the two interfaces give the same residual: the tip edge's moment as end_moment or
// as the last edge moment, the tip force as end_force or as the last vertex force; and the vertex forces'
// potential is in the energy (the residual of an extensible rod with them alone is its gradient).
TEST(Rod3dLoads, EdgeMomentsAndVertexForcesAreTheEndLoadsOnEveryEdge) {
  auto ends = general_model(6, true);
  ends.end_moment = Vec3(0.3, -0.8, 0.45);
  auto distributed = ends;
  distributed.end_moment = Vec3::Zero();
  distributed.edge_moments.assign(6, Vec3::Zero());
  distributed.edge_moments.back() = ends.end_moment;
  distributed.end_force = Vec3::Zero();
  distributed.vertex_forces.assign(7, Vec3::Zero());
  distributed.vertex_forces.back() = ends.end_force;
  const auto state = general_state(ends);
  EXPECT_EQ((rod::static_residual(ends, state, 0.7) - rod::static_residual(distributed, state, 0.7)).cwiseAbs().maxCoeff(), 0.0);
  auto forces_only = general_model(7, false);
  for (std::size_t i = 0; i <= 7; ++i) forces_only.vertex_forces.push_back(Vec3(0.2 * double(i), -0.3, 0.1 * std::sin(double(i))));
  const auto state7 = general_state(forces_only);
  const rod::DofLayout layout(forces_only);
  const VecX r = rod::static_residual(forces_only, state7, 1.0);
  const double h = 1e-5 * forces_only.length;
  double worst = 0.0;
  for (std::size_t k = 0; k < layout.size(); ++k) {
    const double plus = rod::energy(forces_only, rod::displaced(forces_only, state7, unit(layout.size(), k, h))).potential();
    const double minus = rod::energy(forces_only, rod::displaced(forces_only, state7, unit(layout.size(), k, -h))).potential();
    worst = std::max(worst, std::abs((plus - minus) / (2.0 * h) - r[Eigen::Index(k)]));
  }
  EXPECT_LT(worst, 1e-8 * r.cwiseAbs().maxCoeff());
}

TEST(Rod3dLoads, DistributedLoadsOfTheWrongSizeAreRefused) {
  auto model = general_model(6, true);
  model.vertex_forces.assign(6, Vec3::Zero());  // one per vertex is 7
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([&] { rod::validate(model); }), "vertex_forces");
  model = general_model(6, true);
  model.edge_moments.assign(7, Vec3::Zero());
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([&] { rod::validate(model); }), "edge_moments");
  model.edge_moments.assign(6, Vec3(0.0, std::nan(""), 0.0));
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([&] { rod::validate(model); }), "edge_moments[1]");
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

// The statics is free of units: the Mattiasson cantilever with stiffness x mu and length x lambda (the
// load following, P = 2 EI / L^2) converges to the same dimensionless tip, (tip - root) / L, at any
// (lambda, mu), Newton's line search and pseudo-transient continuation alike. Before the KKT system
// was solved in the problem's units (rows over force, moment and length scales, columns times L, 1 and
// the force scale), EI = 1e9 or 1e12 or L = 1e-3 stopped the load continuation part way (a bare 1 on a
// held dof's diagonal among entries of EI / L^3 steered the LU's pivoting).
TEST(Rod3dStatics, EquilibriumIsTheSameInAnyUnits) {
  const auto dimensionless_tip = [](double lambda, double mu, bool pseudo_transient) {
    rod::RodModel model;
    model.elements = 24;
    model.length = 1.3 * lambda;
    model.stiffness = Vec3(0.8, 1.7, 4.4) * mu * lambda * lambda;
    model.root.support = rod::EndSupport::Clamped;
    model.root.frame = tilted_frame(0.7);
    model.root.position = Vec3(0.2, 0.4, -0.1) * lambda;
    model.end_force = 2.0 * model.stiffness[1] / (model.length * model.length) * model.root.frame.col(2);
    rod::StaticOptions options;
    options.load_steps = pseudo_transient ? 1 : 4;
    options.pseudo_transient = pseudo_transient;
    options.max_iterations = 200;
    options.tolerance = 1e-12;
    const auto result = rod::solve_static(model, rod::make_straight_state(model), options);
    return Vec3((rod::make_solution(model, result.state).vertex_position.back() - model.root.position) /
                model.length);
  };
  for (bool pseudo_transient : {false, true}) {
    const Vec3 unit = dimensionless_tip(1.0, 1.0, pseudo_transient);
    for (const auto& [lambda, mu] : {std::pair{1.0, 1e12}, std::pair{1.0, 1e9}, std::pair{1e-3, 1.0},
                                     std::pair{1e3, 1e-6}, std::pair{1e-2, 1e6}}) {
      const Vec3 scaled = dimensionless_tip(lambda, mu, pseudo_transient);
      EXPECT_LE((scaled - unit).norm(), 1e-10) << lambda << " " << mu << " " << pseudo_transient;
    }
  }
}

// Pseudo-transient continuation reaches the same equilibrium as the Newton line search, in one
// load step from the straight rod (the line search needs four): the regularisation D / tau only
// changes the path, and the last steps, at tau = 1e6, are Newton steps to the tolerance.
TEST(Rod3dStatics, PseudoTransientContinuationFindsTheSameEquilibrium) {
  rod::RodModel model;
  model.elements = 32;
  model.length = 1.3;
  model.stiffness = Vec3(0.8, 1.7, 4.4);
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = tilted_frame(0.7);
  model.end_force = 2.0 * model.stiffness[1] / (model.length * model.length) * model.root.frame.col(2);
  rod::StaticOptions newton;
  newton.load_steps = 4;
  newton.tolerance = 1e-12;
  rod::StaticOptions relaxed = newton;
  relaxed.load_steps = 1;
  relaxed.pseudo_transient = true;
  relaxed.max_iterations = 500;
  const auto a = rod::solve_static(model, rod::make_straight_state(model), newton);
  const auto b = rod::solve_static(model, rod::make_straight_state(model), relaxed);
  double largest = 0.0;
  for (std::size_t i = 0; i <= model.elements; ++i)
    largest = std::max(largest, (a.state.position[i] - b.state.position[i]).norm());
  // Both at residual 1e-12 of the force scale EI/L^2 on a rod whose softest stiffness is ~EI/L^3:
  // positions agree to ~1e-12 L; 1e-9 L leaves room for the conditioning of the bent cantilever.
  EXPECT_LE(largest, 1e-9 * model.length);
  rod::StaticOptions bad = relaxed;
  bad.initial_pseudo_time = 0.0;
  try {
    rod::solve_static(model, rod::make_straight_state(model), bad);
    FAIL();
  } catch (const rodvv::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("initial_pseudo_time"), std::string::npos) << e.what();
  }
}

// A sliding clamp (model.hpp: EndCondition::slides) keeps its edge's tangent and frame and its
// transverse position but not its place along the axis: with the tip clamp moved sideways by y0 and
// a dead pull T along the axis, the rod bends into an S between the clamps, the tip slides in (the span
// along the axis shortens), and the axial force at the tip edge is the dead pull, T; a fixed clamp at
// the same place instead carries whatever axial reaction its fixed span needs.
TEST(Rod3dStatics, SlidingClampTakesTheDeadPullAndSlides) {
  rod::RodModel model;
  model.elements = 64;
  model.length = 2.1;
  model.stiffness = Vec3(0.8, 1.7, 1.3);
  model.root.support = rod::EndSupport::Clamped;
  model.tip.support = rod::EndSupport::Clamped;
  model.tip.slides = true;
  model.tip.position = Vec3(model.length, 0.0, 0.0);
  const double T = 2.5, y0 = 0.3;
  model.end_force = Vec3(T, 0.0, 0.0);
  rod::StaticOptions options;
  options.load_steps = 4;
  options.tolerance = 1e-12;
  rod::RodModel moved = model;
  moved.tip.position = Vec3(model.length, y0, 0.0);
  const auto result = rod::solve_static(moved, rod::make_straight_state(moved), options);
  const auto& x = result.state.position;
  const std::size_t n = model.elements;
  EXPECT_NEAR(x[n].y(), y0, 1e-14);                   // transverse position held
  EXPECT_NEAR(x[n - 1].y(), y0, 1e-14);               // and the tangent along e_x
  EXPECT_LT(x[n].x(), model.length - 1e-3);           // slid in: the S needs arclength
  // Edge n - 1's multiplier is its axial force n.t = T (e_x.t = 1): the dead pull, to the Newton tolerance.
  EXPECT_NEAR(result.state.multiplier[n - 1], T, 1e-9 * T);
  rod::RodModel fixed = moved;
  fixed.tip.slides = false;
  fixed.tip.position = Vec3(0.5 * (x[n] + x[n - 1]).x() - 0.01, y0, 0.0);  // a shorter fixed span
  const auto clamped = rod::solve_static(fixed, rod::make_straight_state(fixed), options);
  EXPECT_GT(std::abs(clamped.state.multiplier[n - 1] - T), 1e-3 * T);
  // Bad input: a sliding pin, and a sliding clamp whose tangent is no coordinate axis.
  rod::RodModel bad = model;
  bad.tip.support = rod::EndSupport::Pinned;
  EXPECT_THROW(rod::validate(bad), rodvv::InputError);
  bad = model;
  bad.tip.frame = tilted_frame(0.3);
  try {
    rod::validate(bad);
    FAIL();
  } catch (const rodvv::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tip.slides"), std::string::npos) << e.what();
  }
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

// ---- second-order jets and the stencil derivatives -------------------------------------------------
// (solvers/rod3d/taylor2.hpp and discrete_energy.cpp.) Included here, at the end, because these
// tests were appended to the file: the private jet header (not in the public include directory) and
// Eigen's AutoDiffScalar for the previous implementation of the stencil derivatives, kept below as
// the reference.
#include <array>

#include <unsupported/Eigen/AutoDiff>

#include "../../solvers/rod3d/taylor2.hpp"

namespace rodvv::solvers::rod3d::detail {
// Test hook defined in solvers/rod3d/discrete_energy.cpp (not public API): gradient and, for order 2,
// Hessian of the bending-twisting energy of interior vertex `vertex`'s stencil (x_{i-1}, theta^{i-1},
// x_i, theta^i, x_{i+1}) at base + dz in the chart of base, by the production jets of that order.
void stencil_derivatives_for_testing(const RodModel& model, const RodState& base, const VecX& dz, std::size_t vertex,
                                     int order, VecX& gradient, Eigen::MatrixXd& hessian);
}  // namespace rodvv::solvers::rod3d::detail

namespace {

namespace t2 = rodvv::solvers::rod3d::taylor2;

// A function of 4 variables using every jet operation: jet +, -, *, / jet; unary -; jet +, -, *, /
// double and double +, -, *, / jet; sqrt, sin, cos, asin; and a 2-variable sub-computation lifted
// into the 4 variables (staging).
template <int Order>
t2::Jet<4, Order> all_operations(const std::array<double, 4>& w) {
  using J = t2::Jet<4, Order>;
  using J2 = t2::Jet<2, Order>;
  const J x = J::variable(w[0], 0), y = J::variable(w[1], 1), z = J::variable(w[2], 2), u = J::variable(w[3], 3);
  const J2 zs = J2::variable(w[2], 0), us = J2::variable(w[3], 1);
  const J lifted = t2::lift<4>(sqrt(2.0 + zs * us) - us / zs, 2);  // a function of (z, u) only
  return sin(x * y) / (2.0 + cos(z)) + sqrt(1.5 + x * x + u * u) * asin(0.3 * y - z * 0.2) - u / x + 3.0 -
         (2.0 - y) * z + 0.5 / (1.0 + u * u) - (-x) * 0.7 + (x - 1.0) / 4.0 + lifted * y;
}

TEST(Rod3dJets, DerivativesOfEveryOperationMatchCentralDifferences) {
  const std::array<double, 4> w0{0.7, -0.4, 1.1, 0.3};
  const auto f = all_operations<2>(w0);
  const auto f1 = all_operations<1>(w0);
  // The first-order jet runs the same value and gradient arithmetic as the second-order one.
  EXPECT_EQ(f1.v, f.v);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(f1.g[std::size_t(i)], f.g[std::size_t(i)]) << i;
  // Central differences of step h: truncation h^2 |f'''| / 6 and round-off eps |f| / h. Here |f| ~ 5
  // and the third derivatives are below ~50 (the steepest term, u / x at x = 0.7, has 6 u / x^4 ~ 7),
  // so h = 1e-5 gives ~1e-9 + ~1e-10 on derivatives of size ~1 - 10; the bound 1e-7 (relative to
  // the largest derivative, at least 1) leaves a factor ~100. The Hessian is checked the same way
  // against differences of the (exact, first-order) gradient.
  const double h = 1e-5;
  double grad_scale = 1.0, hess_scale = 1.0;
  for (int i = 0; i < 4; ++i) {
    grad_scale = std::max(grad_scale, std::abs(f.g[std::size_t(i)]));
    for (int j = 0; j < 4; ++j) hess_scale = std::max(hess_scale, std::abs(f.hessian(i, j)));
  }
  double grad_error = 0.0, hess_error = 0.0;
  for (int k = 0; k < 4; ++k) {
    auto plus = w0, minus = w0;
    plus[std::size_t(k)] += h;
    minus[std::size_t(k)] -= h;
    const auto fp = all_operations<1>(plus), fm = all_operations<1>(minus);
    grad_error = std::max(grad_error, std::abs((fp.v - fm.v) / (2.0 * h) - f.g[std::size_t(k)]));
    for (int i = 0; i < 4; ++i)
      hess_error = std::max(hess_error,
                            std::abs((fp.g[std::size_t(i)] - fm.g[std::size_t(i)]) / (2.0 * h) - f.hessian(i, k)));
  }
  EXPECT_LT(grad_error, 1e-7 * grad_scale) << "gradient error " << grad_error << " of scale " << grad_scale;
  EXPECT_LT(hess_error, 1e-7 * hess_scale) << "Hessian error " << hess_error << " of scale " << hess_scale;
  // A product of two independent variables has the exact Hessian [[0, 1], [1, 0]], and a lifted jet
  // has no derivatives outside its variables.
  using J2 = t2::Jet<2>;
  const auto xy = J2::variable(0.3, 0) * J2::variable(-1.7, 1);
  EXPECT_EQ(xy.hessian(0, 0), 0.0);
  EXPECT_EQ(xy.hessian(1, 0), 1.0);
  EXPECT_EQ(xy.hessian(0, 1), 1.0);
  EXPECT_EQ(xy.hessian(1, 1), 0.0);
  const auto lifted = t2::lift<5>(xy, 2);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(lifted.g[std::size_t(i)], i == 2 ? -1.7 : i == 3 ? 0.3 : 0.0) << i;
    for (int j = 0; j < 5; ++j)
      EXPECT_EQ(lifted.hessian(i, j), (i == 2 && j == 3) || (i == 3 && j == 2) ? 1.0 : 0.0) << i << ", " << j;
  }
}

// The previous implementation of the stencil derivatives, verbatim (it was discrete_energy.cpp up
// to the jets): the stencil energy differentiated twice by nested Eigen AutoDiffScalar over the 11
// stencil dofs - an independent reference for the jets, the staging and the reduced variables.
namespace previous {

constexpr int kStencil = 11;  // x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}
using StencilVector = Eigen::Matrix<double, kStencil, 1>;
using StencilMatrix = Eigen::Matrix<double, kStencil, kStencil>;
using Inner = Eigen::AutoDiffScalar<StencilVector>;
using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, kStencil, 1>>;
template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;

struct VertexStencil {
  Vec3 t_prev, a_prev, t_next, a_next;  // tangents and reference directors of edges i-1, i
  double reference_twist = 0.0;
};

template <typename T>
V3<T> transport(const V3<T>& from, const V3<T>& to, const V3<T>& v) {
  const V3<T> b = from.cross(to);
  const T c = from.dot(to);
  return c * v + b.cross(v) + (b.dot(v) / (T(1.0) + c)) * b;
}

template <typename T>
V3<T> constant_vector(const Vec3& v) {
  return V3<T>(T(v[0]), T(v[1]), T(v[2]));
}

template <typename T>
V3<T> stencil_strain(const Eigen::Matrix<T, kStencil, 1>& z, const VertexStencil& st) {
  using std::asin;
  using std::cos;
  using std::sin;
  const V3<T> x0 = z.template segment<3>(0), x1 = z.template segment<3>(4), x2 = z.template segment<3>(8);
  const T th0 = z[3], th1 = z[7];
  const V3<T> e = x1 - x0, f = x2 - x1;
  const V3<T> te = e / e.norm(), tf = f / f.norm();
  const V3<T> ae = transport<T>(constant_vector<T>(st.t_prev), te, constant_vector<T>(st.a_prev));
  const V3<T> af = transport<T>(constant_vector<T>(st.t_next), tf, constant_vector<T>(st.a_next));
  const V3<T> be = te.cross(ae), bf = tf.cross(af);
  const T ce = cos(th0), se = sin(th0), cf = cos(th1), sf = sin(th1);
  const V3<T> m1 = ce * ae + se * be + cf * af + sf * bf;
  const V3<T> m2 = ce * be - se * ae + cf * bf - sf * af;
  const V3<T> kb = (T(2.0) / (T(1.0) + te.dot(tf))) * te.cross(tf);
  const T c0 = T(std::cos(st.reference_twist)), s0 = T(std::sin(st.reference_twist));
  const V3<T> p = transport<T>(te, tf, ae);
  const V3<T> p_turned = c0 * p + s0 * tf.cross(p);
  const T twist = th1 - th0 + T(st.reference_twist) + asin(p_turned.cross(af).dot(tf));
  return V3<T>(twist, T(0.5) * kb.dot(m1), T(0.5) * kb.dot(m2));
}

template <typename T>
T stencil_energy(const Eigen::Matrix<T, kStencil, 1>& z, const VertexStencil& st, const Vec3& stiffness,
                 const Vec3& natural_integrated, double voronoi) {
  const V3<T> k = stencil_strain<T>(z, st);
  T energy(0.0);
  for (int a = 0; a < 3; ++a) {
    const T d = k[a] - T(natural_integrated[a]);
    energy += T(0.5 * stiffness[a] / voronoi) * d * d;
  }
  return energy;
}

// Gradient and Hessian of vertex i's stencil energy at base + dz in base's chart (the inputs as
// discrete_energy.cpp's Context assembles them).
void derivatives(const rod::RodModel& model, const rod::RodState& base, const VecX& dz, std::size_t i,
                 StencilVector& gradient, StencilMatrix& hessian) {
  const rod::DofLayout layout(model);
  const auto tangent = rod::edge_tangents(base);
  const VertexStencil st{tangent[i - 1], base.reference_director[i - 1], tangent[i], base.reference_director[i],
                         base.reference_twist[i]};
  StencilVector z0;
  for (int k = 0; k < 3; ++k) {
    z0[k] = base.position[i - 1][k] + dz[Eigen::Index(layout.vertex(i - 1)) + k];
    z0[4 + k] = base.position[i][k] + dz[Eigen::Index(layout.vertex(i)) + k];
    z0[8 + k] = base.position[i + 1][k] + dz[Eigen::Index(layout.vertex(i + 1)) + k];
  }
  z0[3] = base.angle[i - 1] + dz[Eigen::Index(layout.angle(i - 1))];
  z0[7] = base.angle[i] + dz[Eigen::Index(layout.angle(i))];
  const double ell = rod::rest_edge_length(model);
  Eigen::Matrix<Outer, kStencil, 1> z;
  for (int k = 0; k < kStencil; ++k) {
    z[k].value() = Inner(z0[k], kStencil, k);
    z[k].derivatives() = Eigen::Matrix<Inner, kStencil, 1>::Constant(Inner(0.0));
    z[k].derivatives()[k] = Inner(1.0);
  }
  const Outer e = stencil_energy<Outer>(z, st, model.stiffness, model.natural_strain * ell, ell);
  gradient = e.value().derivatives();
  for (int a = 0; a < kStencil; ++a) hessian.row(a) = e.derivatives()[a].derivatives().transpose();
}

}  // namespace previous

// A smooth displacement of every dof (positions by ~3% of L, angles by ~0.1): the stencils are then
// evaluated away from the chart's base, where the transported frames and the reference twist's
// increment are non-trivial.
VecX smooth_displacement(const rod::RodModel& model) {
  const rod::DofLayout layout(model);
  VecX dz = VecX::Zero(Eigen::Index(layout.size()));
  for (Eigen::Index k = 0; k < dz.size(); ++k) dz[k] = 0.03 * model.length * std::sin(1.7 * double(k) + 0.4);
  for (std::size_t j = 0; j < model.elements; ++j)
    dz[Eigen::Index(layout.angle(j))] = 0.1 * std::cos(0.9 * double(j) + 0.2);
  return dz;
}

// The jets' stencil gradient and Hessian equal the previous nested-AutoDiff ones up to round-off:
// both are exact, and differ only in the order of a few hundred floating-point operations on O(1)
// numbers (observed ~1e-15 relative), so 1e-12 relative to the largest entry leaves a wide margin
// while any wrong term (a sign, a missing second-order cross term, a wrong reduced-variable index)
// would show at O(1).
void expect_stencils_match_previous(const rod::RodModel& model, const VecX& dz) {
  const auto state = general_state(model);
  double worst_g = 0.0, worst_h = 0.0, worst_g1 = 0.0;
  for (std::size_t i = 1; i < model.elements; ++i) {
    previous::StencilVector g_ref;
    previous::StencilMatrix h_ref;
    previous::derivatives(model, state, dz, i, g_ref, h_ref);
    VecX g, g1;
    Eigen::MatrixXd h, none;
    rod::detail::stencil_derivatives_for_testing(model, state, dz, i, 2, g, h);
    rod::detail::stencil_derivatives_for_testing(model, state, dz, i, 1, g1, none);
    ASSERT_EQ(h.rows(), 11);
    ASSERT_EQ(none.size(), 0);
    worst_g = std::max(worst_g, (g - g_ref).cwiseAbs().maxCoeff() / g_ref.cwiseAbs().maxCoeff());
    worst_h = std::max(worst_h, (h - h_ref).cwiseAbs().maxCoeff() / h_ref.cwiseAbs().maxCoeff());
    worst_g1 = std::max(worst_g1, (g1 - g).cwiseAbs().maxCoeff() / g.cwiseAbs().maxCoeff());
    EXPECT_EQ(h, h.transpose()) << "vertex " << i << ": the jets' Hessian is symmetric by construction";
  }
  EXPECT_LE(worst_g, 1e-12) << "largest relative gradient difference " << worst_g;
  EXPECT_LE(worst_h, 1e-12) << "largest relative Hessian difference " << worst_h;
  // First- and second-order jets run the same value and gradient arithmetic.
  EXPECT_LE(worst_g1, 4 * kEps) << "largest relative difference of the first-order gradient " << worst_g1;
}

TEST(Rod3dEnergy, StencilHessianMatchesThePreviousNestedAutoDiffAtTheBase) {
  const auto model = general_model(7, false);
  expect_stencils_match_previous(model, VecX::Zero(Eigen::Index(rod::DofLayout(model).size())));
}

TEST(Rod3dEnergy, StencilHessianMatchesThePreviousNestedAutoDiffAwayFromTheBase) {
  const auto model = general_model(7, true);
  expect_stencils_match_previous(model, smooth_displacement(model));
}

// The stencil Hessian is the derivative of the stencil gradient (both from the jets) in the chart
// of the base, at a displaced configuration.
TEST(Rod3dEnergy, StencilHessianIsTheDerivativeOfTheStencilGradient) {
  const auto model = general_model(6, false);
  const auto state = general_state(model);
  const rod::DofLayout layout(model);
  const VecX dz = smooth_displacement(model);
  const std::size_t i = 3;
  VecX g;
  Eigen::MatrixXd h, none;
  rod::detail::stencil_derivatives_for_testing(model, state, dz, i, 2, g, h);
  // The stencil dofs' places in the global dz (DofLayout).
  std::array<std::size_t, 11> index{};
  for (std::size_t k = 0; k < 3; ++k) {
    index[k] = layout.vertex(i - 1) + k;
    index[4 + k] = layout.vertex(i) + k;
    index[8 + k] = layout.vertex(i + 1) + k;
  }
  index[3] = layout.angle(i - 1);
  index[7] = layout.angle(i);
  // Central differences as in JacobianIsTheDerivativeOfTheResidual: h^2 g''' / 6 + eps g / h with
  // h = 1e-5 L, ~1e-10 relative; the bound 1e-7 relative to the largest Hessian entry.
  const double step = 1e-5 * model.length;
  double worst = 0.0;
  for (int k = 0; k < 11; ++k) {
    VecX plus = dz, minus = dz;
    plus[Eigen::Index(index[std::size_t(k)])] += step;
    minus[Eigen::Index(index[std::size_t(k)])] -= step;
    VecX gp, gm;
    rod::detail::stencil_derivatives_for_testing(model, state, plus, i, 1, gp, none);
    rod::detail::stencil_derivatives_for_testing(model, state, minus, i, 1, gm, none);
    worst = std::max(worst, ((gp - gm) / (2.0 * step) - h.col(k)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-7 * h.cwiseAbs().maxCoeff()) << "largest Hessian error " << worst;
}

}  // namespace
