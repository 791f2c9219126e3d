// The elastica cases pass at their default levels, and their gates turn red on deliberately wrong
// solvers: the polygon run under the arcs' exactness gates, and a drifting H under a conservation
// gate.
#include <gtest/gtest.h>

#include <string>

#include "case_test_support.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::run_at_default_levels;

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }
SweepResult run_default(const Case& c) { return run_at_default_levels(c); }

class ElasticaCase : public ::testing::TestWithParam<std::string> {};

TEST_P(ElasticaCase, PassesAtDefaultLevels) {
  const auto result = run_default(named(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

INSTANTIATE_TEST_SUITE_P(AllElasticaCases, ElasticaCase, ::testing::ValuesIn(rodvv::testing::case_names_of_family("elastica")),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           return rodvv::testing::test_name_of_case(param_info.param);
                         });

TEST(ElasticaCatalogue, HasBothSchemesForEveryProblem) {
  // 4 columns + displacement control + 4 cantilevers + roll-up + tapered + curved, x 2 schemes.
  EXPECT_EQ(rodvv::testing::case_names_of_family("elastica").size(), 24u);
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
