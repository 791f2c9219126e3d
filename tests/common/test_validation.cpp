#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Validation, AcceptsValuesInRange) {
  EXPECT_NO_THROW(rodvv::require_positive("omega", 1e-300));
  EXPECT_NO_THROW(rodvv::require_non_negative("t_end", 0.0));
  EXPECT_NO_THROW(rodvv::require_open_interval("theta0", 1.0, 0.0, M_PI));
  EXPECT_NO_THROW(rodvv::require_closed_interval("k", 1.0, 0.0, 1.0));
  EXPECT_NO_THROW(rodvv::require_at_least("N", 1, 1));
}

TEST(Validation, RejectsOutOfRangeAndNaNNamingTheParameter) {
  try {
    rodvv::require_positive("omega", -1.0);
    FAIL() << "expected InputError";
  } catch (const rodvv::InputError& error) {
    EXPECT_EQ(error.parameter(), "omega");
    EXPECT_STREQ(error.what(), "invalid parameter 'omega' = -1: must be a finite number > 0");
  }
  EXPECT_THROW(rodvv::require_positive("omega", 0.0), rodvv::InputError);
  EXPECT_THROW(rodvv::require_positive("omega", kNaN), rodvv::InputError);
  EXPECT_THROW(rodvv::require_positive("omega", kInf), rodvv::InputError);
  EXPECT_THROW(rodvv::require_non_negative("t_end", -1e-300), rodvv::InputError);
  EXPECT_THROW(rodvv::require_open_interval("theta0", M_PI, 0.0, M_PI), rodvv::InputError);
  EXPECT_THROW(rodvv::require_open_interval("theta0", kNaN, 0.0, M_PI), rodvv::InputError);
  EXPECT_THROW(rodvv::require_closed_interval("k", 1.0000001, 0.0, 1.0), rodvv::InputError);
  EXPECT_THROW(rodvv::require_greater("v0", 2.0, 2.0), rodvv::InputError);
  EXPECT_THROW(rodvv::require_at_least("N", 0, 1), rodvv::InputError);
  EXPECT_THROW(rodvv::require_finite("x", kNaN), rodvv::InputError);
}

TEST(Validation, FiniteVectorNamesTheComponent) {
  EXPECT_NO_THROW(rodvv::require_finite_vector("gravity", rodvv::Vec3(0.0, -9.81, 1e300)));
  try {
    rodvv::require_finite_vector("gravity", rodvv::Vec3(0.0, kNaN, 1.0));
    FAIL() << "a NaN component passed";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "gravity[1]");
  }
  EXPECT_THROW(rodvv::require_finite_vector("end_force", rodvv::Vec3(0.0, 0.0, -kInf)), rodvv::InputError);
}

TEST(Validation, FormatsValuesSoTheyRoundTrip) {
  EXPECT_EQ(rodvv::format_value(0.1), "0.1");
  EXPECT_EQ(rodvv::format_value(kNaN), "NaN");
  EXPECT_EQ(rodvv::format_value(-kInf), "-inf");
}

TEST(SolverErrorMessage, CarriesIterationsAndResidual) {
  const rodvv::SolverError error("newton", "did not converge", 50, 1.5e-3);
  EXPECT_EQ(error.iterations(), 50u);
  EXPECT_DOUBLE_EQ(error.residual(), 1.5e-3);
  EXPECT_NE(std::string(error.what()).find("after 50 iterations, residual 0.0015"), std::string::npos);
}

}  // namespace
