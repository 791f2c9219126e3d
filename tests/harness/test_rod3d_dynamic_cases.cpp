// The rod3d dynamic cases (rod3d/modes, rod3d/energy-in-time) pass at their default levels, and
// their gates turn red on deliberately wrong claims or perturbed constants: a solver whose mass is
// doubled, a reference frequency off by 0.1 %, a first-order energy loss claimed at second order,
// a second-order energy error claimed at first, and a time step twice the one reported.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case_test_support.hpp"
#include "rodvv/harness/parameters.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::run_at_default_levels;

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }

TEST(Rod3dDynamicCases, ModesPassAtDefaultLevels) {
  const auto result = run_at_default_levels(named("rod3d/modes"));
  EXPECT_TRUE(result.passed()) << failing_gates(result);
  EXPECT_EQ(result.gates.size(), 19u);  // with a resolution gate beside each of the 6 orders
}

TEST(Rod3dDynamicCases, EnergyInTimePassesAtDefaultLevels) {
  const auto result = run_at_default_levels(named("rod3d/energy-in-time"));
  EXPECT_TRUE(result.passed()) << failing_gates(result);
  EXPECT_EQ(result.gates.size(), 7u);  // with a resolution gate beside each of the 2 orders
}

TEST(Rod3dDynamicCasesHaveTeeth, DoubledMassSeenByTheSolverOnlyFails) {
  // rho S and rho I0 doubled in the solver, not in the closed forms: every frequency falls by
  // 1/sqrt(2), a relative error of 0.29 >> the bounds C h^2 (<= 1e-3 at N = 64).
  Case wrong = named("rod3d/modes");
  const auto runner = wrong.run_level;
  wrong.run_level = [runner](const Parameters& p, double level) {
    Parameters heavy = p;
    set_parameter(heavy, "rhoS", 2.0 * parameter_value(p, "rhoS"));
    set_parameter(heavy, "rhoI0", 2.0 * parameter_value(p, "rhoI0"));
    LevelOutput solved = runner(heavy, level);
    const LevelOutput exact = runner(p, level);
    for (auto& [name, sample] : solved.metrics) {
      if (name.rfind("omega", 0) != 0) continue;
      sample.reference = exact.metrics.at(name).reference;
      sample.error = std::abs(sample.computed - *sample.reference) / *sample.reference;
    }
    return solved;
  };
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

TEST(Rod3dDynamicCasesHaveTeeth, ReferenceFrequencyOffByATenthOfAPercentFails) {
  // A 1e-3 relative slip of the reference (e.g. a rounded beta_1 L) is 25x the measured error of
  // omega1 at N = 64 (3.9e-5): the measured bound (2x) turns red, and the error stops converging.
  Case wrong = named("rod3d/modes");
  const auto runner = wrong.run_level;
  wrong.run_level = [runner](const Parameters& p, double level) {
    LevelOutput out = runner(p, level);
    auto& s = out.metrics.at("omega1_EI1");
    s.reference = *s.reference * (1.0 + 1e-3);
    s.error = std::abs(s.computed - *s.reference) / *s.reference;
    return out;
  };
  const auto result = run_at_default_levels(wrong);
  EXPECT_FALSE(result.passed());
  int red = 0;
  for (const auto& gate : result.gates)
    if (!gate.passed) {
      ++red;
      EXPECT_NE(gate.name.find("omega1_EI1"), std::string::npos) << gate.name;
    }
  EXPECT_EQ(red, 2);  // its order gate and its bound
}

TEST(Rod3dDynamicCasesHaveTeeth, WrongEnergyOrdersFail) {
  Case euler = named("rod3d/energy-in-time");
  euler.gates = {order_gate("euler_energy_loss", 2.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(euler).passed());
  Case midpoint = named("rod3d/energy-in-time");
  midpoint.gates = {order_gate("midpoint_energy_error", 1.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(midpoint).passed());
}

TEST(Rod3dDynamicCasesHaveTeeth, TimeStepTwiceTheReportedOneFails) {
  // The solver steps with 2 dt while the sweep reports dt: the orders are unchanged, but the
  // midpoint error is 4x and the Euler loss 2x the measured constants: the bounds (2x) turn red.
  Case wrong = named("rod3d/energy-in-time");
  const auto runner = wrong.run_level;
  wrong.run_level = [runner](const Parameters& p, double dt) { return runner(p, 2.0 * dt); };
  const auto result = run_at_default_levels(wrong);
  EXPECT_FALSE(result.passed());
  bool midpoint_bound_red = false;
  for (const auto& gate : result.gates)
    if (!gate.passed && gate.name.find("midpoint_energy_error") != std::string::npos) midpoint_bound_red = true;
  EXPECT_TRUE(midpoint_bound_red) << failing_gates(result);
}

}  // namespace
