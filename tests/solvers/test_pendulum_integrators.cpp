// Tests of the pendulum integrators (solvers/include/rodvv/solvers/pendulum/integrators.hpp):
// observed order against the closed form, energy behaviour over 1000 periods, time reversibility,
// output grid and bookkeeping, input validation and failure reporting.
// Reference values: PHYSICS.md §2.4 (omega = 1, released from rest at 90 deg), verified there to
// about 1e-25 against mpmath; 15 significant digits are quoted, i.e. accurate to ~1e-15 absolute.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/energy.hpp"
#include "rodvv/solvers/pendulum/integrators.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
namespace pendulum = rodvv::solvers::pendulum;
using pendulum::Method;

constexpr double kTheta0 = std::numbers::pi / 2;          // 90 deg, omega = 1, from rest
constexpr double kThetaAt2 = -0.205639486773337;          // PHYSICS.md §2.4, t = 2
constexpr double kThetaDotAt2 = -1.39923593852639;        // PHYSICS.md §2.4, t = 2
constexpr double kReferenceAccuracy = 1e-14;              // 15 quoted digits, with margin
constexpr double kPeriod90 = 7.416298709205488;           // omega T = 4 K(sin 45 deg), §2.4

pendulum::Problem libration90(double t_end) { return {1.0, kTheta0, 0.0, t_end}; }

pendulum::Settings settings_for(Method method, double dt, double tolerance = 1e-8) {
  pendulum::Settings s;
  s.method = method;
  s.dt = dt;
  s.tolerance = tolerance;
  return s;
}

// "rkn4-mclachlan" -> "Rkn4Mclachlan": GoogleTest names without underscores or dashes.
std::string camel(std::string_view id) {
  std::string out;
  bool upper = true;
  for (char c : id) {
    if (c == '-') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return out;
}

std::string method_name(const ::testing::TestParamInfo<Method>& info) {
  return camel(pendulum::info(info.param).id);
}

// Least-squares slope of log(error) against log(h): the observed order (ARCHITECTURE convention 7).
double fitted_order(const std::vector<double>& h, const std::vector<double>& error) {
  const double n = static_cast<double>(h.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    mx += std::log(h[i]) / n;
    my += std::log(error[i]) / n;
  }
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
    sxy += (std::log(h[i]) - mx) * (std::log(error[i]) - my);
  }
  return sxy / sxx;
}

// Step levels for the order study: error in theta(2) measured (PHYSICS §2.4 reference) at
//   dt:            0.02      0.01      0.005
//   explicit Euler 3.39e-3   1.61e-3   7.85e-4   (pairwise 1.07, 1.04: asymptotic from above)
//   sympl. Euler   1.40e-2   7.00e-3   3.50e-3   (1.000, 1.000)
//   Stoermer-Verl. 3.47e-5   8.68e-6   2.17e-6   (2.000, 2.000)
//   rk4            1.97e-9   1.22e-10  7.62e-12  (4.007, 4.003)
//   rkn4-mclachlan 7.79e-11  4.87e-12  3.02e-13  (4.000, 4.009)
// The finest rkn4 error is still 30x the reference accuracy; one more halving (1.9e-14) would not be.
const std::vector<double> kOrderSteps{0.02, 0.01, 0.005};

std::vector<double> final_errors(Method method) {
  std::vector<double> errors;
  for (double dt : kOrderSteps) {
    const rodvv::Trajectory tr = pendulum::integrate(libration90(2.0), settings_for(method, dt));
    EXPECT_EQ(tr.t.back(), 2.0);  // 2 / dt is (within 4 ulps) an integer for all three levels
    errors.push_back(std::abs(tr.theta.back() - kThetaAt2));
  }
  return errors;
}

// ------------------------------------------------------------------------------------------------
// Method table

