// The eulerian1d cases pass at their default levels, and their gates turn red on deliberately wrong
// input: a solution with jumps under the smooth case's order gate, the barrier cases with the
// position projection switched off (the edge then crosses the wall by ~1e-6), and bad parameters.
#include <gtest/gtest.h>

#include <string>

#include "rodvv/common/errors.hpp"
#include "case_test_support.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::named_case;
using rodvv::testing::run_at_default_levels;

class EulerianCase : public ::testing::TestWithParam<std::string> {};

TEST_P(EulerianCase, PassesAtDefaultLevels) {
  const auto result = run_at_default_levels(named_case(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  return rodvv::testing::test_name_of_case(info.param);
}

INSTANTIATE_TEST_SUITE_P(AllEulerianCases, EulerianCase,
                         ::testing::ValuesIn(rodvv::testing::case_names_of_family("eulerian1d")), test_name);

TEST(EulerianCatalogue, HasTheSixCasesWithGatesOnMass) {
  const auto names = rodvv::testing::case_names_of_family("eulerian1d");
  EXPECT_EQ(names.size(), 6u);
  for (const auto& name : names) {
    const Case& c = named_case(name);
    EXPECT_GE(c.info.resolution.default_levels.size(), c.fit_levels) << name;
    bool mass_gated = false;
    for (const auto& gate : c.gates) mass_gated = mass_gated || gate.metric == "mass_error";
    EXPECT_TRUE(mass_gated) << name;
  }
}

// The squeeze (strain jumps, order ~0.5) under the standing wave's order-1 window must fail: the
// order gate separates smooth from non-smooth convergence.
TEST(EulerianGatesHaveTeeth, JumpSolutionFailsTheSmoothOrderGate) {
  Case wrong = named_case("eulerian1d/standing-wave");
  const LevelRunner squeeze = named_case("eulerian1d/squeeze").run_level;
  const Parameters squeeze_parameters = named_case("eulerian1d/squeeze").info.parameters;
  wrong.run_level = [squeeze, squeeze_parameters](const Parameters&, double level) {
    LevelOutput out = squeeze(squeeze_parameters, 2 * level);  // standing-wave levels 100.. -> 200..
    out.metrics["end_max_error"] = out.metrics.at("length_max_error");
    return out;
  };
  const auto result = run_at_default_levels(wrong);
  ASSERT_FALSE(result.gates.empty());
  EXPECT_FALSE(result.gates.front().passed) << result.gates.front().reason;
  ASSERT_TRUE(result.gates.front().measured.has_value());
  EXPECT_LT(*result.gates.front().measured, 0.7);
}

// Without the position projection the velocity-level constraint alone lets the advected edge cross
// the wall by O(1e-6): the round-off penetration gate must catch it, in both barrier cases.
TEST(EulerianGatesHaveTeeth, BarrierCasesFailWithoutPositionProjection) {
  for (const std::string name : {"eulerian1d/impact", "eulerian1d/seed-collision"}) {
    const Case& c = named_case(name);
    Parameters parameters = c.info.parameters;
    set_parameter(parameters, "projection", 0.0);
    const auto result = run_sweep(c, parameters, c.info.resolution.default_levels);
    bool penetration_failed = false;
    for (const auto& gate : result.gates)
      if (gate.metric == "max_penetration") penetration_failed = !gate.passed;
    EXPECT_TRUE(penetration_failed) << name;
  }
}

// A mass loss of 1e-11 (far below anything a plot would show) must fail the mass gate.
TEST(EulerianGatesHaveTeeth, MassGateCatchesASmallLoss) {
  Case wrong = named_case("eulerian1d/translation");
  const LevelRunner original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    LevelOutput out = original(p, level);
    out.metrics["mass_error"].computed += 1e-11;
    out.metrics["mass_error"].error = out.metrics["mass_error"].computed;
    return out;
  };
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

// The round-off gate that follows the parameters: evaluated (evidence) where the 1e-12 bounds are
// skipped, it passes at v0 = 10, at tiny and huge scales and at the ends of the ranges that needed
// its per-cell term (2 steps at L0 = 1e3, cfl = 1); it measures a real round-off (not 0), which a
// bound of half the measured value rejects.
TEST(EulerianGatesHaveTeeth, TranslationRoundOffFollowsTheParameters) {
  const Case& c = named_case("eulerian1d/translation");
  for (const char* assignment : {"v0=10", "L0=1e-2", "kappa=1e6", "L0=1e3", "cfl=1", "t_end=0.01", "kappa=0.01"}) {
    Parameters p = c.info.parameters;
    apply_assignment(p, assignment);
    const SweepResult result = run_sweep(c, p, c.info.resolution.default_levels);
    ASSERT_EQ(result.gates.size(), 1u) << assignment;  // the measured bounds are skipped
    EXPECT_TRUE(result.passed()) << assignment << ": " << result.gates[0].reason;
  }
  const SweepResult at_defaults = run_at_default_levels(c);
  double worst = 0.0;
  for (const auto& level : at_defaults.levels) worst = std::max(worst, level.metrics.at("roundoff_per_step").computed);
  EXPECT_GT(worst, 0.05);
  EXPECT_LE(worst, 4.0);
  Case tight = c;
  tight.gates = {upper_bound_gate("roundoff_per_step", 0.5 * worst, GateScope::AllLevels, "half the measured")};
  EXPECT_FALSE(run_at_default_levels(tight).passed());
}

TEST(EulerianCases, RejectInvalidParameters) {
  auto expect_rejected = [](const std::string& case_name, const std::string& assignment, const std::string& name) {
    const Case& c = named_case(case_name);
    Parameters parameters = c.info.parameters;
    try {
      apply_assignment(parameters, assignment);
      run_sweep(c, parameters, c.info.resolution.default_levels);
      ADD_FAILURE() << case_name << " accepted " << assignment;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  };
  expect_rejected("eulerian1d/translation", "kappa=0", "kappa");
  expect_rejected("eulerian1d/translation", "rho0=-1", "rho0");
  expect_rejected("eulerian1d/squeeze", "cfl=0", "cfl");
  expect_rejected("eulerian1d/squeeze", "cfl=1.5", "cfl");
  expect_rejected("eulerian1d/squeeze", "F0=1", "F0");
  expect_rejected("eulerian1d/standing-wave", "amplitude=0.32", "amplitude");  // A pi > L0: F < 0
  expect_rejected("eulerian1d/impact", "v0=1", "v0");                          // v0 = c: F = 0
  expect_rejected("eulerian1d/seed-collision", "right_wall=0.5", "right_wall");  // overlaps the bar
  // A non-positive grid size is not a level.
  const Case& c = named_case("eulerian1d/squeeze");
  const std::vector<double> bad_levels = {0.0, 100.0, 200.0};
  EXPECT_THROW(run_sweep(c, c.info.parameters, bad_levels), rodvv::InputError);
}

}  // namespace
