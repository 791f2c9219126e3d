// The Euler critical-load cases (harness/src/cases/buckling_cases.cpp): all eight pass at their
// default levels with loads of observed order ~2, their references are Euler's loads for any L and
// EI, and their gates turn red on a perturbed reference, a wrong order claim and a round-off claim
// for a shape that only converges as h^2.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case_test_support.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/references/elastica.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
using rodvv::testing::run_at_default_levels;

const std::string kEulerCases[] = {
    "elastica/euler-pinned-pinned/polygon",   "elastica/euler-clamped-free/polygon",
    "elastica/euler-clamped-clamped/polygon", "elastica/euler-clamped-pinned/polygon",
    "elastica/euler-pinned-pinned/arcs",      "elastica/euler-clamped-free/arcs",
    "elastica/euler-clamped-clamped/arcs",    "elastica/euler-clamped-pinned/arcs",
};

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }

const MetricAnalysis& analysis_of(const SweepResult& result, const std::string& metric) {
  for (const auto& a : result.analyses)
    if (a.metric == metric) return a;
  throw std::logic_error("no analysis of " + metric);
}

class EulerCase : public ::testing::TestWithParam<std::string> {};

TEST_P(EulerCase, PassesWithSecondOrderLoads) {
  const auto result = run_at_default_levels(named(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  // Both loads: least-squares order over N = 16 .. 64 within 0.05 of 2 (measured 1.99 .. 2.04).
  for (const char* metric : {"P1", "P2"}) {
    const auto& order = analysis_of(result, metric).order;
    ASSERT_TRUE(order.least_squares.has_value()) << metric;
    EXPECT_NEAR(*order.least_squares, 2.0, 0.05) << metric;
  }
  // A computed mode-shape plot next to the exact one, for both modes.
  std::size_t series = 0;
  for (const auto& s : result.levels.back().series)
    series += s.name.starts_with("mode 1|") || s.name.starts_with("mode 2|");
  EXPECT_EQ(series, 4u);
}

INSTANTIATE_TEST_SUITE_P(AllEulerCases, EulerCase, ::testing::ValuesIn(kEulerCases),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           return rodvv::testing::test_name_of_case(param_info.param);
                         });

// The reference of P1 is references::euler_critical_load at the case's parameters (here L = 2,
// EI = 3): the same double up to the c EI / L^2 product (2 eps).
TEST(EulerCases, ReferenceIsEulersLoadForAnyLengthAndStiffness) {
  const Case& c = named("elastica/euler-clamped-pinned/arcs");
  Parameters parameters = c.info.parameters;
  set_parameter(parameters, "L", 2.0);
  set_parameter(parameters, "EI", 3.0);
  const auto result = run_sweep(c, parameters, c.info.resolution.default_levels);
  const double expected = rodvv::references::euler_critical_load(
      rodvv::references::EndConditions::ClampedPinned, 2.0, 3.0);
  EXPECT_TRUE(is_close(*result.levels.back().metrics.at("P1").reference, expected, 2 * kEpsilon, 0.0));
  EXPECT_FALSE(result.skipped_gates.empty());  // measured bounds do not apply at other parameters
  EXPECT_TRUE(result.passed()) << failing_gates(result);
}

TEST(EulerCases, BadParameterNamesIt) {
  Parameters parameters = named("elastica/euler-pinned-pinned/polygon").info.parameters;
  try {
    set_parameter(parameters, "EI", 0.0);
    ADD_FAILURE() << "EI = 0 accepted";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "EI");
  }
}

// A reference off by 0.1 % leaves an error that does not converge: the order gates fail.
TEST(EulerCasesHaveTeeth, PerturbedReferenceFails) {
  Case wrong = named("elastica/euler-clamped-clamped/polygon");
  const LevelRunner original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    LevelOutput output = original(p, level);
    MetricSample& load = output.metrics.at("P1");
    load.reference = *load.reference * (1.0 + 1e-3);
    load.error = std::abs(load.computed - *load.reference) / *load.reference;
    return output;
  };
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

// Claiming fourth order for the second-order loads fails the two-sided window.
TEST(EulerCasesHaveTeeth, SecondOrderLoadsRegisteredAsFourthFail) {
  Case wrong = named("elastica/euler-clamped-free/arcs");
  wrong.gates = {order_gate("P1", 4.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

// The clamped-pinned mode is not trigonometric: its shape error is O(h^2), far above the round-off
// gate that the pinned-pinned shapes pass.
TEST(EulerCasesHaveTeeth, ConvergingShapeUnderRoundOffGateFails) {
  Case wrong = named("elastica/euler-clamped-pinned/polygon");
  wrong.gates = {upper_bound_gate("mode1_shape", 1e-8, GateScope::AllLevels, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
  Case right = named("elastica/euler-pinned-pinned/polygon");
  right.gates = {upper_bound_gate("mode1_shape", 1e-8, GateScope::AllLevels, "round-off")};
  EXPECT_TRUE(run_at_default_levels(right).passed());
}

}  // namespace
