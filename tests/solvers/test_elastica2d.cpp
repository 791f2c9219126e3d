// Tests of the planar discrete-rod solvers (solvers/include/rodvv/solvers/elastica2d/):
// arc geometry series, analytic gradient and Hessian of the discrete Lagrangian against finite
// differences, the pinned-pinned column (load and displacement control) with observed order, the
// straight state below the Euler load, the end-moment cantilever (arcs exact for any N), the
// Mattiasson cantilever with observed order, input validation and failure reporting.
// Reference values: PHYSICS.md §3.3 (90 deg row, mpmath, >= 14 quoted digits) and §3.5 (alpha = 1,
// mpmath at 40 digits, 15 quoted digits). The solver never sees them; only this test does.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/elastica2d/arc_geometry.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/elastica2d/continuation.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"
#include "rodvv/testing/elastica2d_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace e2 = rodvv::solvers::elastica2d;
using rodvv::testing::input_error_parameter_of;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
using rodvv::testing::observed_order;
using rodvv::testing::elastica2d::derivative_mismatch;
using rodvv::testing::elastica2d::name_of;
using rodvv::testing::elastica2d::pinned_column;
using rodvv::testing::elastica2d::random_state;
using rodvv::testing::elastica2d::tight;
using e2::Scheme;
using e2::Support;

constexpr double kPi = std::numbers::pi;

// PHYSICS.md §3.3, theta0 = 90 deg, L = EI = 1.
constexpr double kColumnLoad = 13.750371636041;     // P L^2 / EI
constexpr double kColumnMidDeflection = 0.38137988175091;  // y_M / L
constexpr double kColumnMidCurvature = 5.2441151085842;    // |kappa_M| L
constexpr double kColumnChord = 0.45694658104446;          // chord / L = 1 - 0.54305341895554
// PHYSICS.md §3.5, alpha = P L^2 / EI = 1.
constexpr double kMattiassonW = 0.301720773799814;
constexpr double kMattiassonU = 0.0564332362833769;
constexpr double kMattiassonTipAngle = 0.461351949711879;

const std::vector<std::size_t> kLevels{16, 32, 64, 128};

void print_errors(const std::string& what, const std::vector<double>& errors, double order) {
  std::printf("[ order    ] %-28s", what.c_str());
  for (std::size_t i = 0; i < errors.size(); ++i)
    std::printf(" N=%-4zu %.3e", kLevels[i], errors[i]);
  std::printf("  p = %.3f\n", order);
}

e2::InitialGuess first_mode(double amplitude) {
  e2::InitialGuess g;
  g.theta = [amplitude](double s) { return amplitude * std::cos(kPi * s); };
  return g;
}

// ------------------------------------------------------------------------------------------------
// Arc geometry

TEST(Elastica2dArcGeometry, SincSeriesAndClosedFormAgreeAcrossTheSwitch) {
  // Both branches against long double closed forms around |v| = 0.5, where the series ends and the
  // closed form (cancellation ~ eps / v^3 in the derivatives) begins: a few eps each.
  for (double v : {0.5 - 1e-9, 0.5, 0.5 + 1e-9, -0.5 + 1e-9, -0.5, 0.2, 0.05}) {
    const long double lv = v;
    const long double value = std::sin(lv) / lv;
    const long double first = (lv * std::cos(lv) - std::sin(lv)) / (lv * lv);
    const long double second = -value - 2.0L * first / lv;
    const auto a = e2::sinc_derivatives(v);
    EXPECT_TRUE(is_close(a.value, static_cast<double>(value), 0.0, 4 * kEpsilon)) << v;
    EXPECT_TRUE(is_close(a.first, static_cast<double>(first), 0.0, 16 * kEpsilon)) << v;
    EXPECT_TRUE(is_close(a.second, static_cast<double>(second), 0.0, 16 * kEpsilon)) << v;
  }
  const auto zero = e2::sinc_derivatives(0.0);
  EXPECT_EQ(zero.value, 1.0);
  EXPECT_EQ(zero.first, 0.0);
  EXPECT_TRUE(is_close(zero.second, -1.0 / 3.0, 2 * kEpsilon, 0.0));
  // Closed forms at v = 1.3 (far from the series region), and the series at 1e-9 against limits.
  const double v = 1.3;
  const auto s = e2::sinc_derivatives(v);
  EXPECT_TRUE(is_close(s.value, std::sin(v) / v, 4 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(s.first, (v * std::cos(v) - std::sin(v)) / (v * v), 16 * kEpsilon, 0.0));
  const auto tiny = e2::sinc_derivatives(1e-9);
  EXPECT_TRUE(is_close(tiny.first, -1e-9 / 3.0, 4 * kEpsilon, 0.0));
}

TEST(Elastica2dArcGeometry, DerivativesMatchCentralDifferences) {
  // Central differences with step d have truncation ~ d^2 |f'''| / 6 and round-off ~ eps / d;
  // d = cbrt(eps) balances them at ~ eps^(2/3) = 3.7e-11; tolerance 100x that.
  const double d = std::cbrt(kEpsilon);
  const double tol = 100 * d * d;
  for (double v : {-2.0, -0.49, -0.1, 1e-4, 0.3, 0.51, 1.0, 3.0}) {
    const auto c = e2::sinc_derivatives(v);
    const auto p = e2::sinc_derivatives(v + d), m = e2::sinc_derivatives(v - d);
    EXPECT_TRUE(is_close(c.first, (p.value - m.value) / (2 * d), 0.0, tol)) << v;
    EXPECT_TRUE(is_close(c.second, (p.first - m.first) / (2 * d), 0.0, tol)) << v;
  }
}

// ------------------------------------------------------------------------------------------------
// Banded LU

TEST(Elastica2dBandedLU, SolvesAKktMatrixLikeDenseLu) {
  // A real KKT matrix (zero diagonal on the multipliers, so pivoting is needed) and a random band
  // matrix: the solution must match Eigen's dense partial-pivoting LU to ~cond * eps.
  e2::DiscreteLagrangian lag(pinned_column(13.0), {Scheme::Arcs, 12});
  Eigen::VectorXd z = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(lag.size()));
  for (std::size_t i = 0; i <= 12; ++i) {
    z[lag.angle(i)] = 0.5 * std::cos(kPi * static_cast<double>(i) / 12);
    z[lag.x(i)] = static_cast<double>(i) / 12;
  }
  std::srand(11U);
  Eigen::SparseMatrix<double> band(40, 40);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 40; ++i)
    for (int j = std::max(0, i - 3); j <= std::min(39, i + 2); ++j)
      if (i != j || i % 3 != 0) t.emplace_back(i, j, Eigen::VectorXd::Random(1)[0]);
  band.setFromTriplets(t.begin(), t.end());
  for (const Eigen::SparseMatrix<double>& a : {lag.hessian(z), band}) {
    const Eigen::MatrixXd dense(a);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(dense.rows());
    e2::BandedLU lu;
    ASSERT_TRUE(lu.factorize(a));
    const Eigen::VectorXd x = lu.solve(b);
    const Eigen::PartialPivLU<Eigen::MatrixXd> reference(dense);
    const Eigen::VectorXd y = reference.solve(b);
    const double cond = dense.norm() * reference.inverse().norm();
    EXPECT_LE((x - y).norm(), 64 * kEpsilon * cond * y.norm()) << "cond " << cond;
    EXPECT_LE((dense * x - b).norm(), 64 * kEpsilon * cond * b.norm());
  }
  EXPECT_LE(e2::BandedLU().lower_bandwidth(), 0);
  Eigen::SparseMatrix<double> singular(3, 3);
  singular.insert(0, 1) = 1.0;
  singular.insert(1, 0) = 1.0;
  e2::BandedLU lu;
  EXPECT_FALSE(lu.factorize(singular));
}

