// The Reissner (extensible, shearable) cases pass at their default levels; their reference
// constants are the table's values; their gates turn red on a wrong model (the inextensible solver
// under the Reissner references) and on a wrong order claim.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "case_test_support.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/testing/reference_table.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::named_case;
using rodvv::testing::run_at_default_levels;

const std::vector<std::string> kCases{"elastica/reissner-tension/polygon", "elastica/reissner-tension/arcs",
                              "elastica/reissner-cantilever/polygon", "elastica/reissner-cantilever/arcs",
                              "elastica/reissner-critical-load/polygon", "elastica/reissner-critical-load/arcs"};

class ReissnerCase : public ::testing::TestWithParam<std::string> {};

TEST_P(ReissnerCase, PassesAtDefaultLevels) {
  const auto result = run_at_default_levels(named_case(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

INSTANTIATE_TEST_SUITE_P(AllReissnerCases, ReissnerCase, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           return rodvv::testing::test_name_of_case(param_info.param);
                         });

// The constants in reissner_cases.cpp are the CSV values rounded to double (strtod of the same
// decimal string on both sides: bit-equal).
TEST(ReissnerCaseReferences, CantileverConstantsAreTheTableValues) {
  for (double ga : {40.0, 100.0}) {
    const Case& c = named_case("elastica/reissner-cantilever/arcs");
    Parameters p = c.info.parameters;
    set_parameter(p, "GA", ga);
    const LevelOutput out = c.run_level(p, 8.0);
    int matched = 0;
    for (const auto& f : rodvv::testing::read_reference_table("reissner_reference.csv",
                                                              "case,P,EA,GA,L,EI,s,quantity,value")) {
      if (rodvv::testing::parse_table_number(f[3]) != ga) continue;
      const double value = rodvv::testing::parse_table_number(f[8]);
      const std::string q = f[7];
      if (f[6] == "1.0" && (q == "x" || q == "y" || q == "theta")) {
        const std::string metric = q == "theta" ? "tip_theta" : "tip_" + q;
        EXPECT_EQ(*out.metrics.at(metric).reference, value) << metric << " GA " << ga;
        ++matched;
      }
      if (q == "H") {
        EXPECT_EQ(*out.metrics.at("H_mean").reference, value);
        ++matched;
      }
    }
    EXPECT_EQ(matched, 4);
  }
}

// Off the table the reference is the shooting solver: at the table's own parameters it reproduces
// the table values (so the two references agree where both exist), and a user's problem at other
// scales - PyElastica's Timoshenko beam (L = 3, E = 1e6, r = 0.25, G = 1e4, shear factor 27/28, tip
// load 15) - converges at order 2 with an uncertainty far below the errors.
TEST(ReissnerCaseReferences, OffTheTableTheShootingSolverIsTheReference) {
  const Case& c = named_case("elastica/reissner-cantilever/arcs");
  Parameters near = c.info.parameters;
  set_parameter(near, "P", 5.0 * (1.0 + 1e-15));  // not the table row: the shooting reference
  const LevelOutput shooting = c.run_level(near, 8.0), table = c.run_level(c.info.parameters, 8.0);
  EXPECT_EQ(table.metrics.at("reference_uncertainty").computed, 0.0);
  EXPECT_LT(shooting.metrics.at("reference_uncertainty").computed, 1e-11);
  for (const char* metric : {"tip_x", "tip_y", "tip_theta", "H_mean"})
    EXPECT_NEAR(*shooting.metrics.at(metric).reference, *table.metrics.at(metric).reference, 1e-11) << metric;

  Parameters timoshenko = c.info.parameters;
  const double pi = std::numbers::pi, r = 0.25, E = 1e6, G = 1e4;
  for (const auto& [name, value] : {std::pair{"L", 3.0}, {"EI", E * pi * std::pow(r, 4) / 4}, {"EA", E * pi * r * r},
                                    {"GA", 27.0 / 28.0 * G * pi * r * r}, {"P", 15.0}})
    set_parameter(timoshenko, name, value);
  const auto result = run_sweep(c, timoshenko, c.info.resolution.default_levels);
  EXPECT_TRUE(result.passed()) << failing_gates(result);
  EXPECT_FALSE(result.skipped_gates.empty());  // the measured bounds hold at the defaults only
  const auto& finest = result.levels.back().metrics;
  EXPECT_LT(finest.at("reference_uncertainty").computed, 1e-3 * *finest.at("tip_y").error);
}

// The inextensible elastica run under the Reissner cantilever's gates fails (the tip differs by
// O(P/EA) = 1e-2 >> the C h^2 bounds).
TEST(ReissnerGatesHaveTeeth, InextensibleSolverFailsTheReissnerCantilever) {
  Case wrong = named_case("elastica/reissner-cantilever/arcs");
  const auto original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    Parameters q = p;
    LevelOutput out = original(q, level);
    // Replace the computed tip by the inextensible elastica's (same load, EA = GA = inf) through the
    // Mattiasson case at alpha = 5: its tip_w / tip_u computed values.
    const Case& elastica = named_case("elastica/mattiasson-5/arcs");
    const LevelOutput e = elastica.run_level(elastica.info.parameters, level);
    const double x = 1.0 - e.metrics.at("tip_u").computed, y = -e.metrics.at("tip_w").computed;
    auto& tx = out.metrics["tip_x"];
    tx = {x, tx.reference, std::abs(x - *tx.reference)};
    auto& ty = out.metrics["tip_y"];
    ty = {y, ty.reference, std::abs(y - *ty.reference)};
    return out;
  };
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

// A wrong closed form (Engesser instead of the model's Haringx-type load) fails the critical-load
// gates; so does a fourth-order claim.
TEST(ReissnerGatesHaveTeeth, WrongCriticalLoadOrOrderClaimFails) {
  Case wrong = named_case("elastica/reissner-critical-load/polygon");
  const auto original = wrong.run_level;
  wrong.run_level = [original](const Parameters& p, double level) {
    LevelOutput out = original(p, level);
    // In the metric's unit EI/L^2: Engesser's P L^2/EI = pi^2 / (1 + pi^2 EI / (GA L^2)).
    const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI");
    const double euler = std::numbers::pi * std::numbers::pi,
                 engesser = euler / (1 + euler * EI / (parameter_value(p, "GA") * L * L));
    auto& s = out.metrics["P_cr"];
    s = {s.computed, engesser, std::abs(s.computed - engesser)};
    return out;
  };
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
  Case claim = named_case("elastica/reissner-cantilever/polygon");
  claim.gates = {order_gate("tip_x", 4.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(claim).passed());
}

}  // namespace
