#pragma once
// Energy of the pendulum along a trajectory (PHYSICS.md §0): E = 1/2 theta'^2 - omega^2 cos(theta).
// A symplectic integrator keeps E - E(0) bounded (it conserves a nearby modified energy), a
// non-symplectic one lets it drift secularly; the statistics below measure both.
#include <cmath>
#include <vector>

#include "rodvv/common/trajectory.hpp"

namespace rodvv::invariants {

template <class Scalar>
Scalar pendulum_energy(Scalar theta, Scalar theta_dot, Scalar omega) {
  using std::cos;
  return Scalar(0.5) * theta_dot * theta_dot - omega * omega * cos(theta);
}

struct EnergyStatistics {
  double initial = 0.0;            // E at the first sample
  double max_abs_deviation = 0.0;  // max_i |E_i - E_0|
  double drift_slope = 0.0;        // least-squares slope dE/dt over the whole trajectory
  double drift_intercept = 0.0;    // least-squares intercept (at t = 0)
  double early_deviation = 0.0;    // max |E - E_0| over the first `window` fraction of the time span
  double late_deviation = 0.0;     // max |E - E_0| over the last `window` fraction of the time span
};

// E_i at every sample of the trajectory.
std::vector<double> pendulum_energy_history(const Trajectory& trajectory, double omega);

// window: the fraction of the time span, in (0, 0.5], over which early_deviation and
// late_deviation are taken (e.g. 1 / periods compares the first and the last period).
// Throws rodvv::InputError for omega <= 0 / NaN, a window outside (0, 0.5], an empty trajectory,
// arrays of unequal length, times not finite or not strictly increasing, or a non-finite energy.
EnergyStatistics pendulum_energy_statistics(const Trajectory& trajectory, double omega,
                                            double window = 0.1);

}  // namespace rodvv::invariants