// ------------------------------------------------------------------------------------------------
// Gradient and Hessian of the discrete Lagrangian against finite differences

class Elastica2dDerivatives : public ::testing::TestWithParam<Scheme> {};

// A problem exercising every term: tapered EI, curved kappa_hat, a potential (gravity plus a
// quadratic well), a clamp at s = 0 (nonzero angle), dead force and couple at s = L.
e2::Problem everything_problem(Support end_support) {
  e2::Problem p;
  p.length = 1.3;
  p.bending_stiffness = [](double s) { return 1.0 + 0.5 * s; };
  p.natural_curvature = [](double s) { return 0.7 - 0.4 * s; };
  p.potential.value = [](double x, double y) { return 2.0 * y + 0.3 * x * x + 0.2 * x * y * y; };
  p.potential.gradient = [](double x, double y) {
    return Eigen::Vector2d(0.6 * x + 0.2 * y * y, 2.0 + 0.4 * x * y);
  };
  p.potential.hessian = [](double x, double y) {
    Eigen::Matrix2d h;
    h << 0.6, 0.4 * y, 0.4 * y, 0.4 * x;
    return h;
  };
  p.start.support = Support::Clamped;
  p.start.x = 0.1;
  p.start.y = -0.2;
  p.start.angle = 0.3;
  p.end.support = end_support;
  if (end_support == Support::Free) {
    p.end.load = {0.4, -1.1, 0.25};
  } else if (end_support == Support::Sliding) {
    p.end.load.force_x = -0.8;
    p.end.load.moment = 0.2;
  } else if (end_support == Support::Clamped) {
    p.end.x = 1.0;
    p.end.angle = -0.2;
  }
  return p;
}

TEST_P(Elastica2dDerivatives, GradientAndHessianMatchFiniteDifferences) {
  // Central differences with d = cbrt(eps) (1 + |z_j|): error ~ d^2 |third derivative| + eps |L| / d
  // ~ 1e-10 for these O(1) quantities; the tolerance is 1000 d^2 ~ 4e-8 relative to max(1, |value|).
  for (Support end : {Support::Free, Support::Sliding, Support::Pinned, Support::Clamped}) {
    e2::DiscreteLagrangian lag(everything_problem(end), {GetParam(), 7});
    lag.set_load_factor(0.9);
    const Eigen::VectorXd z = random_state(lag, 17U);
    const Eigen::MatrixXd hess = Eigen::MatrixXd(lag.hessian(z));
    ASSERT_EQ(hess.rows(), static_cast<Eigen::Index>(lag.size()));
    EXPECT_TRUE(hess.isApprox(hess.transpose(), 0.0) || (hess - hess.transpose()).norm() == 0.0);
    ASSERT_LE(derivative_mismatch(lag, z, hess), 1000.0) << "end support " << int(end);
  }
}

TEST_P(Elastica2dDerivatives, FiniteDifferenceCheckCanFail) {
  // The same comparison detects a wrong Hessian entry.
  e2::DiscreteLagrangian lag(everything_problem(Support::Free), {GetParam(), 5});
  const Eigen::VectorXd z = random_state(lag, 3U);
  Eigen::MatrixXd hess = Eigen::MatrixXd(lag.hessian(z));
  const auto j = static_cast<Eigen::Index>(lag.angle(2));
  hess(j, j) *= 1.0 + 1e-5;  // 100x the relative tolerance below
  EXPECT_GT(derivative_mismatch(lag, z, hess), 1000.0);
}

