// The pendulum cases pass at their default levels, and their gates turn red on deliberately wrong
// solvers (a solver run under another method's gates).
#include <gtest/gtest.h>

#include <string>

#include <cmath>
#include <limits>

#include <Eigen/LU>  // determinant

#include "case_test_support.hpp"
#include "pendulum/one_step_map.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/testing/input_error.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::failing_gates;
using rodvv::testing::run_at_default_levels;

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }
SweepResult run_default(const Case& c) { return run_at_default_levels(c); }

class PendulumCase : public ::testing::TestWithParam<std::string> {};

TEST_P(PendulumCase, PassesAtDefaultLevels) {
  const auto result = run_default(named(GetParam()));
  EXPECT_TRUE(result.passed()) << GetParam() << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  return rodvv::testing::test_name_of_case(info.param);
}

INSTANTIATE_TEST_SUITE_P(AllPendulumCases, PendulumCase, ::testing::ValuesIn(rodvv::testing::case_names_of_family("pendulum")),
                         test_name);

TEST(PendulumCatalogue, HasEveryMotionAndMethod) {
  const auto names = rodvv::testing::case_names_of_family("pendulum");
  // 5 motions x 6 methods + 5 fixed-step methods in the long-time energy group and in the one-step maps.
  EXPECT_EQ(names.size(), 40u);
  for (const auto& c : default_registry().cases()) {
    EXPECT_GE(c.info.resolution.default_levels.size(), c.fit_levels) << c.info.name;
    EXPECT_FALSE(c.info.citation.empty()) << c.info.name;
  }
}

// A first-order method under a second-order method's gates: the order gate must fail.
TEST(PendulumGatesHaveTeeth, ExplicitEulerUnderVerletGatesFails) {
  Case wrong = named("pendulum/libration-90/stormer-verlet");
  wrong.run_level = named("pendulum/libration-90/explicit-euler").run_level;
  const auto result = run_default(wrong);
  EXPECT_FALSE(result.passed());
  EXPECT_FALSE(result.gates.front().passed) << result.gates.front().reason;
}

// A fourth-order method under a second-order method's gates: the order is far above the window.
TEST(PendulumGatesHaveTeeth, Rk4UnderVerletGatesFailsFromAbove) {
  Case wrong = named("pendulum/libration-90/stormer-verlet");
  wrong.run_level = named("pendulum/libration-90/rk4").run_level;
  const auto result = run_default(wrong);
  ASSERT_TRUE(result.gates.front().measured.has_value());
  EXPECT_GT(*result.gates.front().measured, 2.5);
  EXPECT_FALSE(result.passed());
}

// RK4 drifts: under the symplectic bounded-energy gates it must fail, and Verlet under RK4's
// "must drift" gate must fail too: the contrast gates both ways.
TEST(PendulumGatesHaveTeeth, EnergyContrastSeparatesSymplecticFromNot) {
  Case drifting = named("pendulum/long-time-energy/stormer-verlet");
  drifting.run_level = named("pendulum/long-time-energy/rk4").run_level;
  EXPECT_FALSE(run_default(drifting).passed());

  Case bounded = named("pendulum/long-time-energy/rk4");
  bounded.run_level = named("pendulum/long-time-energy/stormer-verlet").run_level;
  EXPECT_FALSE(run_default(bounded).passed());
}

TEST(PendulumCases, RejectInvalidParameters) {
  const Case& rotation = named("pendulum/rotation/rk4");
  Parameters parameters = rotation.info.parameters;
  EXPECT_THROW(apply_assignment(parameters, "g=-1"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(parameters, "length=0"), rodvv::InputError);
  // v0 below 2 omega is a libration, not a rotation: the window on v0 / omega refuses it, naming v0.
  apply_assignment(parameters, "v0=4.05");  // 1.5 omega
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([&] { rotation.check_parameters(parameters); }), "v0");
  Parameters separatrix = named("pendulum/separatrix/rk4").info.parameters;
  apply_assignment(separatrix, "t_end=3.4");  // omega t_end = 9.2 > 6
  EXPECT_EQ(rodvv::testing::input_error_parameter_of([&] { named("pendulum/separatrix/rk4").check_parameters(separatrix); }),
            "t_end");
  Parameters libration = named("pendulum/libration-90/rk4").info.parameters;
  EXPECT_THROW(apply_assignment(libration, "theta0_deg=180"), rodvv::InputError);
  EXPECT_THROW(apply_assignment(libration, "periods=0"), rodvv::InputError);
}

}  // namespace

namespace {

// The cases state everything in the time unit 1/omega, omega = sqrt(g/l) (pendulum_cases.cpp, Units): a
// libration's results do not depend on g or l beyond round-off, and its measured bounds are evaluated, not
// skipped, at another g and l. A solver that used omega where it needs omega^2 would be right at omega = 1
// only; at the default omega = 2.7 its error would be O(1).
TEST(PendulumUnits, LibrationResultsDoNotDependOnGOrL) {
  // Round-off of ~1e3 steps relative to errors >= 1e-7: 1e-6 relative is a wide margin.
  rodvv::testing::expect_results_free_of_units(named("pendulum/libration-90/stormer-verlet"), {{"g", 0.37}}, 1e-6,
                                               0.0);
  rodvv::testing::expect_results_free_of_units(named("pendulum/libration-90/stormer-verlet"),
                                               {{"g", 41.0}, {"length", 0.02}}, 1e-6, 0.0);
}

// The rotation's start rate v0 is physical: at another g it is another v0 / omega, another problem, so its
// measured bounds are skipped there. dopri5's tolerance mixes theta and theta' (rad/time): g and l are not
// unit scales there either.
TEST(PendulumUnits, PhysicalRatesAndTheAdaptiveToleranceAreNotUnitFree) {
  for (const char* name : {"pendulum/libration-90/dopri5", "pendulum/rotation/rk4"}) {
    const Case& c = named(name);
    Parameters other = c.info.parameters;
    set_parameter(other, "g", 9.0);
    const auto result = run_sweep(c, other, c.info.resolution.default_levels);
    EXPECT_FALSE(result.skipped_gates.empty()) << name;
  }
}

}  // namespace