TEST(PendulumMethods, TableHasTheSixMethodsWithTheirOrders) {
  const auto methods = pendulum::all_methods();
  ASSERT_EQ(methods.size(), 6U);
  const std::array<std::string_view, 6> ids{"explicit-euler", "symplectic-euler", "stormer-verlet",
                                            "rk4", "dopri5", "rkn4-mclachlan"};
  const std::array<int, 6> orders{1, 1, 2, 4, 5, 4};
  const std::array<bool, 6> symplectic{false, true, true, false, false, true};
  for (std::size_t i = 0; i < ids.size(); ++i) {
    EXPECT_EQ(methods[i].id, ids[i]);
    EXPECT_EQ(methods[i].order, orders[i]) << ids[i];
    EXPECT_EQ(methods[i].symplectic, symplectic[i]) << ids[i];
    EXPECT_EQ(methods[i].adaptive, ids[i] == "dopri5") << ids[i];
    EXPECT_FALSE(methods[i].citation.empty()) << ids[i];
    EXPECT_EQ(pendulum::method_from_id(ids[i]), methods[i].method);
    EXPECT_EQ(pendulum::info(methods[i].method).id, ids[i]);
  }
}

TEST(PendulumMethods, UnknownIdThrowsInputErrorListingTheValidIds) {
  try {
    pendulum::method_from_id("leapfrog");
    FAIL() << "expected InputError";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "method");
    const std::string message = e.what();
    EXPECT_NE(message.find("leapfrog"), std::string::npos) << message;
    for (const auto& m : pendulum::all_methods())
      EXPECT_NE(message.find(std::string(m.id)), std::string::npos) << message;
  }
}

// ------------------------------------------------------------------------------------------------
// Observed order, fixed-step methods

class FixedStepIntegrator : public ::testing::TestWithParam<Method> {};

TEST_P(FixedStepIntegrator, ObservedOrderMatchesTheory) {
  const auto& info = pendulum::info(GetParam());
  const std::vector<double> errors = final_errors(GetParam());
  // Above round-off and reference accuracy at every level, or the fit would measure noise.
  for (double e : errors) EXPECT_GT(e, 10.0 * kReferenceAccuracy);
  const double p = fitted_order(kOrderSteps, errors);
  // Two-sided window p - 0.1 .. p + 0.5 (ARCHITECTURE convention 7, after MOOSE mms).
  EXPECT_GE(p, info.order - 0.1) << info.id;
  EXPECT_LE(p, info.order + 0.5) << info.id;
  RecordProperty("observed_order", std::to_string(p));
}

// Teeth: the order window must reject a method of the wrong order. Explicit Euler's fitted slope
// (measured 1.06) lies far outside the window [1.9, 2.5] of a second-order method.
TEST(FixedStepIntegratorTeeth, ExplicitEulerFailsTheSecondOrderWindow) {
  const double p = fitted_order(kOrderSteps, final_errors(Method::ExplicitEuler));
  EXPECT_LT(p, 2.0 - 0.1);
  EXPECT_NEAR(p, 1.0, 0.1);  // ... while it does pass its own window from below
}

// Both state components converge: theta_dot at the finest level is within C h^p of the reference,
// with C measured at the coarser level (C h^p extrapolated, times 2 for the pre-asymptotic drift).
TEST_P(FixedStepIntegrator, RateAlsoConvergesAtTheExpectedRate) {
  const auto& info = pendulum::info(GetParam());
  const auto run = [&](double dt) {
    return pendulum::integrate(libration90(2.0), settings_for(GetParam(), dt)).theta_dot.back();
  };
  const double coarse = std::abs(run(0.01) - kThetaDotAt2);
  const double fine = std::abs(run(0.005) - kThetaDotAt2);
  const double predicted = coarse * std::pow(0.5, info.order);
  EXPECT_LE(fine, 2.0 * predicted + kReferenceAccuracy) << info.id;
}

INSTANTIATE_TEST_SUITE_P(FixedStepMethods, FixedStepIntegrator,
                         ::testing::Values(Method::ExplicitEuler, Method::SymplecticEuler,
                                           Method::StormerVerlet, Method::RungeKutta4,
                                           Method::McLachlanRkn4),
                         method_name);

// ------------------------------------------------------------------------------------------------
// Dormand-Prince: the resolution is the tolerance

