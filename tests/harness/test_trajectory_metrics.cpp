#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::is_close;

rodvv::Trajectory sampled(double dt, double t_end, double omega, double amplitude) {
  rodvv::Trajectory trajectory;
  for (int i = 0; i * dt <= t_end; ++i) {
    const double t = i * dt;
    trajectory.record(t, amplitude * std::cos(omega * t), -amplitude * omega * std::sin(omega * t));
  }
  return trajectory;
}

TEST(CrossingTimes, HermiteLocationIsFourthOrderAccurate) {
  // theta = cos(t) crosses zero at pi/2 + j pi; the Hermite cubic locates it with error O(dt^4).
  const double pi = std::numbers::pi;
  double previous_error = 0.0;
  for (double dt : {0.2, 0.1, 0.05}) {
    const auto times = crossing_times(sampled(dt, 10.0, 1.0, 1.0), 0.0, 0.0);
    ASSERT_EQ(times.size(), 3u);
    double error = 0.0;
    for (std::size_t j = 0; j < times.size(); ++j)
      error = std::max(error, std::abs(times[j] - (pi / 2 + double(j) * pi)));
    if (previous_error > 0.0) {
      EXPECT_GT(previous_error / error, 12.0);  // 2^4 = 16 ideally
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-6);
}

TEST(CrossingTimes, PeriodFromCrossings) {
  const auto times = crossing_times(sampled(0.01, 20.0, 2.0, 0.5), 0.0, 0.0);
  const auto period = period_from_crossings(times, 2.0);
  ASSERT_TRUE(period.has_value());
  // Hermite location error ~ dt^4 / 384 * |theta''''| ~ 1e-10 here.
  EXPECT_TRUE(is_close(*period, std::numbers::pi, 0.0, 1e-9));
  EXPECT_FALSE(period_from_crossings({1.0}, 2.0).has_value());
}

TEST(CrossingTimes, EvenlySpacedValuesForRotation) {
  // theta = 3 t crosses pi + 2 pi j at t = (pi + 2 pi j) / 3, sampled exactly (linear motion).
  rodvv::Trajectory trajectory;
  for (int i = 0; i <= 100; ++i) trajectory.record(0.1 * i, 0.3 * i, 3.0);
  const auto times = crossing_times(trajectory, std::numbers::pi, 2 * std::numbers::pi);
  ASSERT_EQ(times.size(), 5u);  // theta reaches 30: values pi, 3pi, ..., 9pi
  EXPECT_TRUE(is_close(times[4], 9 * std::numbers::pi / 3, 1e-14, 0.0));
}

TEST(ComparisonIndices, StrideDoublesWithSamplesSoTimesCoincide) {
  const auto coarse = comparison_indices(4097, 2048);
  const auto fine = comparison_indices(8193, 2048);
  ASSERT_EQ(coarse.size(), fine.size());
  for (std::size_t i = 0; i < coarse.size(); ++i) EXPECT_EQ(2 * coarse[i], fine[i]);
  EXPECT_EQ(comparison_indices(10, 2048).size(), 10u);
}

TEST(ThinSeries, KeepsPeaks) {
  std::vector<double> x(1000), y(1000, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = double(i);
  y[537] = -5.0;
  const auto series = thin_series("s", "x", "y", x, y, 100);
  EXPECT_EQ(series.x.size(), 100u);
  EXPECT_NE(std::find(series.y.begin(), series.y.end(), -5.0), series.y.end());
}

}  // namespace
