// The elastica-contact cases pass at their default levels, and their gates turn red on a wrong
// model: the cavity run against a wall 1% further out, a soft wall reported as the hard one, a
// contact force that is off by the (point-contact) discretisation error x 4.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "case_test_support.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/harness/sweep.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::named_case;
using rodvv::testing::run_at_default_levels;

class ContactCase : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactCase, PassesAtDefaultLevels) {
  const auto result = run_at_default_levels(named_case(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

INSTANTIATE_TEST_SUITE_P(AllContactCases, ContactCase,
                         ::testing::ValuesIn(rodvv::testing::case_names_of_family("elastica-contact")),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           return rodvv::testing::test_name_of_case(param_info.param);
                         });

TEST(ContactCases, AllTenAreRegistered) {
  EXPECT_EQ(rodvv::testing::case_names_of_family("elastica-contact").size(), 15u);
}

// The solver runs with the wall 1 % further out while the reference keeps it: P moves by ~0.3 EI / L^2, far
// above the C h^2 bounds.
TEST(ContactGatesHaveTeeth, WrongWallGapFailsThePointContactCase) {
  Case wrong = named_case("elastica-contact/cavity-point/arcs");
  const auto original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    Parameters moved = p;
    set_parameter(moved, "wall_gap", 1.01 * parameter_value(p, "wall_gap"));
    LevelOutput solver = original(moved, level);
    const LevelOutput truth = original(p, level);
    for (auto& [name, sample] : solver.metrics)
      if (truth.metrics.at(name).reference && sample.reference) {
        sample.reference = truth.metrics.at(name).reference;
        sample.error = std::abs(sample.computed - *sample.reference);
      }
    return solver;
  };
  const auto result = run_sweep(wrong, wrong.info.parameters, wrong.info.resolution.default_levels);
  EXPECT_FALSE(result.passed());
}

// A constant relative bias of 1e-4 in P (smaller than the coarse-level error) flattens the observed
// order at the fine levels: the order gate catches it.
TEST(ContactGatesHaveTeeth, BiasedLoadFailsTheOrderGate) {
  Case wrong = named_case("elastica-contact/cavity-free/polygon");
  const auto original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    LevelOutput out = original(p, level);
    auto& P = out.metrics.at("P");
    P.computed *= 1.0 + 1e-4;
    P.error = std::abs(P.computed - *P.reference);
    return out;
  };
  const auto result = run_sweep(wrong, wrong.info.parameters, wrong.info.resolution.default_levels);
  EXPECT_FALSE(result.passed());
}

// Soft wall at b reported against the hard wall's constant in place of the §4.2 table: the
// P_vs_table bound fails.
TEST(ContactGatesHaveTeeth, SoftWallAgainstTheHardWallValueFails) {
  Case wrong = named_case("elastica-contact/soft-wall");
  const auto original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    LevelOutput out = original(p, level);
    auto& P = out.metrics.at("P_vs_table");
    P.reference = out.metrics.at("P_vs_hard").reference;
    P.error = std::abs(P.computed - *P.reference);
    return out;
  };
  const auto result = run_sweep(wrong, wrong.info.parameters, wrong.info.resolution.default_levels);
  EXPECT_FALSE(result.passed());
}

// The NewtonLcp variant with its wall 1e-6 L further out (its references follow the wall, so only
// the agreement gate can see it): P moves by ~3e-4 EI / L^2 against the active-set P at wall_gap = 0.1 L,
// far above the 7e-7 agreement bound.
TEST(ContactGatesHaveTeeth, AMicronWallShiftFailsTheLcpAgreementGate) {
  Case wrong = named_case("elastica-contact/cavity-point/polygon-lcp");
  const auto lcp = wrong.run_level;
  const auto active = named_case("elastica-contact/cavity-point/polygon").run_level;
  wrong.run_level = [lcp, active](const Parameters& p, double level) {
    Parameters moved = p;
    set_parameter(moved, "wall_gap", parameter_value(p, "wall_gap") + 1e-6 * parameter_value(p, "L"));
    LevelOutput out = lcp(moved, level);
    const double d = std::abs(out.metrics.at("P").computed - active(p, level).metrics.at("P").computed);
    out.metrics["P_vs_active_set"] = {d, 0.0, d};
    return out;
  };
  const auto result = run_sweep(wrong, wrong.info.parameters, wrong.info.resolution.default_levels);
  EXPECT_FALSE(result.passed());
}

// The line contact's flat, read as a vertex's offset from its neighbours' chord: a polygon whose flat has one
// vertex 1e-12 off (five times the round-off bound, a thousand times the largest measured) fails it; an H
// drift that shrinks like h instead of h^2 (the spread times N / 32, equal at the coarsest level) fails the
// order band measured over the window.
TEST(ContactGatesHaveTeeth, AFlatOffItsWallAndAFirstOrderHDriftFailTheLineGates) {
  for (const std::string metric : {"flat_offset", "H_spread"}) {
    Case wrong = named_case("elastica-contact/cavity-line/polygon");
    const auto right = wrong.run_level;
    wrong.run_level = [right, metric](const Parameters& p, double level) {
      LevelOutput out = right(p, level);
      MetricSample& sample = out.metrics.at(metric);
      sample.computed = metric == "flat_offset" ? sample.computed + 1e-12 : sample.computed * level / 32.0;
      sample.error = sample.computed;
      return out;
    };
    const auto result = run_sweep(wrong, wrong.info.parameters, wrong.info.resolution.default_levels);
    EXPECT_FALSE(result.passed()) << metric;
    bool gate_of_metric_failed = false;
    for (const auto& gate : result.gates)
      if (!gate.passed && gate.metric == metric) gate_of_metric_failed = true;
    EXPECT_TRUE(gate_of_metric_failed) << metric << failing_gates(result);
  }
}

TEST(ContactCases, ShorteningBeyondTheTabulatedBranchIsRejected) {
  const Case& c = named_case("elastica-contact/cavity-line/polygon");
  Parameters p = c.info.parameters;
  set_parameter(p, "shortening", 0.095 * parameter_value(p, "L"));
  try {
    c.check_parameters(p);
    ADD_FAILURE() << "no InputError";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "shortening");
  }
}

}  // namespace
