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

namespace {

// Whole-number and on/off parameters take only values of their form (issue: hardening, class 2):
// nothing is rounded silently, and the message says what is allowed.
TEST(Parameters, CountsAndSwitchesRefuseOtherValues) {
  using namespace rodvv::harness;
  Parameters p{integer_parameter("N", 8, 2, 64, "number of edges"), switch_parameter("projection", true, "on/off")};
  apply_assignment(p, "N=16");
  EXPECT_EQ(parameter_value(p, "N"), 16.0);
  apply_assignment(p, "N=+32");
  EXPECT_EQ(parameter_value(p, "N"), 32.0);
  apply_assignment(p, "projection=0");
  EXPECT_EQ(parameter_value(p, "projection"), 0.0);
  const auto message_of = [&](const char* assignment) {
    try {
      apply_assignment(p, assignment);
    } catch (const rodvv::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message_of("N=8.4").find("must be a whole number in [2, 64]"), std::string::npos);
  EXPECT_NE(message_of("N=65").find("must be a whole number in [2, 64]"), std::string::npos);
  EXPECT_NE(message_of("projection=0.5").find("must be 0 (off) or 1 (on)"), std::string::npos);
  EXPECT_NE(message_of("projection=1e400").find("out of the range of a double"), std::string::npos);
  EXPECT_EQ(parameter_value(p, "N"), 32.0);  // refused values leave the parameter as it was
  EXPECT_EQ(describe_allowed(p[0]), "a whole number in [2, 64]");
}

}  // namespace