TEST_P(Elastica2dDerivatives, LagrangianEqualsEnergyOnTheConstraintSet) {
  // With all constraints satisfied (positions from the chords, rows at their targets) L = Pi.
  e2::DiscreteLagrangian lag(everything_problem(Support::Clamped), {GetParam(), 9});
  Eigen::VectorXd z = random_state(lag, 5U);
  z[lag.x(0)] = 0.1;
  z[lag.y(0)] = -0.2;
  for (std::size_t i = 0; i < lag.elements(); ++i) {
    const Eigen::Vector2d c = lag.element_chord(z, i);
    z[lag.x(i + 1)] = z[lag.x(i)] + c.x();
    z[lag.y(i + 1)] = z[lag.y(i)] + c.y();
  }
  for (std::size_t k = 0; k < lag.rows().size(); ++k) lag.set_row_target(k, z[lag.rows()[k].dof]);
  EXPECT_TRUE(is_close(lag.value(z), lag.energy(z), 64 * kEpsilon, 64 * kEpsilon));
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Elastica2dDerivatives,
                         ::testing::Values(Scheme::Polygon, Scheme::Arcs),
                         [](const auto& param_info) { return name_of(param_info.param); });

// ------------------------------------------------------------------------------------------------
// Pinned-pinned column (PHYSICS.md §3.2-3.3)

class Elastica2dColumn : public ::testing::TestWithParam<Scheme> {};

TEST_P(Elastica2dColumn, PostBuckledFirstModeConvergesAtSecondOrder) {
  std::vector<double> e_theta, e_y, e_kappa;
  for (std::size_t n : kLevels) {
    const auto sol = e2::solve_static(pinned_column(kColumnLoad), {GetParam(), n}, tight(),
                                      first_mode(1.0));
    ASSERT_EQ(sol.nodes(), n + 1);
    EXPECT_LT(sol.residual, 1e-12);
    EXPECT_LE(sol.iterations, 8U);
    e_theta.push_back(sol.theta[0] - kPi / 2);
    e_y.push_back(sol.y[n / 2] - kColumnMidDeflection);
    e_kappa.push_back(std::abs(sol.kappa[n / 2]) - kColumnMidCurvature);
    // The load is dead and there is no distributed load: n = (-P, 0) on every edge, exactly.
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_TRUE(is_close(sol.force_x[i], -kColumnLoad, 16 * kEpsilon, 0.0));
      ASSERT_TRUE(is_close(sol.force_y[i], 0.0, 0.0, 16 * kEpsilon * kColumnLoad));
    }
    // Pins: y = 0 at both ends (rows), zero moment (natural BC), mirror symmetry about midspan.
    EXPECT_EQ(sol.y[0], 0.0);
    EXPECT_TRUE(is_close(sol.y[n], 0.0, 0.0, 1e-14));
    EXPECT_EQ(sol.kappa[0], 0.0);
    EXPECT_EQ(sol.kappa[n], 0.0);
    for (std::size_t i = 0; i <= n; ++i)
      ASSERT_TRUE(is_close(sol.y[i], sol.y[n - i], 0.0, 1e-10)) << i;  // Newton tolerance level
    // Axial force at the pin: n.t = -P cos(theta0).
    EXPECT_TRUE(is_close(sol.axial_force[0], -kColumnLoad * std::cos(sol.theta[0]), 1e-12, 1e-12));
  }
  const double p_theta = observed_order(kLevels, e_theta);
  const double p_y = observed_order(kLevels, e_y);
  const double p_kappa = observed_order(kLevels, e_kappa);
  print_errors(name_of(GetParam()) + " column theta0", e_theta, p_theta);
  print_errors(name_of(GetParam()) + " column y_M", e_y, p_y);
  print_errors(name_of(GetParam()) + " column |kappa_M|", e_kappa, p_kappa);
  // Two-sided windows around the theoretical order 2 (MOOSE style p - 0.1 .. p + 0.5); the polygon
  // end angle is superconvergent (observed ~4: theta' = 0 at a pin), so it is only bounded.
  EXPECT_GE(p_y, 1.9);
  EXPECT_LE(p_y, 2.5);
  EXPECT_GE(p_kappa, 1.9);
  EXPECT_LE(p_kappa, 2.5);
  EXPECT_GE(p_theta, 1.9);
  // Finest level: within 2e-4 of the elliptic values (the observed errors are <= 9e-5).
  EXPECT_LT(std::abs(e_theta.back()), 1e-4);
  EXPECT_LT(std::abs(e_y.back()), 1e-4);
  EXPECT_LT(std::abs(e_kappa.back()), 2e-3);
}

TEST_P(Elastica2dColumn, BelowTheEulerLoadTheColumnStaysStraight) {
  // P = 0.9 P_E: the straight state is the only equilibrium near the perturbed guess.
  const double load = 0.9 * kPi * kPi;
  const std::size_t n = 32;
  const auto sol = e2::solve_static(pinned_column(load), {GetParam(), n}, tight(), first_mode(0.3));
  for (std::size_t i = 0; i <= n; ++i) {
    ASSERT_TRUE(is_close(sol.y[i], 0.0, 0.0, 1e-12)) << i;
    ASSERT_TRUE(is_close(sol.theta[i], 0.0, 0.0, 1e-11)) << i;
    ASSERT_TRUE(is_close(sol.x[i], sol.s[i], 0.0, 1e-12)) << i;
    ASSERT_TRUE(is_close(sol.axial_force[i], -load, 1e-12, 0.0)) << i;
  }
  for (double f : sol.edge_axial_force) ASSERT_TRUE(is_close(f, -load, 1e-12, 0.0));
}

