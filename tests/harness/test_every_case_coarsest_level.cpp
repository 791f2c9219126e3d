// Every registered case solves its coarsest default level and gives finite metrics. Cheap in the
// release preset; its point is the asan preset, where it runs every case's code (tying, relaxing,
// contact, measuring) under AddressSanitizer and UndefinedBehaviorSanitizer. That is what lets the
// tests that repeat a case's whole sweep to check its verdict (the knot and inverse families' sweeps,
// minutes each under the sanitizers) run in the release preset only (RODVV_RELEASE_PRESET_ONLY): the
// sanitizers see the same code at the coarsest level, and the verdict does not depend on the preset.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "case_test_support.hpp"

namespace {

using namespace rodvv::harness;

class EveryCase : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> every_case_name() {
  std::vector<std::string> names;
  for (const auto& c : default_registry().cases()) names.push_back(c.info.name);
  return names;
}

TEST_P(EveryCase, CoarsestLevelRunsAndGivesFiniteMetrics) {
  const Case& c = rodvv::testing::named_case(GetParam());
  ASSERT_FALSE(c.info.resolution.default_levels.empty()) << GetParam();
  const double coarsest = c.info.resolution.default_levels.front();
  const LevelOutput out = c.run_level(c.info.parameters, coarsest);
  ASSERT_FALSE(out.metrics.empty()) << GetParam() << " at level " << coarsest;
  for (const auto& [name, sample] : out.metrics) {
    EXPECT_TRUE(std::isfinite(sample.computed)) << GetParam() << ": " << name << " = " << sample.computed;
    if (sample.error) EXPECT_TRUE(std::isfinite(*sample.error)) << GetParam() << ": " << name << " error";
    if (sample.reference) EXPECT_TRUE(std::isfinite(*sample.reference)) << GetParam() << ": " << name << " reference";
  }
}

INSTANTIATE_TEST_SUITE_P(AllCases, EveryCase, ::testing::ValuesIn(every_case_name()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           return rodvv::testing::test_name_of_case(param_info.param);
                         });

}  // namespace
