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
  const auto steps = options.load_steps;
  for (std::size_t step = 1; step <= steps; ++step) {
    const double lambda = static_cast<double>(step) / static_cast<double>(steps);
    lag.set_load_factor(lambda);
    for (std::size_t k = 0; k < rows; ++k)
      lag.set_row_target(k, step == steps ? to[k] : from[k] + lambda * (to[k] - from[k]));
    newton(lag, z, options, state);
  }
  PlanarRodSolution sol = fill_solution(lag, z);
  sol.iterations = state.iterations;
  sol.residual = state.residual;
  return sol;
}

}  // namespace rodvv::solvers::elastica2d
