#pragma once
// Time history of a one-degree-of-freedom second-order system: the angle theta(t) and its rate
// theta'(t) at the recorded times. Solvers for the pendulum return it; invariants (energy) and
// harness metrics read it. Plain data, no behaviour beyond bookkeeping.
#include <cstddef>
#include <vector>

namespace rodvv {

struct Trajectory {
  std::vector<double> t;          // recorded times, strictly increasing
  std::vector<double> theta;      // angle [rad]
  std::vector<double> theta_dot;  // angular rate [rad / time]
  std::size_t steps = 0;            // accepted integration steps
  std::size_t rhs_evaluations = 0;  // evaluations of the force theta'' = f(theta)

  std::size_t size() const noexcept { return t.size(); }
  void reserve(std::size_t n) {
    t.reserve(n);
    theta.reserve(n);
    theta_dot.reserve(n);
  }
  void record(double time, double angle, double rate) {
    t.push_back(time);
    theta.push_back(angle);
    theta_dot.push_back(rate);
  }
};

}  // namespace rodvv