TEST_P(Elastica2dColumn, DisplacementControlReturnsTheReactionLoad) {
  // Both ends pinned, end at the chord of the 90-deg state: the reaction at s = L is (-P, 0).
  std::vector<double> e_load, e_y;
  for (std::size_t n : kLevels) {
    e2::Problem p;
    p.start.support = Support::Pinned;
    p.end.support = Support::Pinned;
    p.end.x = kColumnChord;
    auto options = tight();
    options.load_steps = 4;  // shortening stepped from the straight guess's L to the chord
    const auto sol = e2::solve_static(p, {GetParam(), n}, options, first_mode(0.2));
    e_load.push_back(-sol.force_x[n] - kColumnLoad);
    e_y.push_back(sol.y[n / 2] - kColumnMidDeflection);
    EXPECT_TRUE(is_close(sol.force_y[n], 0.0, 0.0, 1e-11));
    EXPECT_TRUE(is_close(sol.x[n], kColumnChord, 0.0, 1e-14));
  }
  const double p_load = observed_order(kLevels, e_load);
  const double p_y = observed_order(kLevels, e_y);
  print_errors(name_of(GetParam()) + " displacement P", e_load, p_load);
  print_errors(name_of(GetParam()) + " displacement y_M", e_y, p_y);
  EXPECT_GE(p_load, 1.9);
  EXPECT_LE(p_load, 2.5);
  EXPECT_GE(p_y, 1.9);
  EXPECT_LE(p_y, 2.5);
  EXPECT_LT(std::abs(e_load.back()), 5e-3);  // observed errors at N = 128 are ~1e-3 P / 10
}

TEST_P(Elastica2dColumn, LoadSteppingFollowsTheBranchToLargeRotation) {
  // theta0 = 170 deg, P L^2/EI = 58.728987011639, y_M / L = 0.25998480538300 (PHYSICS.md §3.3).
  // Four load steps 14.7, 29.4, 44.0, 58.7 (all above P_E, so every step stays on the buckled
  // branch) from a first-mode guess near the first step's solution (theta0 ~ 97 deg at P = 14.7;
  // amplitude 1.7 rad), far from the 170-deg answer. Newton converges to the equilibrium nearest
  // the guess, so the guess must be in the first step's basin (a 1-rad guess at P = 14.7 is not).
  const double load = 58.728987011639, deflection = 0.25998480538300;
  const std::size_t n = 64;
  auto options = tight();
  options.load_steps = 4;
  const auto sol = e2::solve_static(pinned_column(load), {GetParam(), n}, options, first_mode(1.7));
  // Discretisation errors at N = 64 (observed): y_M 1.5e-4 (polygon), 2e-6 (arcs); theta0 4e-4
  // (polygon), 3e-4 (arcs). Bounds: about 3x the larger of the two.
  EXPECT_TRUE(is_close(sol.y[n / 2], deflection, 0.0, 5e-4));
  EXPECT_TRUE(is_close(sol.theta[0], 170.0 * kPi / 180.0, 0.0, 1.2e-3));
  std::printf("[ stepping ] %s theta0 = 170 deg, N = 64: y_M error %.3e, theta0 error %.3e, %zu iterations\n",
              name_of(GetParam()).c_str(), sol.y[n / 2] - deflection, sol.theta[0] - 170.0 * kPi / 180.0,
              sol.iterations);
  for (std::size_t i = 1; i < n; ++i) ASSERT_GT(sol.y[i], 0.0) << i;  // first mode: one-signed
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Elastica2dColumn,
                         ::testing::Values(Scheme::Polygon, Scheme::Arcs),
                         [](const auto& param_info) { return name_of(param_info.param); });

// ------------------------------------------------------------------------------------------------
// Cantilevers (PHYSICS.md §3.4-3.5)

e2::Problem end_moment_cantilever(double moment) {
  e2::Problem p;
  p.start.support = Support::Clamped;
  p.end.load.moment = moment;
  return p;
}

TEST(Elastica2dCantilever, EndMomentArcsAreExactForAnyN) {
  // theta = M s / EI, x = sin(M s)/M, y = (1 - cos(M s))/M. Round-off only: the node positions are
  // sums of up to N exact chords, so the tolerance is 8 N eps (absolute, L = 1).
  for (double moment : {0.7, 3.0, 2 * kPi}) {
    for (std::size_t n : {2U, 3U, 7U, 16U, 100U}) {
      const auto sol = e2::solve_static(end_moment_cantilever(moment), {Scheme::Arcs, n}, tight());
      const double tol = 8.0 * static_cast<double>(n) * kEpsilon * std::max(1.0, moment);
      for (std::size_t i = 0; i <= n; ++i) {
        const double s = sol.s[i];
        ASSERT_TRUE(is_close(sol.x[i], std::sin(moment * s) / moment, 0.0, tol)) << n << " " << moment;
        ASSERT_TRUE(is_close(sol.y[i], (1 - std::cos(moment * s)) / moment, 0.0, tol)) << n;
        ASSERT_TRUE(is_close(sol.theta[i], moment * s, 0.0, tol)) << n;
        ASSERT_TRUE(is_close(sol.kappa[i], moment, 0.0, tol * moment)) << n;
        ASSERT_TRUE(is_close(sol.axial_force[i], 0.0, 0.0, tol)) << n;
      }
    }
  }
}

TEST(Elastica2dCantilever, EndMomentPolygonConvergesAtSecondOrder) {
  // The polygon's edge angles are exact (theta at edge midpoints), its nodes are midpoint-rule
  // sums: tip error O(h^2).
  const double moment = 3.0;
  std::vector<double> e_x, e_y;
  for (std::size_t n : kLevels) {
    const auto sol = e2::solve_static(end_moment_cantilever(moment), {Scheme::Polygon, n}, tight());
    e_x.push_back(sol.x[n] - std::sin(moment) / moment);
    e_y.push_back(sol.y[n] - (1 - std::cos(moment)) / moment);
    EXPECT_TRUE(is_close(sol.theta[n], moment, 0.0, 1e-12));  // exact up to Newton tolerance
    for (std::size_t i = 0; i <= n; ++i) ASSERT_TRUE(is_close(sol.kappa[i], moment, 1e-11, 0.0)) << i;
  }
  const double p_x = observed_order(kLevels, e_x), p_y = observed_order(kLevels, e_y);
  print_errors("Polygon end-moment tip x", e_x, p_x);
  print_errors("Polygon end-moment tip y", e_y, p_y);
  EXPECT_NEAR(p_x, 2.0, 0.05);  // pure midpoint-rule error: the asymptotic constant is reached
  EXPECT_NEAR(p_y, 2.0, 0.05);
}

