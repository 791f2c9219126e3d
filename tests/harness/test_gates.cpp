// Every gate kind passes on a correct solver and fails on a deliberately wrong one.
#include <gtest/gtest.h>

#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/sweep.hpp"
#include "synthetic_case.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::synthetic_case;

SweepResult sweep_with(Case c, std::vector<GateSpec> gates) {
  c.gates = std::move(gates);
  return run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
}

TEST(OrderGate, WindowIsTwoSidedAroundTheory) {
  const auto gate = order_gate("error", 2.0, "test");
  EXPECT_DOUBLE_EQ(gate.lower, 1.9);
  EXPECT_DOUBLE_EQ(gate.upper, 2.5);
}

TEST(OrderGate, PassesWhenObservedOrderMatches) {
  const auto result = sweep_with(synthetic_case(2.0), {order_gate("error", 2.0, "theory")});
  ASSERT_EQ(result.gates.size(), 1u);
  EXPECT_TRUE(result.gates[0].passed) << result.gates[0].reason;
  EXPECT_NEAR(*result.gates[0].measured, 2.0, 1e-12);
  EXPECT_TRUE(result.passed());
}

TEST(OrderGate, FailsForFirstOrderSolverRegisteredAsSecondOrder) {
  const auto result = sweep_with(synthetic_case(1.0), {order_gate("error", 2.0, "claimed order 2")});
  EXPECT_FALSE(result.gates[0].passed);
  EXPECT_NE(result.gates[0].reason.find("outside"), std::string::npos) << result.gates[0].reason;
  EXPECT_FALSE(result.passed());
}

TEST(OrderGate, FailsWhenObservedOrderIsFarAboveTheory) {
  // A fourth-order result registered as second order means the case measures something else.
  const auto result = sweep_with(synthetic_case(4.0), {order_gate("error", 2.0, "claimed order 2")});
  EXPECT_FALSE(result.gates[0].passed);
  EXPECT_GT(*result.gates[0].measured, 2.5);
}

TEST(OrderGate, FailsWithReasonWhenMetricIsUnknown) {
  const auto result = sweep_with(synthetic_case(2.0), {order_gate("no-such-metric", 2.0, "")});
  EXPECT_FALSE(result.gates[0].passed);
  EXPECT_NE(result.gates[0].reason.find("no-such-metric"), std::string::npos);
}

TEST(UpperBoundGate, PassesAndFailsAtTheBound) {
  // Finest error = 0.0125^2 = 1.5625e-4.
  auto result = sweep_with(synthetic_case(2.0),
                           {upper_bound_gate("error", 2e-4, GateScope::FinestLevel, "measured x1.3"),
                            upper_bound_gate("error", 1e-4, GateScope::FinestLevel, "too tight")});
  EXPECT_TRUE(result.gates[0].passed) << result.gates[0].reason;
  EXPECT_FALSE(result.gates[1].passed);
  EXPECT_DOUBLE_EQ(*result.gates[1].measured, 0.0125 * 0.0125);
}

TEST(UpperBoundGate, AllLevelsScopeTakesTheWorstLevel) {
  auto result = sweep_with(synthetic_case(2.0),
                           {upper_bound_gate("error", 2e-4, GateScope::AllLevels, "")});
  EXPECT_FALSE(result.gates[0].passed);
  EXPECT_DOUBLE_EQ(*result.gates[0].measured, 0.01);  // coarsest level 0.1^2
}

TEST(UpperBoundGate, NegativeOrderBoundsAQuantityThatGrowsUnderRefinement) {
  // e = 3 h^-1 (round-off-like growth: 30 ... 240): C h^-1 with C = 3.03 holds at every level,
  // C = 2.97 fails at every level, and a constant bound of 3.03 (order 0) fails.
  auto result = sweep_with(synthetic_case(-1.0, 3.0),
                           {scaled_upper_bound_gate("error", 3.03, -1.0, GateScope::AllLevels, "follows N"),
                            scaled_upper_bound_gate("error", 2.97, -1.0, GateScope::AllLevels, "too tight"),
                            upper_bound_gate("error", 3.03, GateScope::AllLevels, "constant")});
  EXPECT_TRUE(result.gates[0].passed) << result.gates[0].reason;
  EXPECT_FALSE(result.gates[1].passed);
  EXPECT_FALSE(result.gates[2].passed);
}

TEST(LowerBoundGate, FailsWhenValueIsBelowBound) {
  auto result = sweep_with(synthetic_case(2.0),
                           {lower_bound_gate("error", 1e-4, GateScope::AllLevels, "must exceed"),
                            lower_bound_gate("error", 1e-3, GateScope::AllLevels, "must exceed")});
  EXPECT_TRUE(result.gates[0].passed) << result.gates[0].reason;
  EXPECT_FALSE(result.gates[1].passed);
  EXPECT_DOUBLE_EQ(*result.gates[1].measured, 0.0125 * 0.0125);
}

TEST(BoundGate, FailsOnLevelFailureAndNonFiniteValues) {
  Case c = synthetic_case(2.0);
  c.run_level = [](const Parameters&, double h) -> LevelOutput {
    if (h < 0.02) throw rodvv::SolverError("newton", "did not converge", 20, 1e-3);
    LevelOutput output;
    output.metrics["error"] = {h, 0.0, h < 0.03 ? std::nan("") : h};
    return output;
  };
  auto result = sweep_with(c, {upper_bound_gate("error", 1.0, GateScope::FinestLevel, ""),
                               upper_bound_gate("error", 1.0, GateScope::AllLevels, "")});
  EXPECT_FALSE(result.gates[0].passed);
  EXPECT_NE(result.gates[0].reason.find("did not converge"), std::string::npos) << result.gates[0].reason;
  EXPECT_FALSE(result.gates[1].passed);
  EXPECT_TRUE(result.levels.back().failure.has_value());
  EXPECT_FALSE(result.passed());
}

}  // namespace
