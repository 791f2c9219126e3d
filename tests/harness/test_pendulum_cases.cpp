// The pendulum cases pass at their default levels, and their gates turn red on deliberately wrong
// solvers (a solver run under another method's gates).
#include <gtest/gtest.h>

#include <string>

#include "rodvv/common/errors.hpp"
#include "case_test_support.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::run_at_default_levels;

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }
SweepResult run_default(const Case& c) { return run_at_default_levels(c); }

class PendulumCase : public ::testing::TestWithParam<std::string> {};

TEST_P(PendulumCase, PassesAtDefaultLevels) {
  const auto result = run_default(named(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  return rodvv::testing::test_name_of_case(info.param);
}

INSTANTIATE_TEST_SUITE_P(AllPendulumCases, PendulumCase, ::testing::ValuesIn(rodvv::testing::case_names_of_family("pendulum")),
                         test_name);

TEST(PendulumCatalogue, HasEveryMotionAndMethod) {
  const auto names = rodvv::testing::case_names_of_family("pendulum");
  // 5 motions x 6 methods + 5 fixed-step methods in the long-time energy group.
  EXPECT_EQ(names.size(), 35u);
  for (const auto& c : default_registry().cases()) {
    EXPECT_GE(c.info.resolution.default_levels.size(), c.fit_levels) << c.info.name;
    EXPECT_FALSE(c.info.citation.empty()) << c.info.name;
  }
}

// A first-order method under a second-order method's gates: the order gate must fail.
TEST(PendulumGatesHaveTeeth, ExplicitEulerUnderVerletGatesFails) {
  Case wrong = named("pendulum/libration-90/stormer-verlet");
  wrong.run_level = named("pendulum/libration-90/explicit-euler").run_level;
  const auto result = run_default(wrong);
  EXPECT_FALSE(result.passed());
  EXPECT_FALSE(result.gates.front().passed) << result.gates.front().reason;
}

// A fourth-order method under a second-order method's gates: the order is far above the window.
TEST(PendulumGatesHaveTeeth, Rk4UnderVerletGatesFailsFromAbove) {
  Case wrong = named("pendulum/libration-90/stormer-verlet");
  wrong.run_level = named("pendulum/libration-90/rk4").run_level;
  const auto result = run_default(wrong);
  ASSERT_TRUE(result.gates.front().measured.has_value());
  EXPECT_GT(*result.gates.front().measured, 2.5);
  EXPECT_FALSE(result.passed());
}

// RK4 drifts: under the symplectic bounded-energy gates it must fail, and Verlet under RK4's
// "must drift" gate must fail too: the contrast gates both ways.
TEST(PendulumGatesHaveTeeth, EnergyContrastSeparatesSymplecticFromNot) {
  Case drifting = named("pendulum/long-time-energy/stormer-verlet");
  drifting.run_level = named("pendulum/long-time-energy/rk4").run_level;
  EXPECT_FALSE(run_default(drifting).passed());

  Case bounded = named("pendulum/long-time-energy/rk4");
  bounded.run_level = named("pendulum/long-time-energy/stormer-verlet").run_level;
  EXPECT_FALSE(run_default(bounded).passed());
}

TEST(PendulumCases, RejectInvalidParameters) {
  const Case& rotation = named("pendulum/rotation/rk4");
  Parameters parameters = rotation.info.parameters;
  EXPECT_THROW(apply_assignment(parameters, "v0_over_omega=1.5"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "omega=-1"), rodvv::InputError);
  Parameters libration = named("pendulum/libration-90/rk4").info.parameters;
  EXPECT_THROW(apply_assignment(libration, "theta0_deg=180"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(libration, "periods=0"), rodvv::InputError);
}

}  // namespace

namespace {

// The cases state everything in the time unit 1/omega (pendulum_cases.cpp, Units): their results
// do not depend on omega beyond round-off, and their measured bounds are evaluated, not skipped, at
// another omega. A solver that used omega where it needs omega^2 would be right at omega = 1 only;
// at the default omega = 2.7 its error would be O(1).
TEST(PendulumUnits, ResultsDoNotDependOnOmega) {
  // Round-off of ~1e3 steps relative to errors >= 1e-7: 1e-6 relative is a wide margin.
  rodvv::testing::expect_results_free_of_units(named("pendulum/libration-90/stormer-verlet"), {{"omega", 0.37}}, 1e-6,
                                               0.0);
}

// dopri5's tolerance mixes theta and theta' (rad/time): omega is not a unit scale there, and its
// measured bounds are skipped at another omega.
TEST(PendulumUnits, AdaptiveToleranceIsNotOmegaFree) {
  const Case& c = named("pendulum/libration-90/dopri5");
  Parameters other = c.info.parameters;
  set_parameter(other, "omega", 0.37);
  const auto result = run_sweep(c, other, c.info.resolution.default_levels);
  EXPECT_FALSE(result.skipped_gates.empty());
}

}  // namespace