class Elastica2dMattiasson : public ::testing::TestWithParam<Scheme> {};

TEST_P(Elastica2dMattiasson, TipDisplacementsConvergeAtSecondOrder) {
  std::vector<double> e_w, e_u, e_phi;
  for (std::size_t n : kLevels) {
    e2::Problem p;
    p.start.support = Support::Clamped;
    p.end.load.force_y = -1.0;  // alpha = P L^2 / EI = 1, downward dead load
    const auto sol = e2::solve_static(p, {GetParam(), n}, tight());
    e_w.push_back(-sol.y[n] - kMattiassonW);
    e_u.push_back(1.0 - sol.x[n] - kMattiassonU);
    e_phi.push_back(-sol.theta[n] - kMattiassonTipAngle);
    // Free end: zero moment, n(L) = applied load; clamped end: n(0) = reaction = (0, -1) too.
    EXPECT_EQ(sol.kappa[n], 0.0);
    EXPECT_TRUE(is_close(sol.force_y[n], -1.0, 16 * kEpsilon, 0.0));
    EXPECT_TRUE(is_close(sol.force_y[0], -1.0, 1e-12, 0.0));
    EXPECT_TRUE(is_close(sol.force_x[0], 0.0, 0.0, 1e-12));
    // Moment balance about the clamp: EI kappa(0) = -x_tip P exactly (the discrete moment balance is
    // exact, so only the Newton tolerance enters).
    EXPECT_TRUE(is_close(sol.kappa[0], -sol.x[n], 0.0, 1e-11));
  }
  const double p_w = observed_order(kLevels, e_w), p_u = observed_order(kLevels, e_u);
  const double p_phi = observed_order(kLevels, e_phi);
  print_errors(name_of(GetParam()) + " Mattiasson w", e_w, p_w);
  print_errors(name_of(GetParam()) + " Mattiasson u", e_u, p_u);
  print_errors(name_of(GetParam()) + " Mattiasson phi_L", e_phi, p_phi);
  for (double p : {p_w, p_u, p_phi}) {
    EXPECT_GE(p, 1.9);
    EXPECT_LE(p, 2.5);
  }
  EXPECT_LT(std::abs(e_w.back()), 1e-4);
  EXPECT_LT(std::abs(e_u.back()), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Elastica2dMattiasson,
                         ::testing::Values(Scheme::Polygon, Scheme::Arcs),
                         [](const auto& param_info) { return name_of(param_info.param); });

// ------------------------------------------------------------------------------------------------
// Pseudo-arc-length continuation

class Elastica2dContinuation : public ::testing::TestWithParam<Scheme> {};

TEST_P(Elastica2dContinuation, FollowsThePostBuckledBranchOfThePinnedColumn) {
  // Unit end load, load factor = P L^2 / EI, traced from theta0 = 60 deg (P = 11.367017035003) to
  // theta0 = 120 deg (P = 18.602238951643, PHYSICS.md §3.3). Every point must satisfy the elliptic
  // relation P L^2/EI = 4 K(sin(theta0/2))^2 (C++17 comp_ellint_1, modulus k), up to the N = 64
  // discretisation error: observed max relative error 2.1e-4 (polygon) / 4.0e-4 (arcs); bound 1e-3.
  const std::size_t n = 64;
  e2::ContinuationOptions c;
  c.initial_load_factor = 11.367017035003;
  c.final_load_factor = 18.602238951643;
  c.step = 0.05;
  const auto branch = e2::trace_branch(pinned_column(1.0), {GetParam(), n}, tight(),
                                       first_mode(1.0), c);
  ASSERT_GE(branch.size(), 5U);
  EXPECT_EQ(branch.back().load_factor, c.final_load_factor);
  double worst = 0.0, previous_theta = 0.0;
  for (const auto& point : branch) {
    const auto& sol = point.solution;
    EXPECT_LE(sol.residual, 1e-12);
    const double theta0 = sol.theta[0];
    EXPECT_GT(theta0, previous_theta);  // monotone along this branch: no fold in P
    previous_theta = theta0;
    const double k = std::comp_ellint_1(std::sin(theta0 / 2));
    const double exact = 4 * k * k;
    worst = std::max(worst, std::abs(point.load_factor - exact) / exact);
    for (std::size_t i = 1; i < n; ++i) ASSERT_GT(sol.y[i], 0.0);  // first mode throughout
  }
  std::printf("[ branch   ] %s: %zu points, max relative P error %.3e\n", name_of(GetParam()).c_str(),
              branch.size(), worst);
  EXPECT_LT(worst, 1e-3);
  EXPECT_TRUE(is_close(branch.back().solution.theta[0], 120.0 * kPi / 180.0, 0.0, 2e-3));
  // The end point is the load-controlled solution at the final load.
  const auto direct = e2::solve_static(pinned_column(c.final_load_factor), {GetParam(), n}, tight(),
                                       first_mode(2.0));
  for (std::size_t i = 0; i <= n; ++i)
    ASSERT_TRUE(is_close(branch.back().solution.y[i], direct.y[i], 0.0, 1e-10)) << i;
}

TEST(Elastica2dContinuationOptions, BadOptionsThrowInputError) {
  e2::ContinuationOptions c;
  c.final_load_factor = c.initial_load_factor;
  EXPECT_EQ(input_error_parameter_of([&] {
              e2::trace_branch(pinned_column(1.0), {Scheme::Arcs, 8}, {}, {}, c);
            }),
            "continuation.final_load_factor");
  c = {};
  c.step = -1.0;
  EXPECT_EQ(input_error_parameter_of([&] {
              e2::trace_branch(pinned_column(1.0), {Scheme::Arcs, 8}, {}, {}, c);
            }),
            "continuation.step");
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Elastica2dContinuation,
                         ::testing::Values(Scheme::Polygon, Scheme::Arcs),
                         [](const auto& param_info) { return name_of(param_info.param); });

// ------------------------------------------------------------------------------------------------
// Natural curvature, tapered stiffness, potential

class Elastica2dExtras : public ::testing::TestWithParam<Scheme> {};

TEST_P(Elastica2dExtras, UnloadedCurvedRodTakesItsNaturalShape) {
  // kappa_hat = 2.5 constant, clamped at s = 0, no load: the natural circle with zero stress, which
  // both discretisations reproduce to round-off (arcs exactly; polygon angles exact at midpoints,
  // so compare the polygon against its own chords, the exact circle's vertices: the polygon
  // inscribed with chord h sinc-free angles phi_i, x_{i+1} - x_i = h cos(phi_i)).
  const double c = 2.5;
  const std::size_t n = 10;
  e2::Problem p;
  p.start.support = Support::Clamped;
  p.natural_curvature = [c](double) { return c; };
  const auto sol = e2::solve_static(p, {GetParam(), n}, tight());
  const double tol = 64 * kEpsilon * static_cast<double>(n);
  double x = 0, y = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    ASSERT_TRUE(is_close(sol.kappa[i], c, 0.0, 1e-11 * c)) << i;
    ASSERT_TRUE(is_close(sol.theta[i], c * sol.s[i], 0.0, 1e-12)) << i;
    ASSERT_TRUE(is_close(sol.force_x[i], 0.0, 0.0, 1e-11)) << i;
    ASSERT_TRUE(is_close(sol.force_y[i], 0.0, 0.0, 1e-11)) << i;
    if (GetParam() == Scheme::Arcs) {
      ASSERT_TRUE(is_close(sol.x[i], std::sin(c * sol.s[i]) / c, 0.0, tol)) << i;
      ASSERT_TRUE(is_close(sol.y[i], (1 - std::cos(c * sol.s[i])) / c, 0.0, tol)) << i;
    } else {
      ASSERT_TRUE(is_close(sol.x[i], x, 0.0, 1e-12)) << i;
      ASSERT_TRUE(is_close(sol.y[i], y, 0.0, 1e-12)) << i;
      const double phi = c * (sol.s[i] + 0.05);  // edge midpoint angle, h = 0.1
      x += 0.1 * std::cos(phi);
      y += 0.1 * std::sin(phi);
    }
  }
}

