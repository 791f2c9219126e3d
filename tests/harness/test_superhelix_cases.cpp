// The Super-Helix cases pass at their default levels, and their gates turn red on deliberately wrong
// claims: a second-order case claimed at order 4, a first-order energy loss claimed at order 2, an
// exact case under a perturbed solver, and a conservation gate on a rod whose H is not constant.
#include <gtest/gtest.h>

#include <string>

#include "case_test_support.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::run_at_default_levels;

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }

class SuperHelixCase : public ::testing::TestWithParam<std::string> {};

TEST_P(SuperHelixCase, PassesAtDefaultLevels) {
  const auto result = run_at_default_levels(named(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

INSTANTIATE_TEST_SUITE_P(AllSuperHelixCases, SuperHelixCase,
                         ::testing::ValuesIn(rodvv::testing::case_names_of_family("superhelix")),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           return rodvv::testing::test_name_of_case(param_info.param);
                         });

TEST(SuperHelixCatalogue, HasEveryCase) {
  EXPECT_EQ(rodvv::testing::case_names_of_family("superhelix").size(), 8u);
}

TEST(SuperHelixGatesHaveTeeth, SecondOrderClaimedAsFourthFails) {
  Case wrong = named("superhelix/mattiasson-2");
  wrong.gates = {order_gate("tip_w", 4.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
  Case modes = named("superhelix/modes");
  modes.gates = {order_gate("omega1", 4.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(modes).passed());
}

TEST(SuperHelixGatesHaveTeeth, ClothoidFourthOrderClaimedAsSecondOrSixthFails) {
  // The two-sided order window [p - 0.1, p + 0.5] rejects both the Super-Helix's 2 and 6.
  for (double claimed : {2.0, 6.0}) {
    Case wrong = named("superhelix/clothoid-mattiasson-2");
    wrong.gates = {order_gate("tip_w", claimed, "wrong claim")};
    EXPECT_FALSE(run_at_default_levels(wrong).passed()) << claimed;
  }
  // A 1e-4 relative change of the load seen by the solver (not by the reference) moves the tip by
  // ~1e-5 >> the C h^4 bound 3.2e-7 at N = 8.
  Case perturbed = named("superhelix/clothoid-mattiasson-2");
  const auto runner = perturbed.run_level;
  perturbed.run_level = [runner](const Parameters& p, double level) {
    Parameters shifted = p;
    set_parameter(shifted, "alpha", parameter_value(p, "alpha") * (1.0 + 1e-4));
    LevelOutput solved = runner(shifted, level);
    const LevelOutput exact = runner(p, level);
    auto& w = solved.metrics["tip_w"];
    w.reference = exact.metrics.at("tip_w").reference;
    w.error = std::abs(w.computed - *w.reference);
    return solved;
  };
  EXPECT_FALSE(run_at_default_levels(perturbed).passed());
}

TEST(SuperHelixGatesHaveTeeth, FirstOrderEnergyLossClaimedAsSecondFails) {
  Case wrong = named("superhelix/energy-decay");
  wrong.gates = {order_gate("energy_loss", 2.0, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

TEST(SuperHelixGatesHaveTeeth, PerturbedHelixFailsExactnessGates) {
  // A 1e-9 change of the twisting moment seen by the solver (not by the reference) moves the
  // equilibrium by ~1e-9: far above the round-off gates.
  Case wrong = named("superhelix/helix-axial-wrench");
  const auto runner = wrong.run_level;
  wrong.run_level = [runner](const Parameters& p, double level) {
    Parameters shifted = p;
    set_parameter(shifted, "twisting_moment", parameter_value(p, "twisting_moment") * (1.0 + 1e-9));
    LevelOutput solved = runner(shifted, level);
    LevelOutput exact = runner(p, level);
    // keep the perturbed H but compare it with the unperturbed closed form
    solved.metrics["H_mean"].reference = exact.metrics["H_mean"].reference;
    solved.metrics["H_mean"].error = std::abs(solved.metrics["H_mean"].computed - *exact.metrics["H_mean"].reference);
    return solved;
  };
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

TEST(SuperHelixGatesHaveTeeth, HeavyCantileverHIsNotConstantAtRoundOff) {
  // H is conserved only to the scheme's order: a round-off gate on its spread must fail.
  Case wrong = named("superhelix/heavy-cantilever");
  wrong.gates = {upper_bound_gate("H_spread", 1e-12, GateScope::AllLevels, "wrong claim")};
  EXPECT_FALSE(run_at_default_levels(wrong).passed());
}

TEST(SuperHelixGatesHaveTeeth, GravityPotentialMustEnterH) {
  // Under gravity H = n.v + m.u - W - V is constant only with V = -rho S g . r: dropping V leaves an
  // O(1) variation along the rod instead of the O(h^2) spread.
  namespace sh = rodvv::solvers::superhelix;
  sh::RodModel model;
  model.elements = 16;
  model.natural_strain = rodvv::Vec3(0.8, 1.2, -0.5);
  model.gravity = rodvv::Vec3(0.0, 0.0, -3.0);
  sh::StaticOptions options;
  options.load_steps = 2;
  rodvv::SpatialRodSolution solution = sh::make_solution(model, sh::solve_static(model, options).q);
  const double with_v = rodvv::invariants::noether3d_summary(solution).spread;
  for (double& v : solution.potential) v = 0.0;
  const double without_v = rodvv::invariants::noether3d_summary(solution).spread;
  EXPECT_LT(with_v, 1e-2);
  EXPECT_GT(without_v, 100.0 * with_v);
}

}  // namespace
