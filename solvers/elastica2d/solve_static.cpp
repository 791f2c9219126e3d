#include "rodvv/solvers/elastica2d/solve_static.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/newton.hpp"

namespace rodvv::solvers::elastica2d {

namespace {
using Eigen::VectorXd;
using detail::initial_state;
using detail::newton;
using detail::fill_solution;
using detail::NewtonState;
constexpr int kMaxHalvings = 10;
constexpr double kMinLoadFraction = 0x1p-10;  // 2^-kMaxHalvings
}  // namespace

void validate(const SolverOptions& options) {
  require_open_interval("options.tolerance", options.tolerance, 0.0, 1.0);
  require_at_least("options.max_iterations", options.max_iterations, 1);
  require_at_least("options.load_steps", options.load_steps, 1);
}

PlanarRodSolution solve_static(const Problem& problem, const Discretisation& discretisation,
                               const SolverOptions& options, const InitialGuess& guess) {
  validate(options);
  DiscreteLagrangian lag(problem, discretisation);
  lag.set_load_factor(1.0 / static_cast<double>(options.load_steps));  // first step's loads
  VectorXd z = initial_state(lag, problem, guess);

  // Displacement stepping: prescribed positions move from the guess's values to their targets.
  const std::size_t rows = lag.rows().size();
  std::vector<double> from(rows), to(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    const BoundaryRow& row = lag.rows()[k];
    to[k] = row.target;
    const bool angle_row = lag.scheme() == Scheme::Arcs &&
                           (row.dof == lag.angle(0) || row.dof == lag.angle(lag.elements()));
    from[k] = angle_row ? row.target : z[row.dof];
  }
  NewtonState state;
  // The planned steps lambda = k / K; a step whose Newton solve fails is retried from the last
  // converged state as two half steps, down to 1/2^kMaxHalvings of a planned step (adaptive load
  // control: a large load, e.g. a cantilever at P L^2/EI = 100, leaves the basin of the previous
  // state in one planned step). A problem that converges in its planned steps is solved exactly
  // as before, step for step.
  const auto steps = options.load_steps;
  const double planned = 1.0 / static_cast<double>(steps);
  double increment = planned, reached = 0.0;
  std::size_t completed = 0;
  while (completed < steps) {
    const double next_planned = static_cast<double>(completed + 1) / static_cast<double>(steps);
    const bool last_of_plan = reached + increment >= next_planned - 1e-12 * planned;
    const double lambda = last_of_plan ? next_planned : reached + increment;
    const bool final_step = last_of_plan && completed + 1 == steps;
    lag.set_load_factor(lambda);
    for (std::size_t k = 0; k < rows; ++k)
      lag.set_row_target(k, final_step ? to[k] : from[k] + lambda * (to[k] - from[k]));
    const VectorXd converged = z;
    try {
      newton(lag, z, options, state);
    } catch (const SolverError& error) {
      if (increment <= planned * kMinLoadFraction)
        throw SolverError(error.method(),
                          error.message() + ", at load factor " + format_value(lambda) + " after " +
                              std::to_string(kMaxHalvings) + " halvings of the load step",
                          error.iterations(), error.residual());
      z = converged;
      increment *= 0.5;
      continue;
    }
    reached = lambda;
    if (last_of_plan) {
      ++completed;
      increment = planned;
    }
  }
  PlanarRodSolution sol = fill_solution(lag, z);
  sol.iterations = state.iterations;
  sol.residual = state.residual;
  return sol;
}

}  // namespace rodvv::solvers::elastica2d
