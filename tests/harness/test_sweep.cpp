#include <gtest/gtest.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"
#include "rodvv/testing/tolerance.hpp"
#include "synthetic_case.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::synthetic_case;

TEST(Sweep, FillsLevelsAnalysesAndRichardson) {
  Case c = synthetic_case(2.0, 0.5);
  const auto result = run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
  ASSERT_EQ(result.levels.size(), 4u);
  EXPECT_DOUBLE_EQ(result.levels[0].h, 0.1);
  EXPECT_DOUBLE_EQ(result.levels[0].metrics.at("error").computed, 0.5 * 0.01);
  ASSERT_EQ(result.analyses.size(), 2u);
  const auto& value = result.analyses[1];
  ASSERT_TRUE(value.richardson.has_value()) << value.richardson_note.value_or("");
  // value = 1 + 0.5 h^2 exactly: the extrapolation recovers 1 to the round-off of the differences.
  EXPECT_TRUE(rodvv::testing::is_close(value.richardson->extrapolated, 1.0, 1e-12, 0.0));
  EXPECT_FALSE(result.analyses[0].richardson.has_value());  // not marked extrapolable
}

// Each level records the process CPU time it took beside its wall time (a real case: thousands of
// Stoermer-Verlet steps per level, well above the clock's resolution).
TEST(Sweep, RecordsCpuTimePerLevel) {
  const Case* c = default_registry().find("pendulum/long-time-energy/stormer-verlet");
  ASSERT_NE(c, nullptr);
  const SweepResult result = run_sweep(*c, c->info.parameters, c->info.resolution.default_levels);
  for (const auto& level : result.levels) {
    EXPECT_GT(level.cpu_seconds, 0.0);
    EXPECT_LT(level.cpu_seconds, 10.0 * level.wall_seconds + 0.01);  // one thread: CPU ~ wall
  }
}

// Every solver family's iteration loop checks the level's time budget: past it each level fails
// naming the budget and the sweep goes on (no input hangs a run; issue 14 class 3).
TEST(Sweep, EverySolverLoopStopsAtTheLevelBudget) {
  for (const char* name : {"elastica/mattiasson-2/polygon", "elastica-contact/cavity-point/polygon",
                           "elastica-contact/cavity-point/polygon-lcp", "sleeve/eshelby", "eulerian1d/impact",
                           "superhelix/mattiasson-2", "superhelix/energy-decay", "rod3d/mattiasson-2",
                           "rod3d/energy-in-time", "knot/trefoil-nodal"}) {
    const Case* c = default_registry().find(name);
    ASSERT_NE(c, nullptr) << name;
    const SweepResult result = run_sweep(*c, c->info.parameters, c->info.resolution.default_levels, {}, 1e-9);
    for (const auto& level : result.levels) {
      ASSERT_TRUE(level.failure.has_value()) << name << " level " << level.level;
      EXPECT_NE(level.failure->find("exceeded its time budget of 1e-09 s per level"), std::string::npos)
          << name << ": " << *level.failure;
    }
    EXPECT_FALSE(result.passed()) << name;
  }
}

TEST(Sweep, CountResolutionFitsInOneOverN) {
  Case c = synthetic_case(2.0);
  c.info.resolution = {"N", "elements", ResolutionScale::Count, {8, 16, 32}, {}};
  c.run_level = [](const Parameters&, double n) {
    LevelOutput output;
    output.metrics["error"] = {1.0 / (n * n), 0.0, 1.0 / (n * n)};
    return output;
  };
  c.gates = {order_gate("error", 2.0, "")};
  const auto result = run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
  EXPECT_TRUE(result.gates[0].passed) << result.gates[0].reason;
  EXPECT_DOUBLE_EQ(result.levels[2].h, 1.0 / 32);
}

TEST(Sweep, RejectsBadLevels) {
  Case c = synthetic_case(2.0);
  c.gates = {order_gate("error", 2.0, "")};
  const std::vector<double> coarsening{0.1, 0.2, 0.05}, too_few{0.1, 0.05}, negative{0.1, -0.05, 0.01},
      not_a_number{0.1, std::nan(""), 0.01};
  EXPECT_THROW(validate_levels(c, coarsening), rodvv::InputError);
  EXPECT_THROW(validate_levels(c, too_few), rodvv::InputError);
  EXPECT_THROW(validate_levels(c, negative), rodvv::InputError);
  EXPECT_THROW(validate_levels(c, not_a_number), rodvv::InputError);
  EXPECT_THROW(validate_levels(c, {}), rodvv::InputError);
  c.info.resolution.scale = ResolutionScale::Count;
  const std::vector<double> fractional{8, 16.5, 32};
  EXPECT_THROW(validate_levels(c, fractional), rodvv::InputError);
  // A parameter study's levels increase like a count's but need not be whole (an angle of 12.5 degrees), and
  // stop at the largest the case honours.
  c.gates = {};
  c.info.resolution = {"angle", "degrees", ResolutionScale::Parameter, {10, 20, 30}, {}, 35.0};
  const std::vector<double> angles{10, 12.5, 30}, decreasing{30, 20, 10}, beyond{10, 20, 40};
  EXPECT_NO_THROW(validate_levels(c, angles));
  EXPECT_THROW(validate_levels(c, decreasing), rodvv::InputError);
  EXPECT_THROW(validate_levels(c, beyond), rodvv::InputError);
}

