// Tests of the pendulum energy invariant (invariants/include/rodvv/invariants/energy.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/trajectory.hpp"
#include "rodvv/invariants/energy.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::Trajectory;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
namespace inv = rodvv::invariants;

TEST(PendulumEnergy, MatchesTheDefinitionAndItsLongDoubleInstance) {
  // E = 1/2 theta'^2 - omega^2 cos theta (PHYSICS.md §0). At theta = 0: exact arithmetic.
  EXPECT_EQ(inv::pendulum_energy(0.0, 2.0, 3.0), 0.5 * 4.0 - 9.0);
  // Hanging at rest: the minimum -omega^2; at the separatrix top speed 2 omega: +omega^2.
  EXPECT_EQ(inv::pendulum_energy(0.0, 0.0, 1.5), -2.25);
  EXPECT_EQ(inv::pendulum_energy(0.0, 2.0 * 1.5, 1.5), 2.25);
  // Template on the scalar (ARCHITECTURE convention 2): the double path agrees with long double
  // to a few ulps of the largest term (|omega^2 cos| ~ 4): 4 eps relative.
  const double d = inv::pendulum_energy(1.1, -0.7, 2.0);
  const long double ld = inv::pendulum_energy(1.1L, -0.7L, 2.0L);
  EXPECT_TRUE(is_close(d, static_cast<double>(ld), 0.0, 4 * kEpsilon * 4.0));
}

Trajectory sample_trajectory() {
  Trajectory tr;
  for (int i = 0; i <= 20; ++i) tr.record(0.1 * i, std::sin(0.3 * i), std::cos(0.7 * i));
  return tr;
}

TEST(PendulumEnergy, HistoryEvaluatesEverySample) {
  const Trajectory tr = sample_trajectory();
  const std::vector<double> e = inv::pendulum_energy_history(tr, 1.3);
  ASSERT_EQ(e.size(), tr.size());
  for (std::size_t i = 0; i < e.size(); ++i)
    EXPECT_EQ(e[i], inv::pendulum_energy(tr.theta[i], tr.theta_dot[i], 1.3));  // same expression
  EXPECT_TRUE(inv::pendulum_energy_history(Trajectory{}, 1.0).empty());
}

// A synthetic trajectory whose energy is exactly E(t) = a + b t in real arithmetic: theta = 0
// (cos 0 = 1 exactly), theta' = sqrt(2 (a + b t + omega^2)).
struct LinearEnergy {
  Trajectory trajectory;
  double a, b, span;
};

LinearEnergy linear_energy(double a, double b, double omega, std::size_t n, double span) {
  LinearEnergy out{{}, a, b, span};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = span * static_cast<double>(i) / static_cast<double>(n - 1);
    out.trajectory.record(t, 0.0, std::sqrt(2.0 * (a + b * t + omega * omega)));
  }
  return out;
}

TEST(PendulumEnergyStatistics, LinearEnergyGivesItsSlopeAndIntercept) {
  const double omega = 1.0;
  const LinearEnergy lin = linear_energy(0.5, 1e-3, omega, 1001, 100.0);
  const auto stats = inv::pendulum_energy_statistics(lin.trajectory, omega);
  const std::vector<double> e = inv::pendulum_energy_history(lin.trajectory, omega);
  // delta = max_i |E_i - (a + b t_i)|: the rounding of sqrt and of the square (measured, a few eps).
  double delta = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i)
    delta = std::max(delta, std::abs(e[i] - (lin.a + lin.b * lin.trajectory.t[i])));
  EXPECT_LE(delta, 8 * kEpsilon);  // |E| <= 0.6, so this is ~13 ulps: sanity of the synthetic data
  // Sensitivity of a least-squares line to a perturbation |delta_i| <= delta on uniform samples:
  // |db| <= delta sum|t - tm| / sum (t - tm)^2 = 3 delta / T (continuum limit; 1 % margin for the
  // discrete sums), |da| <= delta + |db| T / 2 = 2.5 delta; plus 16 eps for the fit's own round-off.
  EXPECT_TRUE(is_close(stats.drift_slope, lin.b, 16 * kEpsilon, 1.01 * 3 * delta / lin.span));
  EXPECT_TRUE(is_close(stats.drift_intercept, lin.a, 16 * kEpsilon, 2.5 * delta + 16 * kEpsilon));
  EXPECT_EQ(stats.initial, e[0]);
  // Deviations from E0 grow linearly: max over the first 10 % of the span is b * 10, over the last
  // 10 % and overall b * 100 (exact in real arithmetic; 2 delta for the two energies subtracted).
  EXPECT_TRUE(is_close(stats.early_deviation, lin.b * 10.0, 0.0, 2 * delta));
  EXPECT_TRUE(is_close(stats.late_deviation, lin.b * 100.0, 0.0, 2 * delta));
  EXPECT_TRUE(is_close(stats.max_abs_deviation, lin.b * 100.0, 0.0, 2 * delta));
}

