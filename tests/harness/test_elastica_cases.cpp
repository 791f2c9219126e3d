// The elastica cases pass at their default levels, and their gates turn red on deliberately wrong
// solvers: the polygon run under the arcs' exactness gates, and a drifting H under a conservation
// gate.
#include <gtest/gtest.h>

#include <string>
#include <vector>

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
  // 4 columns + displacement control + 4 cantilevers + roll-up + tapered + curved, x 2 schemes;
  // + 4 Euler critical-load cases (buckling_cases.cpp) x 2 schemes; + heavy cantilever x 2 schemes;
  // + 3 Reissner cases (reissner_cases.cpp) x 2 schemes; + the manufactured equilibrium x 2 schemes.
  EXPECT_EQ(rodvv::testing::case_names_of_family("elastica").size(), 42u);
}

// elastica/manufactured's teeth: measured against the fields of EI 0.1 % off (kappa_hat, and so the shape, do
// not depend on EI; n and m scale with it), the force and moment bounds fail and the shape's pass.
TEST(ElasticaGatesHaveTeeth, ManufacturedCaseSeesAStiffnessDefect) {
  for (const char* scheme : {"polygon", "arcs"}) {
    Case wrong = named(std::string("elastica/manufactured/") + scheme);
    const SolveLevel solve = wrong.solve;
    const MeasureSolution measure = wrong.measure;
    wrong.run_level = [solve, measure](const Parameters& p, double level) {
      Parameters measured_at = p;
      set_parameter(measured_at, "EI", 1.001 * parameter_value(p, "EI"));
      return measure(measured_at, level, solve(p, level));
    };
    const auto result = run_default(wrong);
    bool force_failed = false, shape_failed = false;
    for (const auto& gate : result.gates) {
      if ((gate.metric == "force" || gate.metric == "moment") && !gate.passed) force_failed = true;
      if ((gate.metric == "theta" || gate.metric == "position") && !gate.passed) shape_failed = true;
    }
    EXPECT_TRUE(force_failed) << scheme;
    EXPECT_FALSE(shape_failed) << scheme;
  }
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

// The cases without a closed form are gated against the shooting solution: the arcs' bounds
// (measured x 2) reject the polygon, whose shape error is 4.4x (heavy cantilever) to 2.2x
// (tapered) larger, and a fourth-order claim fails the order window.
TEST(ElasticaShootingReference, PolygonUnderArcsBoundsFails) {
  for (const std::string motion : {"heavy-cantilever", "tapered"}) {
    Case wrong = named("elastica/" + motion + "/arcs");
    wrong.run_level = named("elastica/" + motion + "/polygon").run_level;
    EXPECT_FALSE(run_default(wrong).passed()) << motion;
  }
  Case fourth = named("elastica/heavy-cantilever/arcs");
  fourth.gates = {order_gate("shape_max_error", 4.0, "wrong claim")};
  EXPECT_FALSE(run_default(fourth).passed());
}

// The shooting reference is a solution of the continuous problem: the discrete shape converges to
// it at order 2 with no floor, down to 1.5e-7 at N = 1024 (measured), i.e. the reference error
// (~1e-12) is invisible; and the heavy cantilever's H, potential included, converges at order 2.
TEST(ElasticaShootingReference, ErrorFallsAsHSquaredToFineLevels) {
  const std::vector<double> levels{64, 256, 1024};
  const auto result = run_sweep(named("elastica/heavy-cantilever/arcs"),
                                named("elastica/heavy-cantilever/arcs").info.parameters, levels);
  ASSERT_EQ(result.levels.size(), 3u);
  const auto error_at = [&](std::size_t i, const std::string& metric) {
    return *result.levels[i].metrics.at(metric).error;
  };
  for (const std::string metric : {"shape_max_error", "H_spread"}) {
    // Two factors of 4 in h: 16^2 = 256 in error; order within [1.9, 2.1] -> ratio in [194, 337].
    const double ratio = error_at(0, metric) / error_at(2, metric);
    EXPECT_GT(ratio, 194.0) << metric;
    EXPECT_LT(ratio, 337.0) << metric;
  }
}

// Claiming fourth order for a second-order discretisation fails the order window.
TEST(ElasticaGatesHaveTeeth, SecondOrderSchemeRegisteredAsFourthFails) {
  Case wrong = named("elastica/mattiasson-1/polygon");
  wrong.gates = {order_gate("tip_w", 4.0, "wrong claim")};
  EXPECT_FALSE(run_default(wrong).passed());
}

}  // namespace

namespace {

// The closed-form cases report in the problem's units (elastica_cases.cpp, Units): their metrics do
// not depend on L and EI beyond the solvers' and references' tolerances, and their measured bounds
// are evaluated, not skipped, at other L and EI.
TEST(ElasticaUnits, ResultsDoNotDependOnLengthAndStiffness) {
  // Measured: at most 1e-3 relative on errors of 1e-7 (the Newton and reference tolerances, ~1e-10
  // absolute); 1e-9 absolute covers round-off-level errors.
  for (const char* name : {"elastica/mattiasson-5/polygon", "elastica/pinned-pinned-120/arcs", "elastica/roll-up/polygon"})
    rodvv::testing::expect_results_free_of_units(named(name), {{"L", 0.31}, {"EI", 47.0}}, 1e-2, 1e-9);
}

}  // namespace
