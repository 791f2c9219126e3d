#pragma once
// The one tolerance helper of the test suites (ARCHITECTURE.md, convention 5).
// A value passes when |actual - expected| <= max(abs_floor, rel_tol * |expected|). On failure the
// message gives the index (for arrays), both values, the difference, the difference in units of
// machine epsilon relative to |expected|, and the tolerance, so that a red test says how far off it is.
// Every call site states in a comment why its tolerance is what it is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <span>
#include <sstream>

namespace rodvv::testing {

inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// |error| in units of epsilon relative to max(|scale|, 1): how references report accuracy.
inline double in_epsilons(double error, double scale = 1.0) {
  return std::abs(error) / (kEpsilon * std::max(std::abs(scale), 1.0));
}

inline ::testing::AssertionResult is_close(double actual, double expected, double rel_tol,
                                           double abs_floor, std::ptrdiff_t index = -1) {
  const double difference = std::abs(actual - expected);
  const double tolerance = std::max(abs_floor, rel_tol * std::abs(expected));
  if (std::isfinite(actual) && std::isfinite(expected) && difference <= tolerance)
    return ::testing::AssertionSuccess();
  std::ostringstream out;
  out << std::setprecision(17);
  if (index >= 0) out << "at index " << index << ": ";
  out << "actual " << actual << " vs expected " << expected << ", |difference| " << difference
      << " (" << std::setprecision(3) << in_epsilons(difference, expected) << " eps)"
      << std::setprecision(17) << " > tolerance " << tolerance << " (rel " << rel_tol << ", abs "
      << abs_floor << ")";
  return ::testing::AssertionFailure() << out.str();
}

inline ::testing::AssertionResult all_close(std::span<const double> actual,
                                            std::span<const double> expected, double rel_tol,
                                            double abs_floor) {
  if (actual.size() != expected.size())
    return ::testing::AssertionFailure()
           << "size mismatch: " << actual.size() << " vs " << expected.size();
  for (std::size_t i = 0; i < actual.size(); ++i) {
    auto result = is_close(actual[i], expected[i], rel_tol, abs_floor, static_cast<std::ptrdiff_t>(i));
    if (!result) return result;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace rodvv::testing
