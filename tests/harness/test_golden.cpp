// Regression gates (golden.hpp): identical results pass with deviation 0; a change of an error
// constant by 10 % (and by 1e-4) fails, round-off in the last digits passes; failure states,
// missing metrics and non-default parameters are handled as documented.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "rodvv/harness/golden.hpp"
#include "rodvv/harness/sweep.hpp"
#include "synthetic_case.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::synthetic_case;

struct Fixture {
  Case c = synthetic_case(2.0, 0.7);
  SweepResult result = run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
  Goldens goldens{{c.info.name, golden_of(result)}};
};

GateResult gate_of(const Fixture& f, const SweepResult& now) {
  std::string why;
  const auto gate = regression_gate(f.c, now, f.goldens, &why);
  EXPECT_TRUE(gate) << why;
  return gate.value_or(GateResult{});
}

TEST(Golden, IdenticalResultsPassWithNoDeviation) {
  const Fixture f;
  const GateResult gate = gate_of(f, f.result);
  EXPECT_TRUE(gate.passed);
  EXPECT_EQ(gate.kind, GateKind::Regression);
  EXPECT_EQ(*gate.measured, 0.0);
  EXPECT_NE(gate.reason.find("8 values at 4 levels identical"), std::string::npos) << gate.reason;
}

TEST(Golden, AChangedErrorConstantFailsAndRoundOffPasses) {
  const Fixture f;
  for (const double factor : {1.1, 1.0 + 1e-4}) {
    // A defect that scales the method's error constant: every error (and value) moves by the factor.
    Case moved = f.c;
    moved.run_level = [original = f.c.run_level, factor](const Parameters& p, double h) {
      LevelOutput out = original(p, h);
      for (auto& [name, sample] : out.metrics) {
        *sample.error *= factor;
        sample.computed = (name == "value" ? 1.0 : 0.0) + *sample.error;
      }
      return out;
    };
    const SweepResult relabelled = run_sweep(moved, f.c.info.parameters, f.c.info.resolution.default_levels);
    const GateResult gate = gate_of(f, relabelled);
    EXPECT_FALSE(gate.passed) << factor;
    EXPECT_GT(*gate.measured, 1.0) << factor;
    EXPECT_NE(gate.reason.find("largest change"), std::string::npos);
  }
  // Round-off: every value and error nudged by 4 ulps.
  SweepResult nudged = f.result;
  for (auto& level : nudged.levels)
    for (auto& [name, sample] : level.metrics) {
      sample.computed = std::nextafter(std::nextafter(sample.computed, 1e300), 1e300);
      if (sample.error) *sample.error *= 1.0 + 4e-16;
    }
  const GateResult gate = gate_of(f, nudged);
  EXPECT_TRUE(gate.passed) << gate.reason;
  EXPECT_GT(*gate.measured, 0.0);
  EXPECT_LT(*gate.measured, 1e-3);
}

// A metric at round-off (Case::golden_absolute) is held to its stated absolute tolerance, the others as before.
TEST(Golden, AMetricAtRoundOffIsHeldToItsAbsoluteTolerance) {
  Fixture f;
  const std::string metric = f.result.levels.front().metrics.begin()->first;
  f.c.golden_absolute[metric] = 0.5;
  for (const auto& [shift, passes] : {std::pair{0.3, true}, std::pair{0.7, false}}) {
    SweepResult moved = f.result;
    for (auto& level : moved.levels) {
      auto& sample = level.metrics.at(metric);
      sample.computed += shift;
      if (sample.error) *sample.error += shift;
    }
    const GateResult gate = gate_of(f, moved);
    EXPECT_EQ(gate.passed, passes) << shift << ": " << gate.reason;
  }
  // The tolerance is the metric's own: the same shift of another metric fails.
  SweepResult other = f.result;
  for (auto& level : other.levels)
    for (auto& [name, sample] : level.metrics)
      if (name != metric) sample.computed += 0.3;
  EXPECT_FALSE(gate_of(f, other).passed);
}

TEST(Golden, FailureStateAndMissingMetricsAreChanges) {
  const Fixture f;
  SweepResult failed = f.result;
  failed.levels[2].failure = "Newton: no convergence";
  failed.levels[2].metrics.clear();
  EXPECT_FALSE(gate_of(f, failed).passed);
  SweepResult missing = f.result;
  missing.levels[0].metrics.erase("value");
  const GateResult gate = gate_of(f, missing);
  EXPECT_FALSE(gate.passed);
  EXPECT_NE(gate.reason.find("metric gone"), std::string::npos) << gate.reason;
  SweepResult nan = f.result;
  nan.levels[1].metrics["error"].computed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(gate_of(f, nan).passed);
}

TEST(Golden, SkippedAwayFromTheDefaultsOrWithoutGoldens) {
  const Fixture f;
  std::string why;
  SweepResult other = f.result;
  other.info.parameters[0].value = 2.0;
  EXPECT_FALSE(regression_gate(f.c, other, f.goldens, &why));
  EXPECT_NE(why.find("default parameters"), std::string::npos);
  EXPECT_FALSE(regression_gate(f.c, f.result, Goldens{}, &why));
  EXPECT_NE(why.find("rodvv bless"), std::string::npos);
  // Levels in common only: a sweep at other levels compares nothing.
  const SweepResult elsewhere = run_sweep(f.c, f.c.info.parameters, std::vector<double>{0.3, 0.2, 0.15});
  EXPECT_FALSE(regression_gate(f.c, elsewhere, f.goldens, &why));
  EXPECT_NE(why.find("no level in common"), std::string::npos);
}

TEST(Golden, DiagnosticsAreNotCompared) {
  Fixture f;
  f.c.info.metrics.push_back({"iterations", MetricKind::Diagnostic, "", "Newton iterations", false, std::nullopt});
  SweepResult with = f.result;
  with.info = f.c.info;
  for (auto& level : with.levels) level.metrics["iterations"] = {7.0, std::nullopt, std::nullopt};
  const GoldenCase golden = golden_of(with);
  for (const auto& level : golden.levels) EXPECT_FALSE(level.metrics.count("iterations"));
}

}  // namespace
