// A downstream project using rodvv's installed references and invariants.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "rodvv/common/errors.hpp"
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
  return ok ? 0 : 1;
}