namespace {

using rodvv::harness::pendulum_cases::documented_map;
using rodvv::harness::pendulum_cases::kAllStepMaps;
using rodvv::harness::pendulum_cases::measured_step_map;
using rodvv::harness::pendulum_cases::step_map;
using rodvv::harness::pendulum_cases::step_map_name;
using rodvv::harness::pendulum_cases::StepMap;
namespace pend = rodvv::solvers::pendulum;
constexpr double kEps = std::numeric_limits<double>::epsilon();

double distance(const Eigen::Matrix2d& a, const Eigen::Matrix2d& b) { return (a - b).cwiseAbs().maxCoeff(); }

int global_order(StepMap map) {
  switch (map) {
    case StepMap::ExplicitEuler:
    case StepMap::SymplecticEulerKickDrift:
    case StepMap::SymplecticEulerDriftKick: return 1;
    case StepMap::VerletKickDriftKick:
    case StepMap::VerletDriftKickDrift: return 2;
    case StepMap::RungeKutta4:
    case StepMap::McLachlanSb3a: return 4;
    case StepMap::ExactFlow: break;
  }
  return 0;
}

// The oracle checked on its own, against the exact flow: each map errs by O(x^(p+1)) per step, with p
// its method's order (a typo in a coefficient, e.g. McLachlan's, drops the order).
TEST(OneStepMapOracle, EveryMapHasItsMethodsLocalOrder) {
  for (StepMap map : kAllStepMaps) {
    if (map == StepMap::ExactFlow) continue;
    const double x = 0.05;
    const double coarse = distance(step_map(map, x), step_map(StepMap::ExactFlow, x));
    const double fine = distance(step_map(map, x / 2), step_map(StepMap::ExactFlow, x / 2));
    EXPECT_NEAR(std::log2(coarse / fine), global_order(map) + 1, 0.05) << step_map_name(map);
  }
}

// Symplectic maps of a linear Hamiltonian flow are area-preserving (det M = 1, HLW 2006 §VI.2); explicit
// Euler and RK4 are not (det = 1 + x^2 and 1 - x^6/72 + x^8/576).
TEST(OneStepMapOracle, SymplecticMapsPreserveArea) {
  const double x = 0.3;
  for (StepMap map : {StepMap::SymplecticEulerKickDrift, StepMap::SymplecticEulerDriftKick,
                      StepMap::VerletKickDriftKick, StepMap::VerletDriftKickDrift, StepMap::McLachlanSb3a,
                      StepMap::ExactFlow})
    EXPECT_NEAR(step_map(map, x).determinant(), 1.0, 8 * kEps) << step_map_name(map);
  EXPECT_NEAR(step_map(StepMap::ExplicitEuler, x).determinant(), 1.0 + x * x, 8 * kEps);
  EXPECT_NEAR(step_map(StepMap::RungeKutta4, x).determinant(), 1.0 - std::pow(x, 6) / 72 + std::pow(x, 8) / 576,
              8 * kEps);
}

// Two methods of the same order are told apart: at the finest default level x = 0.05 every pair of the
// oracle's maps is more than 1e4 times the case's 32-eps gate apart.
TEST(OneStepMapOracle, MapsAreDistinctFarAboveTheGate) {
  for (StepMap a : kAllStepMaps)
    for (StepMap b : kAllStepMaps)
      if (a != b) {
        EXPECT_GT(distance(step_map(a, 0.05), step_map(b, 0.05)) / kEps, 32e4)
            << step_map_name(a) << " vs " << step_map_name(b);
      }
}

// The production integrators are the variants their documentation names, and not the other variant of
// the same order: the kick-drift symplectic Euler is 1e10 times the gate from the drift-kick one.
TEST(OneStepMap, ProductionMethodsAreTheirDocumentedVariants) {
  const double omega = 2.7, x = 0.1;
  const auto error = [&](pend::Method method, StepMap map) {
    return distance(measured_step_map(method, omega, x / omega), step_map(map, x)) / kEps;
  };
  EXPECT_LE(error(pend::Method::SymplecticEuler, StepMap::SymplecticEulerKickDrift), 32.0);
  EXPECT_GT(error(pend::Method::SymplecticEuler, StepMap::SymplecticEulerDriftKick), 1e11);
  EXPECT_LE(error(pend::Method::StormerVerlet, StepMap::VerletKickDriftKick), 32.0);
  EXPECT_GT(error(pend::Method::StormerVerlet, StepMap::VerletDriftKickDrift), 1e10);
  EXPECT_GT(error(pend::Method::McLachlanRkn4, StepMap::RungeKutta4), 1e6);
}

TEST(OneStepMap, AdaptiveMethodHasNoOneStepMap) {
  try {
    (void)documented_map(pend::Method::DormandPrince5);
    FAIL() << "dopri5 has no fixed one-step map";
  } catch (const rodvv::InputError& error) {
    EXPECT_EQ(error.parameter(), "method");
  }
}

}  // namespace