// Measured |theta(2) - reference| / tol = 0.50, 0.14, 0.35, 0.52, 0.69 for tol = 1e-4 .. 1e-12
// (abs = rel tolerance on the local error, and |x| ~ 1 here, so the global error is O(tol)).
// Gate: error <= 2 tol, i.e. C = 2, about 3x the largest measured ratio.
const std::vector<double> kTolerances{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

TEST(Dopri5, AchievedErrorIsWithinTwiceTheTolerance) {
  for (double tol : kTolerances) {
    const auto tr = pendulum::integrate(libration90(2.0),
                                        settings_for(Method::DormandPrince5, 0.1, tol));
    const double error = std::abs(tr.theta.back() - kThetaAt2);
    EXPECT_LE(error, 2.0 * tol + kReferenceAccuracy) << "tol " << tol;
    EXPECT_LE(std::abs(tr.theta_dot.back() - kThetaDotAt2), 2.0 * tol + kReferenceAccuracy)
        << "tol " << tol;
  }
}

TEST(Dopri5, ErrorAndWorkFollowTheTolerance) {
  double previous_error = std::numeric_limits<double>::infinity();
  std::size_t previous_steps = 0;
  for (double tol : kTolerances) {
    const auto tr = pendulum::integrate(libration90(2.0),
                                        settings_for(Method::DormandPrince5, 0.1, tol));
    const double error = std::abs(tr.theta.back() - kThetaAt2);
    EXPECT_LT(error, previous_error) << "tol " << tol;
    EXPECT_GT(tr.steps, previous_steps) << "tol " << tol;
    previous_error = error;
    previous_steps = tr.steps;
  }
}

// Dense output is sampled on the grid, so a coarse output interval does not degrade accuracy: the
// t = 0.5, 1, 2, 5 table values at tol 1e-10 (error gate 2 tol as above; t = 5 has 2.5x the span,
// so 5 tol there).
TEST(Dopri5, DenseOutputMatchesTableAtIntermediateTimes) {
  const double tol = 1e-10;
  const auto tr = pendulum::integrate(libration90(5.0),
                                      settings_for(Method::DormandPrince5, 0.5, tol));
  ASSERT_EQ(tr.size(), 11U);
  EXPECT_TRUE(is_close(tr.theta[1], 1.44586138014692, 0.0, 2 * tol));
  EXPECT_TRUE(is_close(tr.theta[2], 1.07491168437224, 0.0, 2 * tol));
  EXPECT_TRUE(is_close(tr.theta[4], -0.205639486773337, 0.0, 2 * tol));
  EXPECT_TRUE(is_close(tr.theta[10], -0.755077175419911, 0.0, 5 * tol));
  EXPECT_TRUE(is_close(tr.theta_dot[10], 1.20682944409984, 0.0, 5 * tol));
  EXPECT_LT(tr.steps, 200U);  // adaptive: far fewer steps than a fixed 4th-order method at 1e-10
}

TEST(Dopri5, UnreachableToleranceThrowsSolverErrorInsteadOfLooping) {
  // 1e-300 is inside the allowed (0, 1) but below round-off: the controller shrinks the step until
  // it underflows, which must be reported, not looped on.
  try {
    pendulum::integrate(libration90(2.0), settings_for(Method::DormandPrince5, 0.1, 1e-300));
    FAIL() << "expected SolverError";
  } catch (const rodvv::SolverError& e) {
    EXPECT_EQ(e.method(), "dopri5");
    EXPECT_TRUE(std::isfinite(e.residual()));
    EXPECT_NE(std::string(e.what()).find("error estimate"), std::string::npos) << e.what();
  }
}

// ------------------------------------------------------------------------------------------------
// Energy over 1000 periods (omega = 1, 90 deg, dt = 0.05; dopri5 at tol 1e-8)
//
// Measured late/early = max|E - E0| over the last / first 10 % of the span, and the drift slope:
//   explicit-euler    9.58      +2.4e-2   (energy grows)
//   symplectic-euler  1.000000  +2.5e-9   (bounded; the slope is the oscillation, not a trend)
//   stormer-verlet    1.000000  +9.9e-12
//   rk4               9.89      -2.5e-9   (energy decays)
//   dopri5            9.95      -4.6e-9   (energy decays)
//   rkn4-mclachlan    1.000028  -7.6e-18
// A bounded error repeats the same oscillation extremes in both 100-period windows, so its ratio is
// 1; a linear drift from E0 gives 10. Gates: bounded < 1.1, drifting > 5.

struct EnergyCase {
  Method method;
  int drift_sign;  // 0: bounded (symplectic); +1 grows; -1 decays
};

class EnergyOverThousandPeriods : public ::testing::TestWithParam<EnergyCase> {};

TEST_P(EnergyOverThousandPeriods, SymplecticBoundedOthersDrift) {
  const EnergyCase c = GetParam();
  const auto tr = pendulum::integrate(libration90(1000 * kPeriod90),
                                      settings_for(c.method, 0.05, 1e-8));
  const auto stats = rodvv::invariants::pendulum_energy_statistics(tr, 1.0);
  // E0 = -cos(pi/2) = -6.1e-17: exact up to the rounding of pi/2.
  EXPECT_TRUE(is_close(stats.initial, 0.0, 0.0, kEpsilon));
  ASSERT_GT(stats.early_deviation, 0.0);
  const double ratio = stats.late_deviation / stats.early_deviation;
  RecordProperty("late_over_early", std::to_string(ratio));
  RecordProperty("drift_slope", std::to_string(stats.drift_slope));
  if (c.drift_sign == 0) {
    EXPECT_TRUE(pendulum::info(c.method).symplectic);
    EXPECT_LT(ratio, 1.1);
  } else {
    EXPECT_FALSE(pendulum::info(c.method).symplectic);
    EXPECT_GT(ratio, 5.0);
    EXPECT_GT(c.drift_sign * stats.drift_slope, 0.0) << "slope " << stats.drift_slope;
  }
}

std::string energy_case_name(const ::testing::TestParamInfo<EnergyCase>& info) {
  return camel(pendulum::info(info.param.method).id);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, EnergyOverThousandPeriods,
                         ::testing::Values(EnergyCase{Method::ExplicitEuler, +1},
                                           EnergyCase{Method::SymplecticEuler, 0},
                                           EnergyCase{Method::StormerVerlet, 0},
                                           EnergyCase{Method::RungeKutta4, -1},
                                           EnergyCase{Method::DormandPrince5, -1},
                                           EnergyCase{Method::McLachlanRkn4, 0}),
                         energy_case_name);

// ------------------------------------------------------------------------------------------------
// Time reversibility: the symmetric methods retrace their path when the velocity is flipped.
// Measured after 2 x 1000 steps of dt = 0.05: |dtheta| 2.2e-15 / 6.7e-16, |dtheta_dot| 8.1e-15 /
// 2.1e-14 (Verlet / RKN), i.e. round-off growing like sqrt(steps) to linearly; gate 1000 steps x
// eps x 4 = 8.9e-13 (a linear round-off bound with a factor 4 for the operations per step).
// Symplectic Euler is not symmetric: its return error is O(h) (measured 1e-2).

TEST(TimeReversibility, SymmetricMethodsRetraceTheirPath) {
  const double bound = 1000 * kEpsilon * 4;
  for (Method m : {Method::StormerVerlet, Method::McLachlanRkn4}) {
    const auto s = settings_for(m, 0.05);
    const auto forward = pendulum::integrate(libration90(50.0), s);
    ASSERT_EQ(forward.steps, 1000U);
    const auto back = pendulum::integrate(
        {1.0, forward.theta.back(), -forward.theta_dot.back(), 50.0}, s);
    EXPECT_TRUE(is_close(back.theta.back(), kTheta0, 0.0, bound)) << pendulum::info(m).id;
    EXPECT_TRUE(is_close(back.theta_dot.back(), 0.0, 0.0, bound)) << pendulum::info(m).id;
  }
}

TEST(TimeReversibility, SymplecticEulerIsNotSymmetric) {
  const auto s = settings_for(Method::SymplecticEuler, 0.05);
  const auto forward = pendulum::integrate(libration90(50.0), s);
  const auto back =
      pendulum::integrate({1.0, forward.theta.back(), -forward.theta_dot.back(), 50.0}, s);
  // O(h) (measured 1e-2), five orders of magnitude above the round-off bound of the test above.
  EXPECT_GT(std::abs(back.theta_dot.back()), 1e-4);
}

// ------------------------------------------------------------------------------------------------
// Output grid, record_every and bookkeeping, for every method

class PendulumIntegrator : public ::testing::TestWithParam<Method> {};

TEST_P(PendulumIntegrator, OutputGridIsIndexTimesStep) {
  const double dt = 0.02;
  const auto tr = pendulum::integrate(libration90(2.0), settings_for(GetParam(), dt));
  ASSERT_EQ(tr.size(), 101U);
  ASSERT_EQ(tr.theta.size(), 101U);
  ASSERT_EQ(tr.theta_dot.size(), 101U);
  for (std::size_t i = 0; i < tr.size(); ++i) EXPECT_EQ(tr.t[i], static_cast<double>(i) * dt);
  EXPECT_EQ(tr.theta[0], kTheta0);
  EXPECT_EQ(tr.theta_dot[0], 0.0);
}

TEST_P(PendulumIntegrator, EndTimeOffTheGridIsPassedByLessThanOneStep) {
  const double dt = 0.01;
  const auto tr = pendulum::integrate(libration90(1.005), settings_for(GetParam(), dt));
  ASSERT_EQ(tr.size(), 102U);  // n = ceil(100.5) = 101
  EXPECT_GE(tr.t.back(), 1.005);
  EXPECT_LT(tr.t.back(), 1.005 + dt);
}

TEST_P(PendulumIntegrator, ZeroEndTimeGivesTheInitialStateOnly) {
  const auto tr = pendulum::integrate({2.0, 0.3, -0.4, 0.0}, settings_for(GetParam(), 0.1));
  ASSERT_EQ(tr.size(), 1U);
  EXPECT_EQ(tr.t[0], 0.0);
  EXPECT_EQ(tr.theta[0], 0.3);
  EXPECT_EQ(tr.theta_dot[0], -0.4);
  EXPECT_EQ(tr.steps, 0U);
  EXPECT_EQ(tr.rhs_evaluations, 0U);
}

TEST_P(PendulumIntegrator, RecordEveryKeepsEveryKthPointAndTheLast) {
  const auto s1 = settings_for(GetParam(), 0.02);
  auto s7 = s1;
  s7.record_every = 7;
  const auto all = pendulum::integrate(libration90(2.0), s1);
  const auto some = pendulum::integrate(libration90(2.0), s7);
  ASSERT_EQ(some.size(), 16U);  // i = 0, 7, ..., 98 and the last, 100
  for (std::size_t j = 0; j < some.size(); ++j) {
    const std::size_t i = j + 1 < some.size() ? 7 * j : 100;
    EXPECT_EQ(some.t[j], all.t[i]);
    // Recording does not perturb the integration: identical values, bit for bit.
    EXPECT_EQ(some.theta[j], all.theta[i]);
    EXPECT_EQ(some.theta_dot[j], all.theta_dot[i]);
  }
  EXPECT_EQ(some.steps, all.steps);
  EXPECT_EQ(some.rhs_evaluations, all.rhs_evaluations);
  auto s100 = s1;
  s100.record_every = 100;  // n divisible by k: the last point must not appear twice
  EXPECT_EQ(pendulum::integrate(libration90(2.0), s100).size(), 2U);
}

TEST_P(PendulumIntegrator, CountsStepsAndForceEvaluationsHonestly) {
  const auto tr = pendulum::integrate(libration90(2.0), settings_for(GetParam(), 0.02));
  const std::size_t n = 100;
  switch (GetParam()) {
    case Method::ExplicitEuler:
    case Method::SymplecticEuler:
      EXPECT_EQ(tr.steps, n);
      EXPECT_EQ(tr.rhs_evaluations, n);
      break;
    case Method::StormerVerlet:  // one per step, plus the initial force
      EXPECT_EQ(tr.steps, n);
      EXPECT_EQ(tr.rhs_evaluations, n + 1);
      break;
    case Method::RungeKutta4:
      EXPECT_EQ(tr.steps, n);
      EXPECT_EQ(tr.rhs_evaluations, 4 * n);
      break;
    case Method::McLachlanRkn4:  // 6 stages, all evaluated by odeint
      EXPECT_EQ(tr.steps, n);
      EXPECT_EQ(tr.rhs_evaluations, 6 * n);
      break;
    case Method::DormandPrince5:  // FSAL: 1 initial + 6 per attempted (accepted or rejected) step
      EXPECT_GT(tr.steps, 0U);
      EXPECT_EQ((tr.rhs_evaluations - 1) % 6, 0U);
      EXPECT_GE(tr.rhs_evaluations, 1 + 6 * tr.steps);
      break;
  }
}

TEST_P(PendulumIntegrator, HangingPendulumAtRestStaysAtRest) {
  // theta = 0, theta' = 0 is an equilibrium; every method must keep it exactly (sin 0 = 0).
  const auto tr = pendulum::integrate({3.0, 0.0, 0.0, 10.0}, settings_for(GetParam(), 0.1));
  for (std::size_t i = 0; i < tr.size(); ++i) {
    EXPECT_EQ(tr.theta[i], 0.0);
    EXPECT_EQ(tr.theta_dot[i], 0.0);
  }
}

TEST_P(PendulumIntegrator, NonFiniteStateThrowsSolverError) {
  // theta' = 1e308: theta overflows to inf within two steps of dt = 1.
  try {
    pendulum::integrate({1.0, 0.0, 1e308, 10.0}, settings_for(GetParam(), 1.0));
    FAIL() << "expected SolverError";
  } catch (const rodvv::SolverError& e) {
    EXPECT_EQ(e.method(), pendulum::info(GetParam()).id);
    EXPECT_GE(e.iterations(), 1U);
  }
}

TEST_P(PendulumIntegrator, RejectsBadInputNamingTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto expect_input_error = [&](pendulum::Problem p, pendulum::Settings s,
                                      const std::string& parameter) {
    try {
      pendulum::integrate(p, s);
      ADD_FAILURE() << "expected InputError for " << parameter;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), parameter) << e.what();
    }
  };
  const pendulum::Problem good = libration90(1.0);
  const pendulum::Settings ok = settings_for(GetParam(), 0.1);
  auto p = good;
  for (double bad : {0.0, -1.0, nan, inf}) {
    p = good; p.omega = bad; expect_input_error(p, ok, "omega");
  }
  for (double bad : {nan, inf}) {
    p = good; p.theta0 = bad; expect_input_error(p, ok, "theta0");
    p = good; p.theta_dot0 = bad; expect_input_error(p, ok, "theta_dot0");
  }
  for (double bad : {-1e-300, -1.0, nan, inf}) {
    p = good; p.t_end = bad; expect_input_error(p, ok, "t_end");
  }
  auto s = ok;
  for (double bad : {0.0, -0.1, nan, inf}) {
    s = ok; s.dt = bad; expect_input_error(good, s, "dt");
  }
  for (double bad : {0.0, -1e-8, 1.0, 2.0, nan}) {
    s = ok; s.tolerance = bad; expect_input_error(good, s, "tolerance");
  }
  s = ok; s.record_every = 0; expect_input_error(good, s, "record_every");
  // Absurd sizes: t_end / dt = 1e10 output points is refused before any allocation.
  p = good; p.t_end = 1e9; s = ok; s.dt = 0.1;
  expect_input_error(p, s, "dt");
  s = ok; s.method = static_cast<Method>(42); expect_input_error(good, s, "method");
}

INSTANTIATE_TEST_SUITE_P(AllMethods, PendulumIntegrator,
                         ::testing::Values(Method::ExplicitEuler, Method::SymplecticEuler,
                                           Method::StormerVerlet, Method::RungeKutta4,
                                           Method::DormandPrince5, Method::McLachlanRkn4),
                         method_name);

// A million steps is run in the main job: it must finish quickly (about 20 ms measured for
// Stoermer-Verlet in Release) and with exact bookkeeping.
TEST(PendulumIntegratorScale, MillionStepsWithSparseRecording) {
  auto s = settings_for(Method::StormerVerlet, 1e-4);
  s.record_every = 1000;
  const auto tr = pendulum::integrate(libration90(100.0), s);
  EXPECT_EQ(tr.steps, 1000000U);
  EXPECT_EQ(tr.size(), 1001U);
  EXPECT_EQ(tr.t.back(), 100.0);
}

}  // namespace