// A window on a combination of parameters is both listed (info.parameter_windows, for `list -v`) and
// checked before any level runs, after the case's earlier checks.
TEST(Sweep, ParameterWindowsAreListedAndCheckedAfterEarlierChecks) {
  Case c = synthetic_case(2.0);
  int earlier_calls = 0;
  c.check_parameters = [&earlier_calls](const Parameters&) { ++earlier_calls; };
  require_window(c, "c <= 10", [](const Parameters& p) {
    if (parameter_value(p, "c") > 10.0) throw rodvv::InputError("c", "c must be <= 10");
  });
  ASSERT_EQ(c.info.parameter_windows, std::vector<std::string>{"c <= 10"});
  EXPECT_NO_THROW(run_sweep(c, c.info.parameters, c.info.resolution.default_levels));
  EXPECT_EQ(earlier_calls, 1);
  Parameters outside = c.info.parameters;
  outside[0].value = 20.0;
  EXPECT_THROW(run_sweep(c, outside, c.info.resolution.default_levels), rodvv::InputError);
  EXPECT_EQ(earlier_calls, 2);
}

// An InputError from inside a level is the user's only when it names the case's own input (a
// parameter, the resolution): then the run ends with it (exit 2). Naming anything else (an input
// the case built, e.g. a rest shape that does not hold its target) it is that level's failure and the
// sweep goes on.
TEST(Sweep, AnInputErrorNamingNoParameterOfTheCaseIsALevelFailure) {
  Case c = synthetic_case(2.0);
  const LevelRunner original = c.run_level;
  c.run_level = [original](const Parameters& p, double level) {
    if (level == 0.05) throw rodvv::InputError("q", "invalid parameter 'q': not an equilibrium");
    return original(p, level);
  };
  const SweepResult result = run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
  std::size_t failed = 0;
  for (const auto& level : result.levels)
    if (level.failure) {
      ++failed;
      EXPECT_NE(level.failure->find("not a parameter of the case"), std::string::npos) << *level.failure;
    }
  EXPECT_EQ(failed, 1u);
  EXPECT_FALSE(result.passed());
  Case named = synthetic_case(2.0);
  named.run_level = [](const Parameters&, double) -> LevelOutput { throw rodvv::InputError("c", "c is wrong"); };
  EXPECT_THROW(run_sweep(named, named.info.parameters, named.info.resolution.default_levels), rodvv::InputError);
}

// Every case's defaults lie inside its own windows (a window that refused them would refuse the run
// `rodvv run` makes by default), and every listed window is a non-empty statement.
TEST(Registry, EveryCaseAcceptsItsDefaultsInsideItsWindows) {
  for (const Case* c : default_registry().select({})) {
    if (c->check_parameters) {
      EXPECT_NO_THROW(c->check_parameters(c->info.parameters)) << c->info.name;
    }
    for (const auto& window : c->info.parameter_windows) EXPECT_FALSE(window.empty()) << c->info.name;
  }
}

TEST(Registry, SelectsByNamePrefixAndGlob) {
  Registry registry;
  for (const char* name : {"a/x/one", "a/x/two", "a/y/one", "b/z/one"}) {
    Case c = synthetic_case(1.0);
    c.info.name = name;
    registry.add(c);
  }
  const auto names = [&](std::vector<std::string> patterns) {
    std::vector<std::string> out;
    for (const Case* c : registry.select(patterns)) out.push_back(c->info.name);
    return out;
  };
  EXPECT_EQ(names({}).size(), 4u);
  EXPECT_EQ(names({"a/x/one"}), (std::vector<std::string>{"a/x/one"}));
  EXPECT_EQ(names({"a"}).size(), 3u);
  EXPECT_EQ(names({"a/x"}).size(), 2u);
  EXPECT_EQ(names({"*/one"}).size(), 3u);
  EXPECT_EQ(names({"a/x", "a/x/one"}).size(), 2u);  // no duplicates
  EXPECT_EQ(names({"a/"}).size(), 3u);
  EXPECT_THROW(registry.select(std::vector<std::string>{"nope"}), rodvv::InputError);
  EXPECT_THROW(registry.select(std::vector<std::string>{"a/x/on"}), rodvv::InputError);
  registry.add(synthetic_case(1.0));
  EXPECT_THROW(registry.add(synthetic_case(1.0)), std::logic_error);
}

}  // namespace
