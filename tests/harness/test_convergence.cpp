// evaluate_convergence (convergence.hpp): a convergence study gated without a case gives the verdict a
// case's sweep gives on the same numbers, can fail, and refuses malformed studies by name.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "rodvv/harness/convergence.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"
#include "rodvv/testing/input_error.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::input_error_parameter_of;

// Errors 0.3 h^2 (1 + h) of a quantity of size 2 at h = 1/8 .. 1/64.
CaseInfo study_info() {
  CaseInfo info;
  info.name = "user/second-order";
  info.resolution = {"N", "elements", ResolutionScale::Count, {8, 16, 32, 64}, {}, 0.0};
  info.metrics = {{"tip", MetricKind::Error, "", "tip deflection", true, 2.0}};
  return info;
}

std::vector<LevelResult> study_levels(double order) {
  std::vector<LevelResult> levels;
  for (double n : {8.0, 16.0, 32.0, 64.0}) {
    LevelResult level;
    level.level = n;
    level.h = 1.0 / n;
    const double error = 0.3 * std::pow(level.h, order) * (1.0 + level.h);
    level.metrics["tip"] = {2.0 + error, 2.0, error};
    levels.push_back(level);
  }
  return levels;
}

TEST(EvaluateConvergence, SecondOrderStudyPassesItsOrderAndResolutionGates) {
  const auto result = evaluate_convergence(study_info(), study_levels(2.0), {order_gate("tip", 2.0, "theory")});
  ASSERT_EQ(result.gates.size(), 2u);  // the order gate and the resolution gate added beside it
  EXPECT_EQ(result.gates[1].name, resolution_gate("tip").name);
  EXPECT_TRUE(result.passed()) << result.gates[0].reason << " | " << result.gates[1].reason;
  ASSERT_EQ(result.analyses.size(), 1u);
  EXPECT_NEAR(*result.analyses[0].order.least_squares, 2.0, 0.1);
  EXPECT_TRUE(result.analyses[0].richardson.has_value()) << result.analyses[0].richardson_note.value_or("");
}

TEST(EvaluateConvergence, FirstOrderStudyFailsASecondOrderGate) {
  const auto result = evaluate_convergence(study_info(), study_levels(1.0), {order_gate("tip", 2.0, "claimed")});
  EXPECT_FALSE(result.gates[0].passed);
  EXPECT_FALSE(result.passed());
}

TEST(EvaluateConvergence, UnresolvedStudyFailsItsResolutionGate) {
  auto levels = study_levels(2.0);
  for (auto& level : levels) level.metrics["tip"].error = *level.metrics["tip"].error * 1e4;  // 53 .. 0.74 of 2
  const auto result = evaluate_convergence(study_info(), levels, {order_gate("tip", 2.0, "theory")});
  EXPECT_TRUE(result.gates[0].passed);   // the order alone is right
  EXPECT_FALSE(result.gates[1].passed);  // but the error is not small against the quantity
}

TEST(EvaluateConvergence, SameVerdictAsTheCasesSweep) {
  const Case* c = default_registry().find("pendulum/libration-90/rk4");
  ASSERT_NE(c, nullptr);
  const SweepResult sweep = run_sweep(*c, c->info.parameters, c->info.resolution.default_levels);
  std::vector<GateSpec> gates;
  for (const auto& gate : c->gates)
    if (gate.kind != GateKind::Regression) gates.push_back(gate);
  const SweepResult alone = evaluate_convergence(sweep.info, sweep.levels, gates, c->fit_levels);
  ASSERT_EQ(alone.gates.size(), sweep.gates.size());
  for (std::size_t i = 0; i < sweep.gates.size(); ++i) {
    EXPECT_EQ(alone.gates[i].name, sweep.gates[i].name);
    EXPECT_EQ(alone.gates[i].passed, sweep.gates[i].passed);
    EXPECT_EQ(alone.gates[i].measured, sweep.gates[i].measured);  // bit for bit: the same functions
  }
}

TEST(EvaluateConvergence, MalformedStudiesAreInputErrorsNamingTheArgument) {
  const auto gate = order_gate("tip", 2.0, "theory");
  EXPECT_EQ(input_error_parameter_of([&] { evaluate_convergence(study_info(), {}, {gate}); }), "levels");
  auto reversed = study_levels(2.0);
  std::swap(reversed[0], reversed[3]);
  EXPECT_EQ(input_error_parameter_of([&] { evaluate_convergence(study_info(), reversed, {gate}); }), "levels");
  auto zero_h = study_levels(2.0);
  zero_h[3].h = 0.0;
  EXPECT_EQ(input_error_parameter_of([&] { evaluate_convergence(study_info(), zero_h, {gate}); }), "levels");
  EXPECT_EQ(input_error_parameter_of([&] {
              evaluate_convergence(study_info(), study_levels(2.0), {order_gate("root", 2.0, "no such metric")});
            }),
            "gates");
  GateSpec regression = gate;
  regression.kind = GateKind::Regression;
  EXPECT_EQ(input_error_parameter_of([&] { evaluate_convergence(study_info(), study_levels(2.0), {regression}); }),
            "gates");
  EXPECT_EQ(input_error_parameter_of([&] { evaluate_convergence(study_info(), study_levels(2.0), {gate}, 1); }),
            "fit_levels");
}

// A parameter study (ResolutionScale::Parameter: the levels are a physical parameter, not a mesh): no order is
// fitted (a slope against 1 / level would mean nothing), a bound gate is evaluated as in any sweep, an order
// gate is refused, and the registry refuses a case that declares one.
TEST(EvaluateConvergence, AParameterStudyFitsNoOrderAndRefusesOrderGates) {
  CaseInfo info = study_info();
  info.resolution.scale = ResolutionScale::Parameter;
  const auto bounded = evaluate_convergence(info, study_levels(2.0), {upper_bound_gate("tip", 0.01, GateScope::AllLevels, "")});
  ASSERT_EQ(bounded.analyses.size(), 1u);
  EXPECT_FALSE(bounded.analyses[0].order.least_squares.has_value());
  EXPECT_TRUE(bounded.analyses[0].order.pairwise.empty());
  EXPECT_FALSE(bounded.analyses[0].richardson.has_value());
  ASSERT_EQ(bounded.gates.size(), 1u);
  EXPECT_TRUE(bounded.passed()) << bounded.gates[0].reason;  // 0.3 h^2 (1 + h) <= 0.0053
  // The same numbers as a mesh study fit the order 2.
  EXPECT_NEAR(*evaluate_convergence(study_info(), study_levels(2.0), {}).analyses[0].order.least_squares, 2.0, 0.1);
  EXPECT_EQ(input_error_parameter_of([&] { evaluate_convergence(info, study_levels(2.0), {order_gate("tip", 2.0, "")}); }),
            "gates");
  Case c;
  c.info = info;
  c.gates = {order_gate("tip", 2.0, "")};
  Registry registry;
  EXPECT_THROW(registry.add(c), std::logic_error);
  c.gates = {upper_bound_gate("tip", 0.01, GateScope::AllLevels, "")};
  EXPECT_NO_THROW(registry.add(c));
}

}  // namespace