TEST_P(Elastica2dExtras, TaperedCantileverUnderEndMomentConvergesAtSecondOrder) {
  // EI(s) = 1 + s, end couple M = 2: theta = M ln(1 + s); with u = ln(1 + s),
  // x(1) = (2 (cos Mu + M sin Mu) - 1) / (1 + M^2), y(1) = (2 (sin Mu - M cos Mu) + M) / (1 + M^2)
  // at u = ln 2 (integrals of e^u cos Mu, e^u sin Mu).
  const double m = 2.0, u = std::log(2.0);
  const double x_exact = (2 * (std::cos(m * u) + m * std::sin(m * u)) - 1) / (1 + m * m);
  const double y_exact = (2 * (std::sin(m * u) - m * std::cos(m * u)) + m) / (1 + m * m);
  std::vector<double> e_x, e_y, e_theta;
  for (std::size_t n : kLevels) {
    e2::Problem p = end_moment_cantilever(m);
    p.bending_stiffness = [](double s) { return 1.0 + s; };
    const auto sol = e2::solve_static(p, {GetParam(), n}, tight());
    e_x.push_back(sol.x[n] - x_exact);
    e_y.push_back(sol.y[n] - y_exact);
    e_theta.push_back(sol.theta[n] - m * u);
    for (std::size_t i = 0; i <= n; ++i)  // n = 0 everywhere: the moment is M on every node
      ASSERT_TRUE(is_close(sol.axial_force[i], 0.0, 0.0, 1e-11)) << i;
  }
  const double p_x = observed_order(kLevels, e_x), p_y = observed_order(kLevels, e_y);
  const double p_t = observed_order(kLevels, e_theta);
  print_errors(name_of(GetParam()) + " tapered tip x", e_x, p_x);
  print_errors(name_of(GetParam()) + " tapered tip y", e_y, p_y);
  print_errors(name_of(GetParam()) + " tapered tip theta", e_theta, p_t);
  for (double p : {p_x, p_y, p_t}) {
    EXPECT_GE(p, 1.9);
    EXPECT_LE(p, 2.5);
  }
}

