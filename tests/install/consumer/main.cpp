// A downstream project using rodvv's installed references, invariants, solution-file reader and gates.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/convergence.hpp"
#include "rodvv/invariants/energy.hpp"
#include "rodvv/invariants/planar_noether.hpp"
#include "rodvv/solution_files/solution_file.hpp"
#include "rodvv/references/pendulum.hpp"

int main() {
  const rodvv::references::Libration motion{1.0, std::numbers::pi / 2};
  const double period = rodvv::references::libration_period(motion);
  const auto state = rodvv::references::libration_state(motion, 1.0);
  const double energy = rodvv::invariants::pendulum_energy(state.theta, state.theta_dot, 1.0);
  std::printf("period %.16g, energy %.16g\n", period, energy);
  // PHYSICS.md §2.4: omega T = 4K(sin 45 deg) = 7.416298709205488; E = -cos(90 deg) = 0.
  bool ok = std::abs(period - 7.416298709205488) < 1e-13 && std::abs(energy) < 1e-14;

  // A solution file read with the installed reader, its H computed with the installed invariant: a
  // straight rod under tension 2 along x, H = n.t = 2 at every node.
  const auto file = rodvv::solution_files::parse_solution(
      R"({"format": "rodvv-solution", "version": 1, "case": "elastica/mattiasson-2", "resolution": {"N": 2},
          "planar_rod": {"bending_stiffness": 1.5, "nodes": {"s": [0, 0.5, 1], "x": [0, 0.5, 1], "y": [0, 0, 0],
          "force_x": [2, 2, 2], "force_y": [0, 0, 0]}}})",
      "inline", ".");
  const auto& rod = std::get<rodvv::PlanarRodSolution>(file.solution);
  for (double h : rodvv::invariants::planar_noether_h(rod)) ok = ok && h == 2.0;
  std::printf("solution file: %zu nodes, H = %.16g\n", rod.nodes(), rodvv::invariants::planar_noether_h(rod)[0]);
  try {  // and a malformed one is an InputError naming the field
    rodvv::solution_files::parse_solution(R"({"format": "rodvv-solution", "version": 9})", "bad", ".");
    ok = false;
  } catch (const rodvv::InputError& error) {
    std::printf("refused: %s\n", error.what());
  }

  // The project's own "solver" (the composite trapezoidal rule for the integral of e^x over [0, 1], exact
  // e - 1) at N = 8 .. 64, gated with rodvv's order fit and gates: order 2 passes (with its resolution
  // gate beside it), a claimed order 1 fails.
  namespace h = rodvv::harness;
  h::CaseInfo info;
  info.name = "consumer/trapezoid";
  info.resolution = {"N", "panels", h::ResolutionScale::Count, {8, 16, 32, 64}, {}, 0.0};
  info.metrics = {{"integral", h::MetricKind::Error, "", "trapezoidal rule for the integral of e^x on [0, 1]",
                   true, 2.0}};
  std::vector<h::LevelResult> levels;
  for (int n : {8, 16, 32, 64}) {
    double sum = 0.5 * (1.0 + std::exp(1.0));
    for (int k = 1; k < n; ++k) sum += std::exp(double(k) / n);
    h::LevelResult level;
    level.level = n;
    level.h = 1.0 / n;
    const double exact = std::exp(1.0) - 1.0, computed = sum / n;
    level.metrics["integral"] = {computed, exact, std::abs(computed - exact)};
    levels.push_back(level);
  }
  const auto right = h::evaluate_convergence(info, levels, {h::order_gate("integral", 2.0, "trapezoidal rule")});
  const auto wrong = h::evaluate_convergence(info, levels, {h::order_gate("integral", 1.0, "a wrong claim")});
  std::printf("trapezoid: order %.4f, %zu gates, %s; claimed order 1: %s\n",
              *right.analyses[0].order.least_squares, right.gates.size(), right.passed() ? "pass" : "FAIL",
              wrong.passed() ? "pass" : "fails as it must");
  ok = ok && right.passed() && right.gates.size() == 2 && !wrong.passed();
  return ok ? 0 : 1;
}
