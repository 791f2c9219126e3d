#pragma once
// Internal to rodvv::solvers (not installed): the output grid and the fixed-step driver shared by
// integrators.cpp (own methods) and odeint_methods.cpp (Boost.Odeint methods).
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/trajectory.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/pendulum/integrators.hpp"

namespace rodvv::solvers::pendulum::detail {

// Output grid t_i = i * dt, i = 0 .. n; every record_every-th point plus the last is kept.
struct Grid {
  std::size_t n = 0;
  double dt = 0.0;
  std::size_t record_every = 1;

  double time(std::size_t i) const noexcept { return static_cast<double>(i) * dt; }
  bool records(std::size_t i) const noexcept { return i % record_every == 0 || i == n; }
  std::size_t recorded_points() const noexcept { return n / record_every + 2; }  // upper bound
};

[[noreturn]] inline void throw_non_finite(std::string_view method, std::size_t step, double theta,
                                          double theta_dot) {
  throw SolverError(std::string(method),
                    "state became non-finite at step " + std::to_string(step) + " (theta = " +
                        format_value(theta) + ", theta_dot = " + format_value(theta_dot) + ")",
                    step, std::abs(theta) + std::abs(theta_dot));
}

// Runs n fixed steps of `step(q, v)` from (q, v), recording on the grid. `step` advances one step.
template <class Step>
Trajectory run_fixed(std::string_view method, const Problem& problem, const Grid& grid, Step&& step) {
  Trajectory out;
  out.reserve(grid.recorded_points());
  double q = problem.theta0;
  double v = problem.theta_dot0;
  out.record(0.0, q, v);
  for (std::size_t i = 1; i <= grid.n; ++i) {
    step(q, v);
    if (!std::isfinite(q) || !std::isfinite(v)) throw_non_finite(method, i, q, v);
    if (grid.records(i)) out.record(grid.time(i), q, v);
  }
  out.steps = grid.n;
  return out;
}

// Boost.Odeint methods (odeint_methods.cpp); rhs_evaluations is filled by each.
Trajectory integrate_rk4(const Problem& problem, const Grid& grid);
Trajectory integrate_rkn4_mclachlan(const Problem& problem, const Grid& grid);
Trajectory integrate_dopri5(const Problem& problem, const Grid& grid, double tolerance);

}  // namespace rodvv::solvers::pendulum::detail