TEST(PendulumEnergyStatistics, WindowsSeeOnlyTheirOwnEnds) {
  // E(t) = a + c sin(pi t / T): zero deviation at both ends, c in the middle. The first and the last
  // 10 % of the span see at most c sin(0.1 pi) = 0.309 c, the whole run c: a late window that spanned
  // the middle (issue 13: its start computed from the wrong end) reports c.
  const double omega = 1.3, a = 0.2, c = 1e-3, span = 50.0;
  Trajectory trajectory;
  const std::size_t n = 2001;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = span * static_cast<double>(i) / static_cast<double>(n - 1);
    const double energy = a + c * std::sin(std::numbers::pi * t / span);
    trajectory.record(t, 0.0, std::sqrt(2.0 * (energy + omega * omega)));
  }
  const auto stats = inv::pendulum_energy_statistics(trajectory, omega);
  const double edge = c * std::sin(0.1 * std::numbers::pi);
  // the energies are rebuilt from sqrt and squares: a few eps of E ~ 2 (1e-15), far below c
  EXPECT_NEAR(stats.early_deviation, edge, 1e-12);
  EXPECT_NEAR(stats.late_deviation, edge, 1e-12);
  EXPECT_NEAR(stats.max_abs_deviation, c, 1e-12);
}

TEST(PendulumEnergyStatistics, TinyDriftOnALargeEnergyIsResolved) {
  // Centred sums: a drift of 1e-12 per unit time on E ~ 1e3 over 1e5 samples. The one-pass formula
  // (sum t E - n tm Em) / (sum t^2 - n tm^2) was measured at 9.79e-13 here (2 % off, 400x the
  // tolerance); the centred one must be within 3 delta / T = 5e-17, delta = 1.7e-13 being the
  // measured rounding of E (~1e3 eps).
  const double omega = 30.0;  // omega^2 = 900: E0 ~ 1e3
  const LinearEnergy lin = linear_energy(100.0, 1e-12, omega, 100001, 1e4);
  const auto stats = inv::pendulum_energy_statistics(lin.trajectory, omega);
  const std::vector<double> e = inv::pendulum_energy_history(lin.trajectory, omega);
  double delta = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i)
    delta = std::max(delta, std::abs(e[i] - (lin.a + lin.b * lin.trajectory.t[i])));
  EXPECT_TRUE(is_close(stats.drift_slope, lin.b, 0.0, 1.01 * 3 * delta / lin.span))
      << "delta " << delta;
}

TEST(PendulumEnergyStatistics, ConstantEnergyHasZeroSlopeAndDeviation) {
  Trajectory tr;
  for (int i = 0; i < 50; ++i) tr.record(0.25 * i, 0.0, 1.0);
  const auto stats = inv::pendulum_energy_statistics(tr, 2.0);
  EXPECT_EQ(stats.initial, 0.5 - 4.0);
  EXPECT_EQ(stats.drift_slope, 0.0);
  EXPECT_EQ(stats.drift_intercept, 0.5 - 4.0);
  EXPECT_EQ(stats.max_abs_deviation, 0.0);
  EXPECT_EQ(stats.early_deviation, 0.0);
  EXPECT_EQ(stats.late_deviation, 0.0);
}

TEST(PendulumEnergyStatistics, SingleSampleHasNoTrend) {
  Trajectory tr;
  tr.record(3.0, 0.0, 2.0);
  const auto stats = inv::pendulum_energy_statistics(tr, 1.0);
  EXPECT_EQ(stats.initial, 1.0);
  EXPECT_EQ(stats.drift_slope, 0.0);
  EXPECT_EQ(stats.drift_intercept, 1.0);
  EXPECT_EQ(stats.max_abs_deviation, 0.0);
}

TEST(PendulumEnergyStatistics, RejectsBadInputNamingTheParameter) {
  const auto expect_input_error = [](const Trajectory& tr, double omega, const char* parameter) {
    try {
      inv::pendulum_energy_statistics(tr, omega);
      ADD_FAILURE() << "expected InputError for " << parameter;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), parameter) << e.what();
    }
  };
  const Trajectory good = sample_trajectory();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double omega : {0.0, -1.0, nan, std::numeric_limits<double>::infinity()})
    expect_input_error(good, omega, "omega");
  expect_input_error(Trajectory{}, 1.0, "trajectory");
  Trajectory unequal = good;
  unequal.theta.pop_back();
  expect_input_error(unequal, 1.0, "trajectory");
  unequal = good;
  unequal.theta_dot.push_back(0.0);
  expect_input_error(unequal, 1.0, "trajectory");
  Trajectory unordered = good;
  unordered.t[5] = unordered.t[4];
  expect_input_error(unordered, 1.0, "trajectory.t");
  Trajectory nan_time = good;
  nan_time.t[3] = nan;
  expect_input_error(nan_time, 1.0, "trajectory.t");
  Trajectory nan_state = good;
  nan_state.theta_dot[7] = nan;
  expect_input_error(nan_state, 1.0, "trajectory");
  // The history validates too.
  EXPECT_THROW(inv::pendulum_energy_history(good, 0.0), rodvv::InputError);
  EXPECT_THROW(inv::pendulum_energy_history(unequal, 1.0), rodvv::InputError);
}

}  // namespace