TEST_P(Elastica2dExtras, RodHangingUnderGravityCarriesItsWeight) {
  // V = q y (weight q per unit length), pinned at the top, free below, started 0.4 rad off the
  // vertical: it hangs straight down and the tension is the weight below, n.t = q (L - s). The
  // trapezoidal lumping makes every force value exact, so only the Newton tolerance enters.
  const double q = 3.0;
  const std::size_t n = 16;
  e2::Problem p;
  p.start.support = Support::Pinned;
  p.potential.value = [q](double, double yy) { return q * yy; };
  p.potential.gradient = [q](double, double) { return Eigen::Vector2d(0.0, q); };
  e2::InitialGuess g;
  g.theta = [](double) { return -kPi / 2 + 0.4; };
  const auto sol = e2::solve_static(p, {GetParam(), n}, tight(), g);  // Hessian of V by differences
  for (std::size_t i = 0; i <= n; ++i) {
    ASSERT_TRUE(is_close(sol.theta[i], -kPi / 2, 0.0, 1e-11)) << i;
    ASSERT_TRUE(is_close(sol.axial_force[i], q * (1 - sol.s[i]), 0.0, 1e-11)) << i;
    ASSERT_TRUE(is_close(sol.potential[i], q * sol.y[i], 1e-15, 0.0)) << i;
  }
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_TRUE(is_close(sol.edge_axial_force[i], q * (1 - (static_cast<double>(i) + 0.5) / 16), 0.0, 1e-11));
}

TEST(Elastica2dHeavyCantilever, BothSchemesConvergeAtSecondOrderToTheSameLimit) {
  // Clamped horizontal cantilever under its own weight q L^3 / EI = 3 (large deflection, no closed
  // form): the observed order from the differences of successive levels is ~2 for each scheme, and
  // their Richardson limits (p = 2, N = 128 and 256) agree: observed |difference| 7e-12, so 1e-9
  // bounds the remaining O(h^4) terms with margin while any O(h^2) mismatch (~1e-6) would fail.
  const double q = 3.0;
  e2::Problem p;
  p.start.support = Support::Clamped;
  p.potential.value = [q](double, double yy) { return q * yy; };
  p.potential.gradient = [q](double, double) { return Eigen::Vector2d(0.0, q); };
  p.potential.hessian = [](double, double) { return Eigen::Matrix2d::Zero().eval(); };
  std::array<double, 2> limits{};
  for (Scheme scheme : {Scheme::Polygon, Scheme::Arcs}) {
    std::vector<double> tip;
    for (std::size_t n : {16U, 32U, 64U, 128U, 256U}) {
      const auto sol = e2::solve_static(p, {scheme, n}, tight());
      tip.push_back(sol.y[n]);
      // n(0) = force of (0, L] on [0, 0]: the whole weight, (0, -q L).
      EXPECT_TRUE(is_close(sol.force_y[0], -q, 1e-12, 0.0));
    }
    std::vector<double> differences;
    for (std::size_t i = 1; i < tip.size(); ++i) differences.push_back(tip[i] - tip[i - 1]);
    const double order = observed_order(kLevels, differences);
    const double limit = tip.back() + differences.back() / 3.0;
    limits[scheme == Scheme::Polygon ? 0 : 1] = limit;
    std::printf("[ order    ] %s heavy cantilever tip y: N=256 %.12f, Richardson limit %.12f, p = %.3f\n",
                name_of(scheme).c_str(), tip.back(), limit, order);
    EXPECT_GE(order, 1.9);
    EXPECT_LE(order, 2.5);
  }
  EXPECT_TRUE(is_close(limits[0], limits[1], 0.0, 1e-9));
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Elastica2dExtras,
                         ::testing::Values(Scheme::Polygon, Scheme::Arcs),
                         [](const auto& param_info) { return name_of(param_info.param); });

// ------------------------------------------------------------------------------------------------
// Input validation and failure reporting

TEST(Elastica2dValidation, BadInputThrowsInputErrorNamingTheField) {
  const e2::Discretisation disc{Scheme::Arcs, 8};
  auto solve = [&](const e2::Problem& p, e2::Discretisation d = {Scheme::Arcs, 8},
                   e2::SolverOptions o = {}) { return [=] { e2::solve_static(p, d, o); }; };
  const auto good = pinned_column(1.0);
  EXPECT_NO_THROW(solve(good)());

  auto p = good;
  p.length = 0.0;
  EXPECT_EQ(input_error_parameter_of(solve(p)), "length");
  p.length = -1.0;
  EXPECT_EQ(input_error_parameter_of(solve(p)), "length");
  p.length = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(input_error_parameter_of(solve(p)), "length");

  EXPECT_EQ(input_error_parameter_of(solve(good, {Scheme::Polygon, 1})), "elements");
  EXPECT_EQ(input_error_parameter_of(solve(good, {Scheme::Arcs, 0})), "elements");

  p = good;
  p.bending_stiffness = [](double s) { return s < 0.6 ? 1.0 : -1.0; };  // negative on part of [0, L]
  EXPECT_EQ(input_error_parameter_of(solve(p)), "bending_stiffness");
  EXPECT_EQ(input_error_parameter_of(solve(p, {Scheme::Polygon, 8})), "bending_stiffness");
  p.bending_stiffness = [](double s) { return s; };  // EI(0) = 0
  EXPECT_EQ(input_error_parameter_of(solve(p, {Scheme::Polygon, 8})), "bending_stiffness");
  p = good;
  p.natural_curvature = [](double) { return std::numeric_limits<double>::infinity(); };
  EXPECT_EQ(input_error_parameter_of(solve(p)), "natural_curvature");

  p = good;
  p.end.load.force_x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(input_error_parameter_of(solve(p)), "end.load.force_x");
  p = good;
  p.end.load.moment = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(input_error_parameter_of(solve(p)), "end.load.moment");
  p = good;
  p.end.load.force_y = 1.0;  // the roller prescribes y: the reaction carries a vertical load
  EXPECT_EQ(input_error_parameter_of(solve(p)), "end.load.force_y");
  p = good;
  p.start.load.force_x = 1.0;  // pinned: position prescribed
  EXPECT_EQ(input_error_parameter_of(solve(p)), "start.load.force_x");
  p = good;
  p.start.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(input_error_parameter_of(solve(p)), "start.y");
  p = good;
  p.potential.value = [](double, double) { return 0.0; };  // gradient missing
  EXPECT_EQ(input_error_parameter_of(solve(p)), "potential.gradient");

  e2::SolverOptions o;
  o.tolerance = 0.0;
  EXPECT_EQ(input_error_parameter_of(solve(good, disc, o)), "options.tolerance");
  o = {};
  o.max_iterations = 0;
  EXPECT_EQ(input_error_parameter_of(solve(good, disc, o)), "options.max_iterations");
  o = {};
  o.load_steps = 0;
  EXPECT_EQ(input_error_parameter_of(solve(good, disc, o)), "options.load_steps");

  e2::InitialGuess g;
  g.theta = [](double) { return std::numeric_limits<double>::quiet_NaN(); };
  EXPECT_EQ(input_error_parameter_of([&] { e2::solve_static(good, disc, {}, g); }), "guess.theta");
  EXPECT_EQ(input_error_parameter_of([] { e2::scheme_from_id("splines"); }), "scheme");
  EXPECT_EQ(e2::scheme_from_id("arcs"), Scheme::Arcs);
  EXPECT_EQ(e2::scheme_from_id("polygon"), Scheme::Polygon);
}

