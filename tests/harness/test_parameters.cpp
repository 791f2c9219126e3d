#include <gtest/gtest.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/parameters.hpp"

namespace {

using namespace rodvv::harness;

Parameters sample() {
  return {make_parameter("theta0_deg", 90, 0, 180, true, true, "deg", "release angle"),
          make_parameter("periods", 2, 1, 1e4, false, false, "", "horizon")};
}

TEST(Parameters, AssignmentSetsValue) {
  auto parameters = sample();
  apply_assignment(parameters, "theta0_deg=45.5");
  EXPECT_DOUBLE_EQ(parameter_value(parameters, "theta0_deg"), 45.5);
  apply_assignment(parameters, "periods=1");  // closed lower end
  EXPECT_DOUBLE_EQ(parameter_value(parameters, "periods"), 1.0);
}

TEST(Parameters, RejectsOutOfRangeNamingParameterAndRange) {
  auto parameters = sample();
  try {
    apply_assignment(parameters, "theta0_deg=180");
    FAIL();
  } catch (const rodvv::InputError& error) {
    EXPECT_EQ(error.parameter(), "theta0_deg");
    EXPECT_NE(std::string(error.what()).find("(0, 180)"), std::string::npos) << error.what();
  }
  EXPECT_THROW(apply_assignment(parameters, "periods=0.5"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "theta0_deg=nan"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "theta0_deg=inf"), rodvv::InputError);
  EXPECT_DOUBLE_EQ(parameter_value(parameters, "theta0_deg"), 90.0);  // unchanged after rejection
}

TEST(Parameters, RejectsMalformedAssignments) {
  auto parameters = sample();
  EXPECT_THROW(apply_assignment(parameters, "theta0_deg"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "=3"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "theta0_deg="), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "theta0_deg=3x"), rodvv::InputError);
  try {
    apply_assignment(parameters, "omega=2");
    FAIL();
  } catch (const rodvv::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("theta0_deg, periods"), std::string::npos) << error.what();
  }
}

}  // namespace
