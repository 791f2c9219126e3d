#pragma once
// pendulum/one-step-map/<method>: a time integrator identified by its exact one-step map, not only by
// its order (issue 13, class 4). Two methods of the same order (the two symplectic Euler variants, the
// kick-drift-kick and drift-kick-drift Verlets) converge alike and conserve energy alike; on the
// linearised pendulum theta'' = -omega^2 theta each is a distinct 2 x 2 matrix M(x), x = omega dt,
// acting on the scaled state z = (theta, theta'/omega): z_1 = M(x) z_0.
//
// The oracle: M(x) written from each method's textbook definition (below), sharing no code with
// solvers/pendulum. The measurement: the production `integrate` run for one step from two states of
// amplitude 2^-30 rad (columns of M), where sin(theta) = theta to 1e-19 relative, i.e. the linear
// problem to far below round-off; the amplitude is a power of 2, so dividing by it is exact.
#include <string_view>

#include <Eigen/Core>

#include "rodvv/solvers/pendulum/integrators.hpp"

namespace rodvv::harness {
class Registry;
}

namespace rodvv::harness::pendulum_cases {

// The maps the oracle knows (Hairer, Lubich & Wanner 2006, §I.1 and §VI.3; McLachlan 1995).
enum class StepMap {
  ExplicitEuler,             // z_1 = (I + x A) z_0
  SymplecticEulerKickDrift,  // momentum first: u_1 = u_0 - x theta_0, theta_1 = theta_0 + x u_1
  SymplecticEulerDriftKick,  // position first: theta_1 = theta_0 + x u_0, u_1 = u_0 - x theta_1
  VerletKickDriftKick,       // velocity Verlet: half kick, drift, half kick
  VerletDriftKickDrift,      // position Verlet: half drift, kick, half drift
  RungeKutta4,               // sum_{k <= 4} (x A)^k / k! (every 4-stage order-4 explicit RK on a linear problem)
  McLachlanSb3a,             // McLachlan's SB3A: 6 drift-kick stages, coefficients of the paper
  ExactFlow,                 // exp(x A) = cos x I + sin x A
};
inline constexpr StepMap kAllStepMaps[] = {
    StepMap::ExplicitEuler,       StepMap::SymplecticEulerKickDrift, StepMap::SymplecticEulerDriftKick,
    StepMap::VerletKickDriftKick, StepMap::VerletDriftKickDrift,     StepMap::RungeKutta4,
    StepMap::McLachlanSb3a,       StepMap::ExactFlow};

std::string_view step_map_name(StepMap map);
// The oracle's M(x) on z = (theta, theta'/omega), for theta'' = -omega^2 theta and x = omega dt.
Eigen::Matrix2d step_map(StepMap map, double x);
// The map a fixed-step method is documented to be (integrators.hpp); InputError "method" for dopri5,
// whose steps are its controller's.
StepMap documented_map(solvers::pendulum::Method method);
// M measured through solvers::pendulum::integrate: one step of dt from two states of amplitude 2^-30.
Eigen::Matrix2d measured_step_map(solvers::pendulum::Method method, double omega, double dt);

void add_one_step_map_cases(Registry& registry);

}  // namespace rodvv::harness::pendulum_cases
