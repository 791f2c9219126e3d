#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/order_fit.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::harness::fit_order;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;

std::vector<std::optional<double>> synthetic_errors(const std::vector<double>& h, double c, double p) {
  std::vector<std::optional<double>> errors;
  for (double value : h) errors.push_back(c * std::pow(value, p));
  return errors;
}

TEST(OrderFit, RecoversKnownOrderExactly) {
  const std::vector<double> h{0.1, 0.05, 0.025, 0.0125};
  for (double p : {1.0, 2.0, 4.0, 0.5}) {
    const auto fit = fit_order(h, synthetic_errors(h, 3.7, p), 3);
    ASSERT_TRUE(fit.least_squares.has_value());
    // log/exp round trips: a few hundred eps relative in p for these magnitudes.
    EXPECT_TRUE(is_close(*fit.least_squares, p, 1e3 * kEpsilon, 1e3 * kEpsilon));
    EXPECT_TRUE(is_close(*fit.r_squared, 1.0, 0.0, 1e3 * kEpsilon));
    EXPECT_EQ(fit.levels_used, 3u);
    ASSERT_EQ(fit.pairwise.size(), 3u);
    for (double pair : fit.pairwise) EXPECT_TRUE(is_close(pair, p, 1e3 * kEpsilon, 1e3 * kEpsilon));
  }
}

TEST(OrderFit, UsesOnlyTheLastLevels) {
  // Pre-asymptotic coarse level: e = h^2 + 100 h^4 deviates at h = 0.4 only.
  const std::vector<double> h{0.4, 0.01, 0.005, 0.0025};
  std::vector<std::optional<double>> errors;
  for (double value : h) errors.push_back(value * value + (value > 0.1 ? 100 * std::pow(value, 4) : 0.0));
  const auto fit = fit_order(h, errors, 3);
  EXPECT_TRUE(is_close(*fit.least_squares, 2.0, 1e-12, 1e-12));
  EXPECT_GT(std::abs(fit.pairwise[0] - 2.0), 0.1);  // the coarse pair sees the h^4 term
}

TEST(OrderFit, NoisyDataGivesRSquaredBelowOne) {
  const std::vector<double> h{0.1, 0.05, 0.025, 0.0125};
  std::vector<std::optional<double>> errors = synthetic_errors(h, 1.0, 2.0);
  *errors[2] *= 1.5;
  const auto fit = fit_order(h, errors, 4);
  ASSERT_TRUE(fit.r_squared.has_value());
  EXPECT_LT(*fit.r_squared, 0.999);
  EXPECT_GT(*fit.r_squared, 0.9);
}

TEST(OrderFit, MissingOrZeroErrorAtFinestLevelsGivesNoFit) {
  const std::vector<double> h{0.1, 0.05, 0.025};
  auto errors = synthetic_errors(h, 1.0, 2.0);
  errors[2] = 0.0;
  EXPECT_FALSE(fit_order(h, errors, 3).least_squares.has_value());
  errors[2] = std::nullopt;
  const auto fit = fit_order(h, errors, 3);
  EXPECT_FALSE(fit.least_squares.has_value());
  EXPECT_TRUE(std::isnan(fit.pairwise[1]));
  EXPECT_FALSE(std::isnan(fit.pairwise[0]));
}

TEST(OrderFit, TooFewLevelsGivesNoLeastSquaresFit) {
  const std::vector<double> h{0.1, 0.05};
  const auto fit = fit_order(h, synthetic_errors(h, 1.0, 2.0), 3);
  EXPECT_FALSE(fit.least_squares.has_value());
  EXPECT_EQ(fit.pairwise.size(), 1u);
}

TEST(OrderFit, RejectsBadInput) {
  const std::vector<double> h{0.1, 0.05, 0.025};
  EXPECT_THROW(fit_order(h, synthetic_errors({0.1, 0.05}, 1, 1), 3), rodvv::InputError);
  EXPECT_THROW(fit_order(h, synthetic_errors(h, 1, 1), 1), rodvv::InputError);
  EXPECT_THROW(fit_order(std::vector<double>{0.1, -0.05, 0.025}, synthetic_errors(h, 1, 1), 3),
               rodvv::InputError);
}

}  // namespace