TEST(Elastica2dLoadSteps, AFailedLoadStepIsHalvedUntilNewtonConverges) {
  // A cantilever at P L^2/EI = 100 (L = 1.7, EI = 2.3) in ONE planned step: Newton from the straight
  // rod fails, the halved steps reach the same equilibrium as 64 small planned steps do.
  e2::Problem p;
  p.length = 1.7;
  p.bending_stiffness = [](double) { return 2.3; };
  p.start.support = Support::Clamped;
  p.end.load.force_y = -100.0 * 2.3 / (1.7 * 1.7);
  for (Scheme scheme : {Scheme::Polygon, Scheme::Arcs}) {
    e2::SolverOptions one_step, many_steps;
    many_steps.load_steps = 64;
    const auto halved = e2::solve_static(p, {scheme, 32}, one_step);
    const auto planned = e2::solve_static(p, {scheme, 32}, many_steps);
    EXPECT_LE(halved.residual, one_step.tolerance);
    EXPECT_GT(halved.iterations, 50U);  // more than one step's worth: the step was subdivided
    EXPECT_NEAR(halved.y.back(), planned.y.back(), 1e-9);
    EXPECT_NEAR(halved.x.back(), planned.x.back(), 1e-9);
    EXPECT_LT(halved.y.back(), -1.5);  // hanging nearly straight down (tip y / L < -0.88)
  }
}

TEST(Elastica2dUnits, TheSameCantileverConvergesAlikeAtAnyLengthAndStiffness) {
  // Newton converges on the residual in the problem's own units (newton.hpp): a cantilever at
  // P L^2/EI = 2 posed at (L, EI) = (1, 1), (1e6, 1e-6) and (1e-6, 1e12) gives the same shape in
  // units of L, to the Newton tolerance. Before, L = 1e3 already failed (an absolute 1e-10 on
  // ||grad L|| that round-off in positions ~L cannot reach).
  auto solve = [](double L, double EI, Scheme scheme) {
    e2::Problem p;
    p.length = L;
    p.bending_stiffness = [EI](double) { return EI; };
    p.start.support = Support::Clamped;
    p.end.load.force_y = -2.0 * EI / (L * L);
    e2::SolverOptions o;
    o.load_steps = 2;
    return e2::solve_static(p, {scheme, 24}, o);
  };
  for (Scheme scheme : {Scheme::Polygon, Scheme::Arcs}) {
    const auto unit = solve(1.0, 1.0, scheme);
    for (const auto& [L, EI] : {std::pair{1e6, 1e-6}, std::pair{1e-6, 1e12}}) {
      const auto scaled = solve(L, EI, scheme);
      EXPECT_LE(scaled.residual, 1e-10);
      for (std::size_t i = 0; i < unit.nodes(); ++i) {
        EXPECT_NEAR(scaled.x[i] / L, unit.x[i], 1e-9) << "L = " << L << ", node " << i;
        EXPECT_NEAR(scaled.y[i] / L, unit.y[i], 1e-9) << "L = " << L << ", node " << i;
        EXPECT_NEAR(scaled.force_y[i] * L * L / EI, unit.force_y[i], 1e-9) << "L = " << L << ", node " << i;
      }
    }
  }
}

TEST(Elastica2dFailure, NewtonFailureThrowsSolverErrorWithIterationsAndResidual) {
  e2::SolverOptions o;
  o.max_iterations = 2;  // the column needs ~5 iterations
  try {
    e2::solve_static(pinned_column(kColumnLoad), {Scheme::Polygon, 32}, o, first_mode(1.0));
    FAIL() << "expected SolverError";
  } catch (const rodvv::SolverError& e) {
    // The planned step and its 10 halvings (solve_static.hpp) each stop at max_iterations: 11 x 2
    // iterations, all counted, and the message names the load factor reached.
    EXPECT_EQ(e.iterations(), 22U);
    EXPECT_GT(e.residual(), o.tolerance);
    EXPECT_EQ(e.method(), "elastica2d-polygon");
    EXPECT_NE(std::string(e.what()).find("at load factor 0.0009765625 after 10 halvings"), std::string::npos)
        << e.what();
  }
  // A bent free-free rod without loads: rigid motions make the KKT matrix singular (or, if round-off
  // leaves a tiny pivot, Newton cannot reduce the residual): SolverError either way.
  e2::Problem floating;
  e2::InitialGuess bent;
  bent.theta = [](double s) { return 0.3 * s; };
  EXPECT_THROW(e2::solve_static(floating, {Scheme::Arcs, 8}, {}, bent), rodvv::SolverError);
  EXPECT_THROW(e2::solve_static(floating, {Scheme::Polygon, 8}, {}, bent), rodvv::SolverError);
}

}  // namespace
