// A downstream project using rodvv's installed references and invariants.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "rodvv/invariants/energy.hpp"
#include "rodvv/references/pendulum.hpp"

int main() {
  const rodvv::references::Libration motion{1.0, std::numbers::pi / 2};
  const double period = rodvv::references::libration_period(motion);
  const auto state = rodvv::references::libration_state(motion, 1.0);
  const double energy = rodvv::invariants::pendulum_energy(state.theta, state.theta_dot, 1.0);
  std::printf("period %.16g, energy %.16g\n", period, energy);
  // PHYSICS.md §2.4: omega T = 4K(sin 45 deg) = 7.416298709205488; E = -cos(90 deg) = 0.
  const bool ok = std::abs(period - 7.416298709205488) < 1e-13 && std::abs(energy) < 1e-14;
  return ok ? 0 : 1;
}
