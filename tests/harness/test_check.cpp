// rodvv check in-process: another solver's solutions through a case's metrics, orders and gates.
// rodvv's own solutions, written to the solution-file format and read back, give the sweep's metrics
// bit for bit; an O(h) defect in a solution turns the order gates red; the gates that describe
// rodvv's solver are skipped, said so, and user bounds apply.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/check.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::harness {
namespace {

const Case& mattiasson() { return *default_registry().find("elastica/mattiasson-2/arcs"); }
const std::vector<double> kLevels = {32, 64, 128};

// Through the file format and back, as `rodvv sweep --write-solutions` and `rodvv check` do.
Solution through_a_file(const Case& c, const Parameters& parameters, double level) {
  solution_files::SolutionFile file;
  file.case_name = c.info.name;
  for (const auto& parameter : parameters) file.parameters.emplace_back(parameter.name, parameter.value);
  file.resolution_name = c.info.resolution.name;
  file.level = level;
  file.solution = c.solve(parameters, level);
  return solution_files::parse_solution(solution_files::format_solution(file), "level.json", ".").solution;
}

// The InputError message with which check_solutions refuses `solutions`; a test failure (and "")
// when it accepts them.
std::string refusal(const Case& c, const Parameters& p, const std::vector<LevelSolution>& solutions,
                    const std::string& what) {
  try {
    check_solutions(c, p, solutions, {});
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << what << " accepted";
  return "";
}

std::vector<LevelSolution> solutions_of(const Case& c, const Parameters& parameters,
                                        const std::vector<double>& levels) {
  std::vector<LevelSolution> solutions;
  for (double level : levels) {
    std::string source = "N";
    source += std::to_string(int(level));
    solutions.push_back({source, level, through_a_file(c, parameters, level), "rodvv"});
  }
  return solutions;
}

const GateResult* gate_named(const SweepResult& result, const std::string& metric) {
  for (const auto& gate : result.gates)
    if (gate.metric == metric) return &gate;
  return nullptr;
}

TEST(Check, RodvvSolutionsThroughFilesReproduceTheSweepExactly) {
  const Case& c = mattiasson();
  const Parameters& p = c.info.parameters;
  const SweepResult sweep = run_sweep(c, p, kLevels);
  auto solutions = solutions_of(c, p, kLevels);
  std::reverse(solutions.begin(), solutions.end());  // any order: sorted coarse to fine
  const SweepResult checked = check_solutions(c, p, solutions, {});
  ASSERT_EQ(checked.levels.size(), sweep.levels.size());
  for (std::size_t i = 0; i < sweep.levels.size(); ++i) {
    EXPECT_EQ(checked.levels[i].level, sweep.levels[i].level);
    ASSERT_EQ(checked.levels[i].metrics.size(), sweep.levels[i].metrics.size());
    for (const auto& [name, sample] : sweep.levels[i].metrics) {
      const MetricSample& other = checked.levels[i].metrics.at(name);
      EXPECT_EQ(other.computed, sample.computed) << name;
      EXPECT_EQ(other.reference, sample.reference) << name;
      EXPECT_EQ(other.error, sample.error) << name;
    }
  }
  // The order gates and their resolution gates apply and pass; the bounds measured on rodvv's
  // solver are skipped, and said so.
  std::size_t orders = 0, resolutions = 0;
  for (const auto& gate : checked.gates) {
    EXPECT_TRUE(gate.kind == GateKind::Order || gate.name.find(" resolved: ") != std::string::npos) << gate.name;
    EXPECT_TRUE(gate.passed) << gate.reason;
    ++(gate.kind == GateKind::Order ? orders : resolutions);
  }
  EXPECT_EQ(orders, 4u);
  EXPECT_EQ(resolutions, 4u);
  ASSERT_EQ(checked.skipped_gates.size(), 2u);
  EXPECT_NE(checked.skipped_gates[0].find("rodvv's own solver"), std::string::npos);
  EXPECT_NE(checked.info.method.find("rodvv check"), std::string::npos);
}

// The 3-D form: rodvv's nodal rod through files, the cantilever in a tilted frame and the helix (at
// a twisting moment other than its default); every metric including both forms of H identical, and
// the order gates that apply to any solver pass on both.
TEST(Check, SpatialRodSolutionsThroughFilesReproduceTheSweepExactly) {
  for (const auto& [name, levels, twisting_moment] :
       {std::tuple{"rod3d/mattiasson-2", std::vector<double>{32, 64, 128}, 0.0},
        std::tuple{"rod3d/helix-axial-wrench", std::vector<double>{32, 64, 128}, -0.8},
        std::tuple{"rod3d/heavy-cantilever", std::vector<double>{32, 64, 128}, 0.0}}) {
    const Case& c = *default_registry().find(name);
    Parameters p = c.info.parameters;
    for (auto& parameter : p)
      if (parameter.name == "twisting_moment") parameter.value = twisting_moment;
    const SweepResult sweep = run_sweep(c, p, levels);
    const SweepResult checked = check_solutions(c, p, solutions_of(c, p, levels), {});
    for (std::size_t i = 0; i < levels.size(); ++i) {
      ASSERT_EQ(checked.levels[i].metrics.size(), sweep.levels[i].metrics.size()) << name;
      EXPECT_TRUE(checked.levels[i].metrics.contains("H_form_difference")) << name;
      for (const auto& [metric, sample] : sweep.levels[i].metrics) {
        EXPECT_EQ(checked.levels[i].metrics.at(metric).computed, sample.computed) << name << " " << metric;
        EXPECT_EQ(checked.levels[i].metrics.at(metric).error, sample.error) << name << " " << metric;
      }
    }
    for (const auto& gate : checked.gates) EXPECT_TRUE(gate.passed) << name << ": " << gate.name << ": " << gate.reason;
  }
  // The manufactured solutions of both 3-D rods (no H: their distributed loads change it along s): positions,
  // frames, strains, n and m read back from the files give the same metrics, bit for bit.
  for (const char* name : {"rod3d/manufactured", "superhelix/manufactured"}) {
    const Case& c = *default_registry().find(name);
    const std::vector<double> levels{16, 32, 64};
    const SweepResult sweep = run_sweep(c, c.info.parameters, levels);
    const SweepResult checked = check_solutions(c, c.info.parameters, solutions_of(c, c.info.parameters, levels), {});
    for (std::size_t i = 0; i < levels.size(); ++i)
      for (const auto& [metric, sample] : sweep.levels[i].metrics) {
        if (metric != "newton_iterations") {
          EXPECT_EQ(checked.levels[i].metrics.at(metric).computed, sample.computed) << name << " " << metric;
        }
      }
    for (const auto& gate : checked.gates) {
      if (gate.kind == GateKind::Order) {
        EXPECT_TRUE(gate.passed) << name << " " << gate.name << ": " << gate.reason;
      }
    }
  }
  // The helix's H spread falls at fourth order on rodvv's rod at its defaults, a superconvergence
  // measured, not derived: not asked of another solver.
  const Case& helix = *default_registry().find("rod3d/helix-axial-wrench");
  const SweepResult checked =
      check_solutions(helix, helix.info.parameters, solutions_of(helix, helix.info.parameters, {32, 64, 128}), {});
  EXPECT_TRUE(std::ranges::any_of(checked.skipped_gates, [](const std::string& skipped) {
    return skipped.starts_with("order of H_spread = 4: an order measured on rodvv's own solver");
  }));
}

// A 3-D dynamic case: rodvv's nodal rod's trajectories (vertex positions in time) through files give the
// sweep's metrics bit for bit, and the order gates pass.
TEST(Check, RodTrajectoriesThroughFilesReproduceTheSweepExactly) {
  const Case& c = *default_registry().find("rod3d/skew-vibration");
  const Parameters& p = c.info.parameters;
  const std::vector<double> levels{8, 16, 32};
  const SweepResult sweep = run_sweep(c, p, levels);
  const SweepResult checked = check_solutions(c, p, solutions_of(c, p, levels), {});
  for (std::size_t i = 0; i < levels.size(); ++i) {
    ASSERT_EQ(checked.levels[i].metrics.size(), sweep.levels[i].metrics.size());
    for (const auto& [metric, sample] : sweep.levels[i].metrics)
      EXPECT_EQ(checked.levels[i].metrics.at(metric).computed, sample.computed) << metric;
  }
  std::size_t orders = 0;
  for (const auto& gate : checked.gates) {
    EXPECT_TRUE(gate.passed) << gate.name << ": " << gate.reason;
    orders += gate.kind == GateKind::Order;
  }
  EXPECT_EQ(orders, 3u);
}

// Another solver that swaps EI1 and EI2 (each plane vibrating at the other's frequency) converges, but to
// the wrong motion: its tip errors stay O(1) and the order gates turn red.
TEST(Check, ATrajectoryWithSwappedStiffnessesTurnsRed) {
  const Case& c = *default_registry().find("rod3d/skew-vibration");
  const Parameters& p = c.info.parameters;
  Parameters swapped = p;
  for (auto& parameter : swapped) {
    if (parameter.name == "EI1") parameter.value = parameter_value(p, "EI2");
    if (parameter.name == "EI2") parameter.value = parameter_value(p, "EI1");
  }
  std::vector<LevelSolution> solutions;
  for (double level : {8.0, 16.0, 32.0}) solutions.push_back({"swapped", level, c.solve(swapped, level), "x"});
  const SweepResult checked = check_solutions(c, p, solutions, {});
  EXPECT_GT(checked.levels.back().metrics.at("tip_error").computed, 0.1);
  const GateResult* order = gate_named(checked, "tip_error");
  ASSERT_NE(order, nullptr);
  EXPECT_FALSE(order->passed);
}

// What cannot show the motion is refused, naming why: a trajectory that stops early, gaps between
// snapshots that could hide the peaks, snapshots whose vertex count disagrees with N.
TEST(Check, ARodTrajectoryMustCoverTheMotion) {
  const Case& c = *default_registry().find("rod3d/skew-vibration");
  const Parameters& p = c.info.parameters;
  const Solution full = c.solve(p, 8);
  {
    Solution half = full;
    auto& trajectory = std::get<RodTrajectory>(half);
    trajectory.t.resize(trajectory.size() / 2);
    trajectory.snapshots.resize(trajectory.t.size());
    const std::string message = refusal(c, p, {{"short.json", 8, half, "x"}}, "a half trajectory");
    EXPECT_NE(message.find("short.json: the trajectory ends at t = "), std::string::npos) << message;
  }
  {
    Solution sparse = full;
    auto& trajectory = std::get<RodTrajectory>(sparse);
    trajectory.t.erase(trajectory.t.begin() + 1, trajectory.t.begin() + 4);
    trajectory.snapshots.erase(trajectory.snapshots.begin() + 1, trajectory.snapshots.begin() + 4);
    const std::string message = refusal(c, p, {{"sparse.json", 8, sparse, "x"}}, "a gap of four samples");
    EXPECT_NE(message.find("gaps must not exceed an eighth of the faster period"), std::string::npos) << message;
  }
  {
    const std::string message = refusal(c, p, {{"n9.json", 9, full, "x"}}, "a vertex count that disagrees with N");
    EXPECT_NE(message.find("N = 9 elements, but the rod has 9 nodes"), std::string::npos) << message;
  }
}

// The column's midspan values need a node at s = L/2: an odd N is refused, not measured off-centre.
TEST(Check, PinnedColumnNeedsAMidspanNode) {
  const Case& c = *default_registry().find("elastica/pinned-pinned-60/arcs");
  const Parameters& p = c.info.parameters;
  EXPECT_NO_THROW(check_solutions(c, p, solutions_of(c, p, {32, 64, 128}), {}));
  {
    const std::string message = refusal(c, p, solutions_of(c, p, {33, 65, 129}), "an odd N");
    EXPECT_NE(message.find("N33: y_M and kappa_M are taken at the midspan node"), std::string::npos) << message;
  }
}

// A solver with an O(h) defect (PyElastica's clamp, README): each node's deflection off by
// h/2 (s/L)^2. The order gates see it.
TEST(Check, AFirstOrderDefectTurnsTheOrderGatesRed) {
  const Case& c = mattiasson();
  const Parameters& p = c.info.parameters;
  auto solutions = solutions_of(c, p, kLevels);
  for (auto& level : solutions) {
    auto& rod = std::get<PlanarRodSolution>(level.solution);
    const double h = rod.length / level.level;
    for (std::size_t i = 0; i < rod.nodes(); ++i) rod.y[i] -= 0.5 * h * std::pow(rod.s[i] / rod.length, 2);
  }
  const SweepResult checked = check_solutions(c, p, solutions, {});
  const GateResult* tip = gate_named(checked, "tip_w");
  ASSERT_NE(tip, nullptr);
  EXPECT_FALSE(tip->passed) << tip->reason;
  ASSERT_TRUE(tip->measured);
  EXPECT_NEAR(*tip->measured, 1.0, 0.1);
}

TEST(Check, OneSolutionGivesErrorsAndUserBoundsButNoOrders) {
  const Case& c = mattiasson();
  const Parameters& p = c.info.parameters;
  const auto solutions = solutions_of(c, p, {64});
  const double error = *check_solutions(c, p, solutions, {}).levels[0].metrics.at("tip_w").error;
  const std::vector<GateSpec> loose{user_bound(c, "tip_w", 2.0 * error)}, tight{user_bound(c, "tip_w", 0.5 * error)};
  const SweepResult passed = check_solutions(c, p, solutions, loose);
  ASSERT_EQ(passed.gates.size(), 1u);
  EXPECT_TRUE(passed.gates[0].passed);
  const auto order_skips = std::count_if(passed.skipped_gates.begin(), passed.skipped_gates.end(), [](const auto& s) {
    return s.find("an order needs solutions at 3 levels or more, got 1") != std::string::npos;
  });
  EXPECT_EQ(order_skips, 8);  // 4 orders and the resolution gate beside each
  EXPECT_FALSE(check_solutions(c, p, solutions, tight).gates[0].passed);
}

TEST(Check, WithoutForcesTheInvariantIsNotComputedAndItsGateIsSkipped) {
  const Case& c = mattiasson();
  const Parameters& p = c.info.parameters;
  auto solutions = solutions_of(c, p, kLevels);
  for (auto& level : solutions) std::get<PlanarRodSolution>(level.solution).axial_force.clear();
  const SweepResult checked = check_solutions(c, p, solutions, {});
  EXPECT_FALSE(checked.levels[0].metrics.contains("H_spread"));
  EXPECT_EQ(gate_named(checked, "H_spread"), nullptr);
  EXPECT_TRUE(std::any_of(checked.skipped_gates.begin(), checked.skipped_gates.end(), [](const auto& s) {
    return s.find("order of H_spread") != std::string::npos && s.find("lack the fields") != std::string::npos;
  }));
  EXPECT_NE(gate_named(checked, "tip_w"), nullptr);
}

TEST(Check, RefusesWhatItCannotCheck) {
  const Case& c = mattiasson();
  const Parameters& p = c.info.parameters;
  auto solutions = solutions_of(c, p, {32, 64});
  EXPECT_THROW(check_solutions(c, p, {}, {}), InputError);
  auto twice = solutions;
  twice[1] = twice[0];  // the same level twice (and a consistent node count, so that this is what is refused)
  twice[1].source = "again";
  {
    const std::string message = refusal(c, p, twice, "two solutions at one level");
    EXPECT_NE(message.find("are both at N = 32: one solution per level"), std::string::npos) << message;
  }
  auto fractional = solutions;
  fractional[0].level = 32.5;
  EXPECT_THROW(check_solutions(c, p, fractional, {}), InputError);
  auto miscounted = solutions;
  miscounted[0].level = 33;  // 33 elements declared, 32 in the rod
  {
    const std::string message = refusal(c, p, miscounted, "a node count that disagrees with N");
    EXPECT_NE(message.find("N = 33 elements, but the rod has 33 nodes"), std::string::npos) << message;
  }
  auto trajectory = solutions;
  trajectory[0].solution = Trajectory{};
  {
    const std::string message = refusal(c, p, trajectory, "a trajectory for a planar case");
    EXPECT_NE(message.find("measures a planar_rod solution; got a trajectory"), std::string::npos) << message;
  }
  EXPECT_THROW(user_bound(c, "tip_z", 1.0), InputError);
  EXPECT_THROW(user_bound(c, "tip_w", -1.0), InputError);
  const Case& pendulum = *default_registry().find("pendulum/libration-90/rk4");
  EXPECT_THROW(check_solutions(pendulum, pendulum.info.parameters, solutions, {}), InputError);
}

// A trajectory that stops early would be measured over part of the motion: refused, with the span.
TEST(Check, ATrajectoryMustCoverTheCasesHorizon) {
  const Case& c = *default_registry().find("pendulum/libration-90/rk4");
  const Parameters& p = c.info.parameters;
  Solution solution = c.solve(p, 0.05);
  auto& trajectory = std::get<Trajectory>(solution);
  const std::size_t half = trajectory.size() / 2;
  for (auto* values : {&trajectory.t, &trajectory.theta, &trajectory.theta_dot}) values->resize(half);
  {
    const std::string message = refusal(c, p, {{"short.json", 0.05, solution, "x"}}, "a half trajectory");
    EXPECT_NE(message.find("short.json: the trajectory spans t = 0 .."), std::string::npos) << message;
  }
  EXPECT_THROW(check_solutions(c, p, solutions_of(c, p, {0.1, 0.05, 0.025}), {}, 0.0), InputError);  // --order 0
}

}  // namespace
}  // namespace rodvv::harness
