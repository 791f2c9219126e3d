// The elastica cases pass at their default levels, and their gates turn red on deliberately wrong
// solvers: the polygon run under the arcs' exactness gates, and a drifting H under a conservation
// gate.
#include <gtest/gtest.h>

#include <cctype>
#include <string>

#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"

namespace {

using namespace rodvv::harness;

std::vector<std::string> elastica_case_names() {
  std::vector<std::string> names;
  for (const auto& c : default_registry().cases())
    if (c.info.family == "elastica") names.push_back(c.info.name);
  return names;
}

const Case& named(const std::string& name) {
  const Case* c = default_registry().find(name);
  if (!c) throw std::logic_error("no case " + name);
  return *c;
}

SweepResult run_default(const Case& c) {
  return run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
}

std::string failures(const SweepResult& result) {
  std::string text;
  for (const auto& gate : result.gates)
    if (!gate.passed) text += "\n  " + gate.name + ": " + gate.reason;
  for (const auto& level : result.levels)
    if (level.failure) text += "\n  level failed: " + *level.failure;
  return text;
}

class ElasticaCase : public ::testing::TestWithParam<std::string> {};

TEST_P(ElasticaCase, PassesAtDefaultLevels) {
  const auto result = run_default(named(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failures(result);
  EXPECT_FALSE(result.gates.empty());
}

INSTANTIATE_TEST_SUITE_P(AllElasticaCases, ElasticaCase, ::testing::ValuesIn(elastica_case_names()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           std::string name;
                           for (char ch : param_info.param)
                             name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : 'X';
                           return name;
                         });

TEST(ElasticaCatalogue, HasBothSchemesForEveryProblem) {
  // 4 columns + displacement control + 4 cantilevers + roll-up + tapered + curved, x 2 schemes.
  EXPECT_EQ(elastica_case_names().size(), 24u);
}

// The arcs are exact for the rolled-up circle; the polygon is only second order: under the arcs'
// round-off gate the polygon must fail.
TEST(ElasticaGatesHaveTeeth, PolygonUnderArcsExactnessGateFails) {
  Case wrong = named("elastica/roll-up/arcs");
  wrong.run_level = named("elastica/roll-up/polygon").run_level;
  EXPECT_FALSE(run_default(wrong).passed());
}

// On a tapered rod H is not conserved: a conservation gate on its drift must fail, while the
// predicted drift explains it (the case's own gate passes).
TEST(ElasticaGatesHaveTeeth, TaperedRodViolatesConservationButMatchesPrediction) {
  Case conserved = named("elastica/tapered/arcs");
  conserved.gates = {upper_bound_gate("H_drift", 1e-3, GateScope::AllLevels, "H conserved?")};
  const auto result = run_default(conserved);
  EXPECT_FALSE(result.passed());
  EXPECT_GT(*result.gates.front().measured, 0.05);  // H moves by O(0.1) along the rod
  EXPECT_TRUE(run_default(named("elastica/tapered/arcs")).passed());
}

// Claiming fourth order for a second-order discretisation fails the order window.
TEST(ElasticaGatesHaveTeeth, SecondOrderSchemeRegisteredAsFourthFails) {
  Case wrong = named("elastica/mattiasson-1/polygon");
  wrong.gates = {order_gate("tip_w", 4.0, "wrong claim")};
  EXPECT_FALSE(run_default(wrong).passed());
}

}  // namespace
