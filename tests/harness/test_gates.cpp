// Every gate kind passes on a correct solver and fails on a deliberately wrong one.
#include <gtest/gtest.h>

#include <algorithm>

#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/registry.hpp"
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

// A range gate brackets a mixed-order error: orders 1 to 2 pass, 0.5 and 3 do not.
TEST(OrderGate, RangeGatePassesInsideTheBracketedOrdersOnly) {
  const auto gate = order_range_gate("error", 1.0, 2.0, "mixed");
  EXPECT_EQ(gate.name, "order of error in [1, 2]");
  EXPECT_DOUBLE_EQ(gate.lower, 0.9);
  EXPECT_DOUBLE_EQ(gate.upper, 2.5);
  for (const double order : {1.0, 1.5, 2.0}) EXPECT_TRUE(sweep_with(synthetic_case(order), {gate}).passed()) << order;
  for (const double order : {0.5, 3.0}) EXPECT_FALSE(sweep_with(synthetic_case(order), {gate}).passed()) << order;
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

// ---- resolution gates: the magnitude beside every order --------------------------------------------

TEST(ResolutionGate, FailsASweepThatConvergesAtTheRightOrderButResolvesNothing) {
  // Issue 14's meaningless pass: errors 1e3 times the quantity that shrink exactly as h^2.
  const auto unresolved = sweep_with(synthetic_case(2.0, 1e7), {order_gate("value", 2.0, "theory"), resolution_gate("value")});
  EXPECT_TRUE(unresolved.gates[0].passed) << unresolved.gates[0].reason;
  EXPECT_FALSE(unresolved.gates[1].passed) << unresolved.gates[1].reason;
  EXPECT_NEAR(*unresolved.gates[1].measured, 1e7 * 0.0125 * 0.0125, 1e-6);  // error / |reference 1|
  EXPECT_FALSE(unresolved.passed());
  // The same sweep resolved: 1e-4 of the quantity at the finest level.
  const auto resolved = sweep_with(synthetic_case(2.0, 0.64), {order_gate("value", 2.0, "theory"), resolution_gate("value")});
  EXPECT_TRUE(resolved.passed()) << resolved.gates[1].reason;
  // At the boundary: just above and just below a tenth of the quantity.
  const double at_tenth = kResolvedFraction / (0.0125 * 0.0125);
  EXPECT_FALSE(sweep_with(synthetic_case(2.0, 1.001 * at_tenth), {resolution_gate("value")}).passed());
  EXPECT_TRUE(sweep_with(synthetic_case(2.0, 0.999 * at_tenth), {resolution_gate("value")}).passed());
}

TEST(ResolutionGate, AStatedScaleOverridesTheReferenceAndNoSizeIsAFailureNamingIt) {
  Case c = synthetic_case(2.0, 100.0);  // finest error 1.5625e-2
  // "error" has reference 0 and no stated scale: its relative error is unknown, which is not a pass.
  const auto unknown = sweep_with(c, {resolution_gate("error")});
  EXPECT_FALSE(unknown.passed());
  EXPECT_NE(unknown.gates[0].reason.find("no size"), std::string::npos) << unknown.gates[0].reason;
  const auto runner = c.run_level;
  const auto with_scale = [runner](double scale) {
    return [runner, scale](const Parameters& p, double h) {
      LevelOutput output = runner(p, h);
      output.metrics["error"].scale = output.metrics["value"].scale = scale;
      return output;
    };
  };
  c.run_level = with_scale(1.0);
  const auto sized = sweep_with(c, {resolution_gate("error"), resolution_gate("value")});
  EXPECT_TRUE(sized.passed());
  EXPECT_DOUBLE_EQ(*sized.gates[0].measured, 100.0 * 0.0125 * 0.0125);
  c.run_level = with_scale(0.1);  // the reference 1 is not the size: 0.1 is (error 0.156 of it)
  const auto small = sweep_with(c, {resolution_gate("value")});
  EXPECT_FALSE(small.passed()) << small.gates[0].reason;
  EXPECT_DOUBLE_EQ(*small.gates[0].measured, 100.0 * 0.0125 * 0.0125 / 0.1);
}

TEST(ResolutionGate, EveryOrderGetsOneOnceAndItHoldsAwayFromTheDefaults) {
  std::vector<GateSpec> gates{order_gate("value", 2.0, ""), order_gate("value", 2.0, "again"),
                              order_gate("error", 2.0, ""), upper_bound_gate("value", 1.0, GateScope::AllLevels, "")};
  add_resolution_gates(gates);
  add_resolution_gates(gates);  // idempotent
  ASSERT_EQ(gates.size(), 6u);
  EXPECT_TRUE(gates[4].relative && gates[4].metric == "value" && !gates[4].measured);
  EXPECT_TRUE(gates[5].relative && gates[5].metric == "error");
  // A bound measured at the defaults is skipped at other parameters; the resolution gate is not.
  Case c = synthetic_case(2.0);
  GateSpec measured = scaled_upper_bound_gate("value", 2.0, 2.0, GateScope::FinestLevel, "measured");
  measured.measured = true;
  c.gates = {order_gate("value", 2.0, ""), measured};
  add_resolution_gates(c.gates);
  Parameters other = c.info.parameters;
  set_parameter(other, "c", 1e7);
  const auto result = run_sweep(c, other, c.info.resolution.default_levels);
  ASSERT_EQ(result.gates.size(), 2u);  // order and resolution; the measured bound skipped
  EXPECT_EQ(result.skipped_gates.size(), 1u);
  EXPECT_TRUE(result.gates[0].passed);
  EXPECT_FALSE(result.gates[1].passed) << result.gates[1].reason;
}

TEST(ResolutionGate, EveryRegisteredOrderGateHasOne) {
  for (const Case& c : default_registry().cases())
    for (const GateSpec& order : c.gates) {
      if (order.kind != GateKind::Order) continue;
      const auto beside = std::count_if(c.gates.begin(), c.gates.end(), [&](const GateSpec& g) {
        return g.relative && g.metric == order.metric && g.upper == kResolvedFraction;
      });
      EXPECT_EQ(beside, 1) << c.info.name << ": " << order.name;
    }
}

}  // namespace
